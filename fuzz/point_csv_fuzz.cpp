// Fuzzes the point-set CSV reader: any bytes give points in the unit square
// or an Error; small sets that load have finite discrepancies.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/analyze/discrepancy.h"
#include "aapat/io/point_set_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto points = aapat::parse_point_csv(text, "fuzz.csv");
    for (const aapat::Vec2& p : points)
      if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1)) __builtin_trap();
    if (points.size() <= 64) {
      const double l2 = aapat::l2_star_discrepancy(points);
      const auto star = aapat::star_discrepancy(points);
      if (!std::isfinite(l2) || !(star.lower <= star.upper + 1e-12)) __builtin_trap();
    }
  } catch (const aapat::Error&) {
  }
  return 0;
}
