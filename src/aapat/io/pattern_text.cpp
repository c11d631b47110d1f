#include "aapat/io/pattern_text.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "aapat/core/filter_catalog.h"

namespace aapat {

std::string pattern_to_text(const Pattern& p) {
  validate(p);
  if (p.set_count() != 1 || p.footprint.size != 1 || p.weights[0].size() != p.sets[0].size())
    throw Error(fmt::format(
        "pattern {} is {}: the x y weight text holds one pixel's samples and weights (P(1,1,n)); "
        "write it as .json",
        p.name, family(p)));
  std::string out = fmt::format("# {} {}: x y weight per sample, pixels from the pixel centre\n",
                                p.name, family(p));
  for (size_t i = 0; i < p.sets[0].size(); ++i)
    out += fmt::format("{} {} {}\n", p.sets[0][i].x, p.sets[0][i].y, p.weights[0][i]);
  return out;
}

Pattern pattern_from_text(std::string_view text, std::string_view source) {
  std::vector<Vec2> samples;
  std::vector<double> weights;
  std::istringstream in{std::string(text)};
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (const auto h = line.find('#'); h != std::string::npos) line.erase(h);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    const std::string where = fmt::format("pattern file {} line {}", source, no);
    if (w.size() != 3)
      throw Error(fmt::format("{}: expected 'x y weight', got {} values", where, w.size()));
    if (samples.size() >= kMaxSamplesPerSet)
      throw Error(
          fmt::format("{}: more than {} samples, the limit per pixel", where, kMaxSamplesPerSet));
    samples.push_back({parse_number(w[0], where + ": x"), parse_number(w[1], where + ": y")});
    weights.push_back(parse_number(w[2], where + ": weight"));
  }
  if (samples.empty()) throw Error(fmt::format("pattern file {}: no samples", source));
  std::string name(source);
  if (const auto slash = name.find_last_of('/'); slash != std::string::npos)
    name.erase(0, slash + 1);
  if (const auto dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.erase(dot);
  Pattern p = single_pixel_pattern(name, samples, weights);
  try {
    validate(p);
  } catch (const Error& e) {
    throw Error(fmt::format("pattern file {}: {}", source, e.what()));
  }
  return p;
}

}  // namespace aapat
