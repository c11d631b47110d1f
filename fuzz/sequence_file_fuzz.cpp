// Fuzzes the sequence file reader: any bytes must give a sequence that passes
// validation or an Error naming the problem; never a crash, hang or leak.
// A sequence read must round-trip exactly and evaluate under an EMA.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const aapat::Sequence s = aapat::sequence_from_json(text, "fuzz.json");
    aapat::validate(s);
    const std::string again = aapat::sequence_to_json(s);
    if (aapat::sequence_to_json(aapat::sequence_from_json(again, "again.json")) != again)
      __builtin_trap();
    // Small sequences only: the evaluation is not what is fuzzed.
    if (s.period() <= 16 && aapat::samples_in_order(s).size() <= 64) {
      static const aapat::Metric metric(aapat::make_filter("box"), aapat::uniform_acuity(45), 2);
      aapat::Accumulation ema;
      aapat::kernels_e2(metric, aapat::accumulated_kernels(s, ema, 0, true));
    }
  } catch (const aapat::Error&) {
  }
  return 0;
}
