#include "aapat/temporal/sequence/sequence_export.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "aapat/core/geometry.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

// The numbers after `float2(` (or the language's constructor) in order.
std::vector<double> numbers_after(const std::string& text, const std::string& open) {
  std::vector<double> out;
  for (size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
    const char* p = text.c_str() + at + open.size();
    char* end = nullptr;
    out.push_back(std::strtod(p, &end));
    out.push_back(std::strtod(end + 1, nullptr));
  }
  return out;
}

// Every offset round-trips through its 17 digits, with y negated for screen
// rows and kept for aapat's +y up.
TEST(SequenceExport, AJitterRoundTripsExactlyInEitherYDirection) {
  const Sequence s = make_sequence("halton:frames=8");
  for (const bool y_down : {true, false}) {
    const std::vector<double> v =
        numbers_after(export_jitter(s, ExportLanguage::hlsl, y_down), "float2(");
    ASSERT_EQ(v.size(), 16u);
    for (size_t f = 0; f < 8; ++f) {
      const Vec2 j = s.frames[f].sets[0][0];
      EXPECT_EQ(v[2 * f], j.x) << f;
      EXPECT_EQ(v[2 * f + 1], y_down ? -j.y : j.y) << f;
    }
  }
}

// Each language names its own vector type; a pattern of several samples is
// no jitter.
TEST(SequenceExport, EachLanguageHasItsTypeAndAJitterIsOneSample) {
  const Sequence s = make_sequence("halton:frames=4");
  EXPECT_NE(export_jitter(s, ExportLanguage::glsl, true).find("vec2("), std::string::npos);
  EXPECT_NE(export_jitter(s, ExportLanguage::cpp, true).find("{"), std::string::npos);
  EXPECT_EQ(parse_export_language("c++"), ExportLanguage::cpp);
  EXPECT_THROW(parse_export_language("wgsl"), Error);
  EXPECT_THROW(export_jitter(make_sequence("msaa-alternating:samples=2,frames=2"),
                             ExportLanguage::hlsl, true),
               Error);
}

// A hostile name or provenance value stays inside its comment line in every
// language: no line of the export starts with the injected directive.
TEST(SequenceExport, AHostileNameStaysInItsComment) {
  Sequence s = make_sequence("halton:frames=4");
  s.name = "evil\n#define aapat_jitter evil";
  s.provenance.emplace_back("note\n#pragma", "x\r\n#define y 1");
  for (const ExportLanguage language :
       {ExportLanguage::hlsl, ExportLanguage::glsl, ExportLanguage::cpp}) {
    const std::string code = export_jitter(s, language, true);
    EXPECT_EQ(code.find("\n#"), std::string::npos) << code;
  }
}

}  // namespace
}  // namespace aapat
