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
                  "resolve each frame over every sample within this filter's support, the "
                  "neighbours' too (e.g. gaussian:sigma=0.47,radius=1.5: 3x3 pixels)");
}

Accumulation ModelOptions::make() const {
  try {
    return make_accumulation(model, alpha, window, resolve);
  } catch (const ParameterError& e) {
    throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
  }
}

std::string ModelOptions::text() const {
  return accumulation_text(make());
}

}  // namespace aapat
