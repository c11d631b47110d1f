#include "aapat/temporal/sequence/sequence_svg.h"

#include <gtest/gtest.h>

#include <string>

#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// One numbered disc per frame's sample, in time order.
TEST(SequenceSvg, DrawsEveryFramesSampleNumbered) {
  const std::string svg = sequence_svg(make_sequence("halton:frames=12"));
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "<circle"), 12u);
  for (const char* label : {">0<", ">11<"}) EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_EQ(svg.find(">12<"), std::string::npos);
}

// The convergence curve: one polyline per series, its label shown.
TEST(SequenceSvg, TheConvergenceCurveHasASeriesEach) {
  const std::string svg = convergence_svg(
      {{"halton", {0.9, 0.5, 0.3, 0.2}}, {"r2", {0.9, 0.6, 0.35, 0.25}}}, "after a cut");
  EXPECT_EQ(count(svg, "<polyline"), 2u);
  EXPECT_NE(svg.find("halton"), std::string::npos);
  EXPECT_NE(svg.find("after a cut"), std::string::npos);
}

}  // namespace
}  // namespace aapat
