#include "aapat/io/scene_json.h"
#include "testing/error_message.h"

#include <gtest/gtest.h>

namespace aapat {
namespace {

TEST(SceneJson, ReadsPolygonsCirclesAndGreyLevels) {
  const ShapesScene s = scene_from_json(R"({
    "format": "aapat-scene",
    "background": 0.2,
    "shapes": [
      {"polygon": [[0, 0], [10, 0], [0, 10]], "grey": 1},
      {"circle": [5, 5], "radius": 2, "grey": 0.5},
      {"polygon": [[20, 20], [30, 20], [30, 30]]}
    ]})",
                                        "test");
  ASSERT_EQ(s.shapes.size(), 3u);
  EXPECT_EQ(s.background, 0.2);
  EXPECT_EQ(s.shapes[0].polygon.size(), 3u);
  EXPECT_EQ(s.shapes[1].radius, 2);
  EXPECT_EQ(s.shapes[2].grey, 1);  // the default
  EXPECT_EQ(shade(s, {5, 5}), 0.5);
  EXPECT_EQ(shade(s, {1, 1}), 1.0);
  EXPECT_EQ(shade(s, {15, 15}), 0.2);
}

TEST(SceneJson, RejectsBadFilesByName) {
  auto message = [](const char* text) {
    return testing::error_message([&] { scene_from_json(text, "s.json"); });
  };
  EXPECT_NE(message("{").find("scene file s.json: not valid JSON"), std::string::npos);
  EXPECT_EQ(message(R"({"shapes": [{"polygon": [[0,0],[1,1]]}]})"),
            "scene file s.json: shapes[0].polygon: expected a list of 3 or more [x, y] vertices");
  EXPECT_EQ(message(R"({"shapes": [{"circle": [0,0], "radius": -1}]})"),
            "scene file s.json: shapes[0].radius: -1 is outside [0, 10000000]");
  EXPECT_EQ(message(R"({"shapes": [{"circle": [0,0]}]})"),
            "scene file s.json: shapes[0]: a circle needs a radius");
  EXPECT_EQ(message(R"({"shapes": [{"circle": [0,0], "radius": 1, "grey": 2}]})"),
            "scene file s.json: shapes[0].grey: 2 is outside [0, 1]");
  EXPECT_EQ(message(R"({"shapes": [{"circle": [0,0], "polygon": [], "radius": 1}]})"),
            "scene file s.json: shapes[0]: give either \"polygon\" or \"circle\"");
  EXPECT_EQ(message(R"({"shapes": [{"polygon": [[0,0],[1,"a"],[2,0]]}]})"),
            "scene file s.json: shapes[0].polygon[1][1]: expected a number");
  EXPECT_EQ(message(R"({"shape": []})"),
            "scene file s.json: unknown field 'shape' (expected format, background, shapes)");
  EXPECT_EQ(message(R"({"format": "svg", "shapes": []})"),
            "scene file s.json: format: expected \"aapat-scene\"");
  EXPECT_EQ(message(R"({"background": 1})"),
            "scene file s.json: shapes: expected a list of polygons and circles");
}

}  // namespace
}  // namespace aapat
