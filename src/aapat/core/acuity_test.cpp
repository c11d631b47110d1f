#include "aapat/core/acuity.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "aapat/core/geometry.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

TEST(Acuity, DefaultTableIsTheFourAnglesOfTheReference) {
  const AcuityTable t = laine_aila_acuity();
  EXPECT_EQ(t.angles_deg, (std::vector<double>{0, 45, 90, 135}));
  EXPECT_EQ(t.weights, (std::vector<double>{3.93, 2.50, 3.93, 2.50}));
  EXPECT_EQ(make_acuity("laine-aila").angles_deg, t.angles_deg);
}

TEST(Acuity, UniformAndLinearTables) {
  const AcuityTable u = make_acuity("uniform:step=1");
  EXPECT_EQ(u.angles_deg.size(), 180u);
  EXPECT_EQ(u.weights[17], 1.0);
  EXPECT_EQ(make_acuity("uniform:step=22.5,weight=2").weights.size(), 8u);
  const AcuityTable l = make_acuity("linear:step=15");
  ASSERT_EQ(l.angles_deg.size(), 12u);
  EXPECT_DOUBLE_EQ(l.weights[0], 3.93);                       // 0
  EXPECT_DOUBLE_EQ(l.weights[3], 2.5);                        // 45
  EXPECT_DOUBLE_EQ(l.weights[6], 3.93);                       // 90
  EXPECT_NEAR(l.weights[1], 3.93 - (3.93 - 2.5) / 3, 1e-15);  // 15
}

void expect_acuity_error(const std::string& spec_or_text, const std::string& message,
                         bool csv = false) {
  EXPECT_EQ(testing::error_message([&] {
              if (csv)
                parse_acuity_csv(spec_or_text, "t.csv");
              else
                make_acuity(spec_or_text);
            }),
            message)
      << spec_or_text;
}

TEST(Acuity, CsvRowsAndErrors) {
  const AcuityTable t = parse_acuity_csv("# angle,weight\n0, 2\n\n30,1.5 # comment\n", "t.csv");
  EXPECT_EQ(t.angles_deg, (std::vector<double>{0, 30}));
  EXPECT_EQ(t.weights, (std::vector<double>{2, 1.5}));
  expect_acuity_error("0,1\n45\n", "acuity table t.csv line 2: expected 'angle,weight', got '45'",
                      true);
  expect_acuity_error("0,1,2\n", "acuity table t.csv line 1: expected 'angle,weight', got '0,1,2'",
                      true);
  expect_acuity_error("0,-1\n", "acuity table t.csv line 1: weight -1 is out of range [0, 1000000]",
                      true);
  expect_acuity_error("0,x\n", "acuity table t.csv line 1: weight: 'x' is not a finite number",
                      true);
  expect_acuity_error(
      "10,1\n190,1\n",
      "acuity table t.csv line 2: angle 190 repeats angle 10 (edge directions repeat "
      "every 180)",
      true);
  expect_acuity_error("# nothing\n", "acuity table t.csv: no rows", true);
  // Repeats modulo 180 are found in a sorted pass, naming the later line.
  expect_acuity_error(
      "0,1\n45,1\n90,1\n-135,1\n",
      "acuity table t.csv line 4: angle -135 repeats angle 45 (edge directions repeat "
      "every 180)",
      true);
  expect_acuity_error("0,1\n720,1\n",
                      "acuity table t.csv line 2: angle 720 is out of range [-360, 360]", true);
  expect_acuity_error("0,0\n90,0\n",
                      "acuity table t.csv: every weight is 0, so every pattern scores 0", true);
  expect_acuity_error(
      "0,1e7\n", "acuity table t.csv line 1: weight 10000000 is out of range [0, 1000000]", true);
}

TEST(Acuity, ValidateChecksTablesBuiltInCode) {
  AcuityTable t{"mine", {0, 90}, {1}};
  EXPECT_EQ(testing::error_message([&] { validate(t); }),
            "acuity table mine: 2 angles but 1 weights");
  t.weights = {1, std::nan("")};
  EXPECT_EQ(testing::error_message([&] { validate(t); }),
            "acuity table mine: weight nan at angle 90 is out of range [0, 1000000]");
  t.angles_deg.assign(kMaxAcuityAngles + 1, 0);
  EXPECT_EQ(testing::error_message([&] { validate(t); }),
            "acuity table mine: 36001 angles exceed the limit of 36000");
  EXPECT_EQ(uniform_acuity(0.005).angles_deg.size(), 36000u);  // the finest step fits
}

TEST(Acuity, SpecErrors) {
  expect_acuity_error(
      "uniform:step=0",
      "acuity step 0 is out of range [0.005, 90] degrees (at most 36000 angles in [0, 180))");
  expect_acuity_error("uniform:size=2",
                      "acuity uniform: unknown parameter 'size=2' (it takes step, weight)");
  expect_acuity_error("linear:weight=2",
                      "acuity linear: unknown parameter 'weight=2' (it takes step)");
  expect_acuity_error(
      "no/such.csv",
      "unknown acuity table 'no/such.csv': not laine-aila, uniform:step=S, linear:step=S "
      "or a readable CSV file");
}

TEST(Acuity, LoadsAFile) {
  const std::string path = ::testing::TempDir() + "acuity_test.csv";
  std::ofstream(path) << "0,4\n90,4\n";
  const AcuityTable t = make_acuity(path);
  EXPECT_EQ(t.angles_deg.size(), 2u);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace aapat
