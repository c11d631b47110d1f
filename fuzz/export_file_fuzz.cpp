// Fuzzes `aapat import`: any bytes give a hardware layout or an Error; a
// layout that reads back as a pattern gives a valid one.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/hardware_layout.h"
#include "aapat/io/api_export.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const aapat::HardwareLayout layout = aapat::parse_export(text, "fuzz.h");
    const aapat::Pattern p = aapat::pattern_from_layout(layout);
    aapat::validate(p);
  } catch (const aapat::Error&) {
  }
  return 0;
}
