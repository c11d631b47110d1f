#include "aapat/io/pattern_json.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "aapat/generate/catalog.h"
#include "aapat/io/atomic_file.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

std::vector<std::string> catalog_names() {
  std::vector<std::string> names;
  for (const auto& [e, build] : pattern_registry().entries())
    names.push_back(e.name == "grid-NxN" ? "grid-3x3" : e.name);
  return names;
}

// A pattern file round-trips byte for byte, and to the same values.
TEST(PatternJson, RoundTripsEveryCatalogPatternExactly) {
  for (const auto& name : catalog_names()) {
    const Pattern p = catalog_pattern(name);
    const std::string text = pattern_to_json(p);
    const Pattern back = pattern_from_json(text, "mem");
    EXPECT_EQ(pattern_to_json(back), text) << name;
    EXPECT_EQ(back.sets, p.sets) << name;
    EXPECT_EQ(back.weights, p.weights) << name;
    EXPECT_EQ(back.provenance, p.provenance) << name;
  }
}

TEST(PatternJson, KeepsFullPrecisionAndProvenanceOrder) {
  Pattern p =
      single_pixel_pattern("third", {{1.0 / 3, -0.1}, {0.1 + 0.2, 0.2}}, {1.0 / 3, 2.0 / 3});
  p.provenance = {{"zeta", "1"}, {"alpha", "two"}};
  const Pattern back = pattern_from_json(pattern_to_json(p), "mem");
  EXPECT_EQ(back.sets[0][0].x, 1.0 / 3);
  EXPECT_EQ(back.sets[0][1].x, 0.1 + 0.2);
  EXPECT_EQ(back.weights[0][1], 2.0 / 3);
  EXPECT_EQ(back.provenance, p.provenance);
}

const char* kMinimal = R"({
  "format": "aapat-pattern", "version": 1, "name": "one",
  "tile": [1, 1], "footprint": "1", "sets": [[[0, 0]]], "kernels": [[1]]
})";

void expect_pattern_file_error(const std::string& text, const std::string& message) {
  EXPECT_EQ(testing::error_message([&] { pattern_from_json(text, "p.json"); }), message) << text;
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PatternJson, MinimalFileLoads) {
  const Pattern p = pattern_from_json(kMinimal, "p.json");
  EXPECT_EQ(family(p), "P(1,1,1)");
}

// Each load rule with its exact message.
TEST(PatternJson, RejectsMalformedFilesNamingTheField) {
  const std::string m = kMinimal;
  expect_pattern_file_error(
      "{",
      "pattern file p.json: not valid JSON: [json.exception.parse_error.101] parse "
      "error at line 1, column 2: syntax error while parsing object key - unexpected "
      "end of input; expected string literal");
  expect_pattern_file_error("[]", "pattern file p.json: expected a JSON object at the top level");
  expect_pattern_file_error(
      with(m, "\"name\": \"one\",", "\"name\": \"one\", \"weight\": 1,"),
      "pattern file p.json: weight: unknown field (known: format, version, name, "
      "description, family, tile, footprint, sets, kernels, provenance)");
  expect_pattern_file_error(with(m, "\"tile\": [1, 1], ", ""),
                            "pattern file p.json: tile: missing");
  expect_pattern_file_error(
      with(m, "aapat-pattern", "other"),
      "pattern file p.json: format: expected \"aapat-pattern\", got \"other\"");
  expect_pattern_file_error(
      with(m, "\"version\": 1", "\"version\": 2"),
      "pattern file p.json: version: 2 is not supported (this aapat reads version 1)");
  expect_pattern_file_error(with(m, "\"name\": \"one\"", "\"name\": 5"),
                            "pattern file p.json: name: expected a string");
  expect_pattern_file_error(with(m, "[1, 1]", "[1.5, 1]"),
                            "pattern file p.json: tile: expected [width, height] in pixels");
  expect_pattern_file_error(
      with(m, "\"footprint\": \"1\"", "\"footprint\": \"3x3\""),
      "pattern file p.json: footprint: '3x3' is not one of 1, 1+, 2x2, 2x2+, 4x4, 4x4+ "
      "(or r = 4, 16 with optional +)");
  expect_pattern_file_error(
      with(m, "[1, 1]", "[4294967297, 1]"),
      "pattern file p.json: tile: 4294967297x1 is not a tile size: each side must be 1 to "
      "128 pixels");
  expect_pattern_file_error(with(m, "[[[0, 0]]]", "[[[0, 0, 0]]]"),
                            "pattern file p.json: sets[0][0]: expected [x, y]");
  expect_pattern_file_error(with(m, "[[[0, 0]]]", "[[[0, \"a\"]]]"),
                            "pattern file p.json: sets[0][0].y: expected a number");
  expect_pattern_file_error(
      with(m, "[[[0, 0]]]", "[[[0, 0.7]]]"),
      "pattern file p.json: sets[0][0]: (0, 0.7) lies outside the pixel [-0.5, 0.5] x "
      "[-0.5, 0.5]");
  expect_pattern_file_error(
      with(m, "[[1]]", "[[0.5]]"),
      "pattern file p.json: kernels[0]: weights sum to 0.5 instead of 1 (tolerance 1e-06)");
  expect_pattern_file_error(
      with(m, "[[1]]", "[[1, 0]]"),
      "pattern file p.json: kernels[0]: the kernel reads 1 samples but has 2 weights");
  expect_pattern_file_error(
      with(m, "\"kernels\": [[1]]", "\"kernels\": [[1]], \"family\": \"P(1,1,2)\""),
      "pattern file p.json: family: the file says P(1,1,2) but its samples make P(1,1,1)");
  expect_pattern_file_error(
      with(m, "\"kernels\": [[1]]", "\"kernels\": [[1]], \"provenance\": {\"seed\": 4}"),
      "pattern file p.json: provenance.seed: expected a string");
}

TEST(PatternJson, OverflowingNumbersAreRejected) {
  // JSON has no NaN; a number too large for a double must not sneak in as inf.
  const std::string message = testing::error_message(
      [] { pattern_from_json(with(kMinimal, "[[[0, 0]]]", "[[[0, 1e999]]]"), "p.json"); });
  EXPECT_NE(message.find("p.json"), std::string::npos) << message;
}

TEST(PatternJson, FilesRoundTripAndMissingFilesAreNamed) {
  const std::string path = ::testing::TempDir() + "aapat_rt.json";
  save_pattern_file(catalog_pattern("hasselgren-c"), path);
  const Pattern p = load_pattern_file(path);
  EXPECT_EQ(read_file(path, "file"), pattern_to_json(p));
  std::filesystem::remove(path);
  EXPECT_EQ(testing::error_message([] { load_pattern_file("/no/such/file.json"); }),
            "cannot read pattern file '/no/such/file.json': no such file");
}

TEST(PatternJson, ResolvesCatalogNamesAndFiles) {
  EXPECT_EQ(resolve_pattern("flipquad").name, "flipquad");
  EXPECT_THROW(resolve_pattern("missing.json"), Error);
}

}  // namespace
}  // namespace aapat
