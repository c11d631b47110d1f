#include "cli/sequence_options.h"

#include <fmt/format.h>

#include "aapat/core/filter_catalog.h"

namespace aapat {

void ModelOptions::add_to(CLI::App* cmd) {
  cmd->add_option("--model", model, "accumulation: ema (history 1 - alpha) or box (a window)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ema", "box"}));
  cmd->add_option("--alpha", alpha, "EMA blend factor, the current frame's weight, in (0, 1]")
      ->capture_default_str();
  cmd->add_option("--window", window, "box: frames averaged (0: the period)")
      ->capture_default_str();
  cmd->add_option("--resolve", resolve,
                  "resolve each frame over its neighbours' samples with this filter "
                  "(e.g. gaussian:sigma=0.47,radius=1.5)");
  cmd->add_option("--resolve-radius", radius, "pixels the resolve reads on each side (1: 3x3)")
      ->capture_default_str();
}

Accumulation ModelOptions::make() const {
  Accumulation a;
  a.kind = model == "box" ? AccumulationKind::box : AccumulationKind::ema;
  a.alpha = alpha;
  a.window = window;
  a.resolve_radius = radius;
  if (!resolve.empty()) a.resolve = make_filter(resolve);
  try {
    validate(a);
  } catch (const ParameterError& e) {
    throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
  }
  return a;
}

std::string ModelOptions::text() const {
  std::string t = model == "box" ? (window ? fmt::format("box of {} frames", window)
                                           : std::string("box of the period"))
                                 : fmt::format("EMA alpha {}", alpha);
  if (!resolve.empty())
    t += fmt::format(", {} resolve over {}x{}", resolve, 2 * radius + 1, 2 * radius + 1);
  return t;
}

}  // namespace aapat
