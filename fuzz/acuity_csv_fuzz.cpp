// Fuzzes the acuity CSV reader: any bytes give a valid table or an Error, and
// a table that loads gives a finite E2 for a catalog pattern.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/generate/catalog.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    aapat::AcuityTable table = aapat::parse_acuity_csv(text, "fuzz.csv");
    static const aapat::Pattern kRgss = aapat::catalog_pattern("rgss");
    const aapat::Metric metric(aapat::make_filter("mitchell"), std::move(table));
    if (!std::isfinite(metric.evaluate(kRgss).e2)) __builtin_trap();
  } catch (const aapat::Error&) {
  }
  return 0;
}
