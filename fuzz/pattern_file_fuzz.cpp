// Fuzzes the pattern file reader: any bytes must give a pattern that passes
// validation or an Error naming the problem; never a crash, hang or leak.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/geometry.h"
#include "aapat/core/pattern.h"
#include "aapat/io/pattern_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const aapat::Pattern p = aapat::pattern_from_json(text, "fuzz.json");
    aapat::validate(p);  // what the reader returns must be valid
    // And it must round-trip exactly.
    const std::string again = aapat::pattern_to_json(p);
    if (aapat::pattern_to_json(aapat::pattern_from_json(again, "again.json")) != again)
      __builtin_trap();
  } catch (const aapat::Error&) {
  }
  return 0;
}
