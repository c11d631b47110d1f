#include "aapat/optimize/family.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "aapat/generate/enumerate.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// Every placement the enumeration lists is a placement of its family, with
// as many samples read as it says.
TEST(Family, EveryEnumeratedPlacementIsAPlacementOfItsFamily) {
  for (double n : {1.25, 1.5, 1.75, 2.0})
    for (const auto& c : enumerate_placements(n)) {
      const FamilySpec spec = parse_family(fmt::format("P(4,1+,{})", n), c.sites());
      EXPECT_EQ(static_cast<int>(spec.sites.size()), c.samples()) << c.sites();
    }
  PlacementConfig fliptri;
  fliptri.corners = {0, 0, 0, 1};
  fliptri.edges = {1, 1, 0, 0};
  EXPECT_EQ(fliptri.sites(), "top-left,bottom,right");
}

// P(s, r, n) parses to its parts; impossible families are refused naming the rule.
TEST(Family, ParsesTheNotationAndRefusesImpossibleFamilies) {
  const FamilySpec f = parse_family("P(4,1+,2)", "left,right,bottom,top");
  EXPECT_EQ(f.s, 4);
  EXPECT_TRUE(f.footprint.plus);
  EXPECT_TRUE(f.mirrored);
  EXPECT_EQ(f.n, 2.0);
  EXPECT_EQ(f.text(), "P(4,1+,2)");
  EXPECT_EQ(parse_family("P(1,1,8)", "").text(), "P(1,1,8)");
  EXPECT_NE(testing::error_message([] { parse_family("P(1,1,2.5)", ""); }).find("whole number"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] { parse_family("P(1,1,4)", "left"); }).find("border"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              parse_family("P(4,1+,2)", "nowhere");
            }).find("unknown site 'nowhere'"),
            std::string::npos);
  EXPECT_THROW(parse_family("Q(1,1,1)", ""), Error);
}

}  // namespace
}  // namespace aapat
