#include "aapat/io/gltf_prescan.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "aapat/io/mesh_file.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

namespace fs = std::filesystem;

// One triangle, its buffer a data URI (three float positions), and `nodes`.
std::string triangle_with(const std::string& nodes, const std::string& accessor_extra = "") {
  // 9 floats: (0,0,0) (1,0,0) (0,1,0), base64.
  const std::string buffer =
      "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
  return fmt::format(
      R"({{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
  "nodes": {},
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
  "buffers": [{{"uri": "{}", "byteLength": 36}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0]{}}}]}})",
      nodes, buffer, accessor_extra);
}

std::string refusal(const std::string& text) {
  return testing::error_message([&] { prescan_gltf(text, "m.gltf"); });
}

// 20,000 nested nodes (assimp's importer overflowed its stack on them) are
// refused from the JSON, without recursion.
TEST(GltfPrescan, DeepNodesAreRefusedBeforeAssimp) {
  std::string nodes = "[";
  for (int i = 0; i < 20000; ++i)
    nodes += fmt::format("{}{{\"children\": [{}]}}", i ? "," : "", i + 1);
  nodes += ",{\"mesh\": 0}]";
  EXPECT_EQ(refusal(triangle_with(nodes)),
            "model 'm.gltf': nodes nested more than 256 deep (docs/limits.md)");
  // 255 nested nodes are read.
  std::string fine = "[";
  for (int i = 0; i < 255; ++i)
    fine += fmt::format("{}{{\"children\": [{}]}}", i ? "," : "", i + 1);
  fine += ",{\"mesh\": 0}]";
  EXPECT_NO_THROW(prescan_gltf(triangle_with(fine), "m.gltf"));
}

// 21 nodes that each list the next twice expand to 2^21 copies (4 GB from a
// 774-byte file in assimp): refused by their count after expansion.
TEST(GltfPrescan, NodeGraphsThatExpandAreRefused) {
  std::string nodes = "[";
  for (int i = 0; i < 21; ++i)
    nodes += fmt::format("{}{{\"children\": [{}, {}]}}", i ? "," : "", i + 1, i + 1);
  nodes += ",{\"mesh\": 0}]";
  const std::string m = refusal(triangle_with(nodes));
  EXPECT_NE(m.find("its nodes expand to more than 1000000"), std::string::npos) << m;
  // Shared but small: 4 levels of two copies is 31 nodes, read.
  EXPECT_NO_THROW(prescan_gltf(
      triangle_with(R"([{"children": [1, 1]}, {"children": [2, 2]}, {"children": [3, 3]},
                        {"children": [4, 4]}, {"mesh": 0}])"),
      "m.gltf"));
}

TEST(GltfPrescan, CyclesAndBadIndicesAreNamed) {
  EXPECT_EQ(refusal(triangle_with(R"([{"children": [1]}, {"children": [0]}])")),
            "model 'm.gltf': node 0 is its own descendant (a cycle)");
  EXPECT_EQ(refusal(triangle_with(R"([{"children": [7]}])")),
            "model 'm.gltf': node 0 has child 7, not a node of the model");
  EXPECT_EQ(refusal(triangle_with(R"([{"children": [0.5]}, {}])")),
            "model 'm.gltf': node 0 has child 0.5, not a node of the model");
}

// An accessor's count is what assimp allocates before reading any data (a
// sparse count of 10^8 took 3.9 GB from 456 bytes).
TEST(GltfPrescan, AccessorCountsAreBounded) {
  const std::string sparse = R"(, "sparse": {"count": 100000000, "indices": {"bufferView": 0,
      "componentType": 5125}, "values": {"bufferView": 0}})";
  EXPECT_EQ(refusal(triangle_with(R"([{"mesh": 0}])", sparse)),
            "model 'm.gltf': accessor 0 holds 100000000 elements; at most 12000000 "
            "(docs/limits.md)");
  std::string big = triangle_with(R"([{"mesh": 0}])");
  big.replace(big.find("\"count\": 3"), 10, "\"count\": 3e9");
  EXPECT_NE(refusal(big).find("accessor 0 holds 3000000000 elements"), std::string::npos);
}

TEST(GltfPrescan, JsonNestingAndBinaryContainers) {
  const std::string deep = "{\"asset\": " + std::string(5000, '[') + std::string(5000, ']') + "}";
  EXPECT_NE(refusal(deep).find("nested 5001 deep, past the limit of 256"), std::string::npos);
  EXPECT_NE(refusal("{\"asset\": ").find("not valid glTF JSON"), std::string::npos);
  // A .glb whose JSON chunk holds the node cycle.
  const std::string json = triangle_with(R"([{"children": [1]}, {"children": [0]}])");
  std::string glb = "glTF";
  const auto u32 = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) glb += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  u32(2);
  u32(static_cast<uint32_t>(20 + json.size()));
  u32(static_cast<uint32_t>(json.size()));
  u32(0x4E4F534Au);
  glb += json;
  EXPECT_EQ(refusal(glb), "model 'm.gltf': node 0 is its own descendant (a cycle)");
  EXPECT_NE(refusal(glb.substr(0, 12)).find("shorter than its header"), std::string::npos);
  EXPECT_TRUE(looks_like_gltf(glb, "x.bin"));
  EXPECT_TRUE(looks_like_gltf("{}", "Model.GLTF"));
  EXPECT_FALSE(looks_like_gltf("v 0 0 0", "model.obj"));
}

// Through the model reader: the refusal is the error, and a sound file reads.
TEST(GltfPrescan, TheModelReaderRefusesBeforeAssimpRuns) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("aapat-gltf-{}", ::getpid());
  fs::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  std::string nodes = "[";
  for (int i = 0; i < 21; ++i)
    nodes += fmt::format("{}{{\"children\": [{}, {}]}}", i ? "," : "", i + 1, i + 1);
  nodes += ",{\"mesh\": 0}]";
  const std::string bomb = write("bomb.gltf", triangle_with(nodes));
  const std::string m = testing::error_message([&] { read_mesh(bomb); });
  EXPECT_NE(m.find("model '" + bomb + "': its nodes expand to more than"), std::string::npos) << m;
  const std::shared_ptr<const Mesh> mesh =
      read_mesh(write("triangle.gltf", triangle_with(R"([{"mesh": 0}])")));
  EXPECT_EQ(mesh->triangles.size(), 1u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace aapat
