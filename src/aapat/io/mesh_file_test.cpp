// Model files from Debian's assimp-testmodels (scripts/install-deps.sh
// installs it; nothing of it is in this repository).
#include "aapat/io/mesh_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "aapat/io/mesh_scene.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

namespace fs = std::filesystem;
const fs::path kModels = "/usr/share/assimp/models";

std::string model(const std::string& relative) {
  const fs::path p = kModels / relative;
  if (!fs::exists(p))
    ADD_FAILURE() << p
                  << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh)";
  return p.string();
}

// BoxTextured (glTF sample models): 24 vertices, 12 triangles, one material
// (assimp adds a default one unused) whose base-colour texture is the
// 211 x 211 Cesium logo.
TEST(MeshFile, ReadsAglTFModelWithItsTexture) {
  const auto m = read_mesh(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
  EXPECT_EQ(m->positions.size(), 24u);
  EXPECT_EQ(m->triangles.size(), 12u);
  ASSERT_EQ(m->uv.size(), 24u);
  const MeshMaterial& mat = m->materials[m->material[0]];
  for (uint32_t k : m->material) EXPECT_EQ(k, m->material[0]);
  ASSERT_TRUE(mat.texture[0]);
  EXPECT_EQ(mat.texture[0]->texture.width, 211);
  EXPECT_EQ(mat.texture[0]->texture.height, 211);
  EXPECT_TRUE(m->warnings.empty());
}

// The same model as .gltf with a .bin, as .glb and with its buffers embedded
// in the JSON is the same mesh, bit for bit.
TEST(MeshFile, OneModelInThreeContainers) {
  const uint64_t gltf = content_hash(*read_mesh(model("glTF2/BoxTextured-glTF/BoxTextured.gltf")));
  EXPECT_EQ(content_hash(*read_mesh(model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"))), gltf);
  EXPECT_EQ(content_hash(*read_mesh(model("glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"))),
            gltf);
}

// OBJ with an .mtl whose textures are JPEG files, some of them missing: the
// present one is read, the missing ones leave a warning each.
TEST(MeshFile, ReadsObjWithJpegTexturesAndWarnsOfMissingOnes) {
  const auto m = read_mesh(model("OBJ/spider.obj"));
  EXPECT_EQ(m->triangles.size(), 1368u);  // its 1368 faces are triangles
  bool jpeg = false;
  for (const MeshMaterial& mat : m->materials)
    if (mat.texture[0] && mat.texture_name.ends_with("SpiderTex.jpg")) jpeg = true;
  EXPECT_TRUE(jpeg);
  for (const std::string& w : m->warnings) EXPECT_NE(w.find("not used"), std::string::npos) << w;
}

// Every malformed model of the package ends in an Error that names the file,
// or loads as a valid mesh; none crashes, hangs or half-loads.
TEST(MeshFile, MalformedModelsEndInACleanError) {
  const char* files[] = {"glTF2/wrongTypes/badArray.gltf",
                         "glTF2/wrongTypes/badExtension.gltf",
                         "glTF2/wrongTypes/badNumber.gltf",
                         "glTF2/wrongTypes/badObject.gltf",
                         "glTF2/wrongTypes/badString.gltf",
                         "glTF2/wrongTypes/badUint.gltf",
                         "glTF2/IndexOutOfRange/IndexOutOfRange.gltf",
                         "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf",
                         "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
                         "glTF2/MissingBin/BoxTextured.gltf",
                         "glTF2/SchemaFailures/sceneWrongType.gltf",
                         "glTF2/TestNoRootNode/NoScene.gltf",
                         "glTF2/TestNoRootNode/SceneWithoutNodes.gltf",
                         "glTF2/RecursiveNodes/RecursiveNodes.gltf",
                         "glTF2/IncorrectVertexArrays/Cube.gltf",
                         "glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb"};
  int refused = 0;
  for (const char* f : files) {
    const std::string path = model(f);
    const std::string message = testing::error_message([&] { read_mesh(path); });
    if (message == "no error") continue;  // a correct mesh (validate passed)
    ++refused;
    EXPECT_EQ(message.rfind("model '" + path + "': ", 0), 0u) << message;
  }
  EXPECT_GE(refused, 10);  // most of them are refused, not silently read
}

// Every OBJ file of the package, edge cases included (UTF-16, no line
// ending, points and lines only, concave polygons): a mesh or a clean Error.
TEST(MeshFile, EveryObjEdgeCase) {
  int read = 0;
  for (const auto& entry : fs::directory_iterator(kModels / "OBJ")) {
    if (entry.path().extension() != ".obj") continue;
    const std::string path = entry.path().string();
    const std::string message = testing::error_message([&] { read_mesh(path); });
    if (message == "no error") {
      ++read;
    } else {
      EXPECT_EQ(message.rfind("model '" + path + "': ", 0), 0u) << message;
    }
  }
  EXPECT_GE(read, 15);
}

TEST(MeshFile, RefusesWhatIsNotAModelFile) {
  EXPECT_EQ(testing::error_message([] { read_mesh("/nonexistent/m.obj"); }),
            "model '/nonexistent/m.obj': no such file");
  const fs::path dir = fs::temp_directory_path() / fmt::format("aapat-mesh-{}", getpid());
  fs::create_directories(dir);
  const std::string fifo = (dir / "fifo.obj").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(testing::error_message([&] { read_mesh(fifo); }).find("not a regular file"),
            std::string::npos);
  std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\np 1\np 2\n";
  EXPECT_EQ(testing::error_message([&] { read_mesh((dir / "points.obj").string()); }),
            fmt::format("model '{}': it has no triangles (only points, lines or nothing)",
                        (dir / "points.obj").string()));
  std::ofstream(dir / "nan.obj") << "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_NE(
      testing::error_message([&] { read_mesh((dir / "nan.obj").string()); }).find("not finite"),
      std::string::npos);
  fs::remove_all(dir);
}

// A camera stored in the file (glTF's Cameras sample: a perspective camera,
// yfov 0.7 rad, at (0.5, 0.5, 3) looking down -z) is read as the file says.
TEST(MeshFile, ReadsTheCameraStoredInTheFile) {
  const auto m = read_mesh(model("glTF2/cameras/Cameras.gltf"));
  ASSERT_TRUE(m->camera.has_value());
  EXPECT_NEAR(m->camera->eye.x, 0.5, 1e-6);
  EXPECT_NEAR(m->camera->eye.y, 0.5, 1e-6);
  EXPECT_NEAR(m->camera->eye.z, 3, 1e-6);
  EXPECT_NEAR(m->camera->target.z, 2, 1e-6);
  EXPECT_NEAR(m->camera->fov_deg, 0.7 * 180 / kPi, 1e-4);
}

// A mesh scene file: the model beside it, the camera's fields checked.
TEST(MeshFile, SceneFileNamesItsModelAndCamera) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("aapat-mesh-scene-{}", getpid());
  fs::create_directories(dir);
  fs::copy_file(model("OBJ/box.obj"), dir / "box.obj", fs::copy_options::overwrite_existing);
  const std::string source = (dir / "s.json").string();
  const MeshSceneSpec spec = mesh_scene_from_json(
      R"({"mesh": "box.obj", "camera": {"yaw_deg": 10, "pitch_deg": 5, "fov_deg": 30}})", source);
  EXPECT_EQ(spec.mesh->triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(spec.camera.fov_deg, 30);
  EXPECT_EQ(testing::error_message([&] {
              mesh_scene_from_json(R"({"mesh": "box.obj", "camera": {"pitch_deg": 95}})", source);
            }),
            fmt::format("scene file {}: camera.pitch_deg: 95 is outside [-89.9, 89.9]", source));
  EXPECT_EQ(testing::error_message(
                [&] { mesh_scene_from_json(R"({"mesh": "box.obj", "camera": "file"})", source); }),
            fmt::format("scene file {}: camera: \"file\", but {} has no camera", source,
                        (dir / "box.obj").string()));
  EXPECT_EQ(testing::error_message(
                [&] { mesh_scene_from_json(R"({"mesh": "box.obj", "lights": 1})", source); }),
            fmt::format("scene file {}: unknown field 'lights' (expected format, mesh, camera, "
                        "light, background)",
                        source));
  fs::remove_all(dir);
}

// A model reads only what lies in its folder: a glTF buffer by absolute
// path or climbing out with .., or an OBJ texture outside, is refused by
// name; AAPAT_TRUST_MODELS=1 reads them (content the user trusts).
TEST(MeshFile, ReadsOnlyFilesInsideItsFolder) {
  const fs::path top = fs::temp_directory_path() / fmt::format("aapat-contain-{}", ::getpid());
  fs::remove_all(top);
  fs::create_directories(top / "model");
  const std::string box = model("glTF2/BoxTextured-glTF/BoxTextured.gltf");
  fs::copy_file(fs::path(box).parent_path() / "BoxTextured0.bin", top / "outside.bin");
  std::ifstream in(box);
  std::string gltf(std::istreambuf_iterator<char>(in), {});
  const auto with_buffer = [&](const std::string& uri) {
    std::string text = gltf;
    const size_t at = text.find("BoxTextured0.bin");
    text.replace(at, std::string("BoxTextured0.bin").size(), uri);
    const fs::path f = top / "model" / "box.gltf";
    std::ofstream(f) << text;
    return f.string();
  };
  {
    const std::string path = with_buffer("../outside.bin");
    const std::string message = testing::error_message([&] { read_mesh(path); });
    EXPECT_NE(message.find("is outside the model's folder"), std::string::npos) << message;
    EXPECT_NE(message.find("outside.bin"), std::string::npos) << message;
  }
  {  // assimp joins an absolute uri to the folder: refused or missing, never read
    const std::string path = with_buffer((top / "outside.bin").string());
    const std::string message = testing::error_message([&] { read_mesh(path); });
    EXPECT_TRUE(message.find("is outside the model's folder") != std::string::npos ||
                message.find("no such file") != std::string::npos)
        << message;
  }
  // An OBJ whose material's texture climbs out of the folder.
  std::ofstream(top / "model" / "m.mtl") << "newmtl m\nKd 1 1 1\nmap_Kd ../secret.png\n";
  std::ofstream(top / "model" / "t.obj")
      << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\n"
         "f 1/1 2/2 3/3\n";
  fs::copy_file(fs::path(box).parent_path() / "CesiumLogoFlat.png", top / "secret.png");
  // The texture is refused by name, and its base colour stands in (a warning).
  const std::shared_ptr<const Mesh> mesh = read_mesh((top / "model" / "t.obj").string());
  ASSERT_EQ(mesh->warnings.size(), 1u);
  EXPECT_NE(mesh->warnings[0].find("is outside the model's folder"), std::string::npos)
      << mesh->warnings[0];
  for (const MeshMaterial& m : mesh->materials) EXPECT_EQ(m.texture[0], nullptr) << m.name;
  // Trusted: the same files are read.
  ::setenv("AAPAT_TRUST_MODELS", "1", 1);
  EXPECT_NO_THROW(read_mesh(with_buffer("../outside.bin")));
  ::unsetenv("AAPAT_TRUST_MODELS");
  fs::remove_all(top);
}

// The cache keys a model by the contents of every file it read: a .bin
// rewritten with the same size and modification time is read anew, and an
// unchanged model is the mesh already read.
TEST(MeshFile, ARewrittenBufferIsReadAgain) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("aapat-stale-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path from = fs::path(model("glTF2/BoxTextured-glTF/BoxTextured.gltf")).parent_path();
  for (const char* f : {"BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png"})
    fs::copy_file(from / f, dir / f);
  const std::string path = (dir / "BoxTextured.gltf").string();
  const std::shared_ptr<const Mesh> first = read_mesh(path);
  EXPECT_EQ(read_mesh(path), first);  // unchanged: the same mesh
  // Scale every float of the buffer's positions: the same size, the same time.
  const fs::path bin = dir / "BoxTextured0.bin";
  const auto time = fs::last_write_time(bin);
  std::string bytes;
  {
    std::ifstream in(bin, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::fstream out(bin, std::ios::binary | std::ios::in | std::ios::out);
  out.seekp(288);
  for (size_t k = 288; k < 576; k += 4) {  // the positions: bytes 288 to 576
    float v = 0;
    std::memcpy(&v, &bytes[k], 4);
    v *= 2;
    out.write(reinterpret_cast<const char*>(&v), 4);
  }
  out.close();
  fs::last_write_time(bin, time);
  const std::shared_ptr<const Mesh> second = read_mesh(path);
  EXPECT_NE(second, first);
  EXPECT_NE(content_hash(*second), content_hash(*first));
  fs::remove_all(dir);
}

// PLY: counts past the limits are refused from the header (assimp allocated
// them first: std::bad_alloc), and an ASCII face whose list count is not the
// number of indices on its line is named (assimp read on into the next lines).
TEST(MeshFile, PlyCountsAndFaceListsAreChecked) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("aapat-ply-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto ply = [&](const std::string& name, const std::string& vertices,
                       const std::string& face) {
    std::ofstream(dir / name) << "ply\nformat ascii 1.0\nelement vertex " << vertices
                              << "\nproperty float x\nproperty float y\nproperty float z\n"
                                 "element face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n"
                              << face << "\n";
    return (dir / name).string();
  };
  EXPECT_EQ(read_mesh(ply("good.ply", "3", "3 0 1 2"))->triangles.size(), 1u);
  const std::string liar = ply("liar.ply", "3", "255 0 1 2");
  EXPECT_EQ(testing::error_message([&] { read_mesh(liar); }),
            "model '" + liar + "': face 0 lists 255 indices but its line gives 3");
  const std::string huge = ply("huge.ply", "3000000000000", "3 0 1 2");
  EXPECT_EQ(
      testing::error_message([&] { read_mesh(huge); }),
      "model '" + huge + "': 3000000000000 vertex elements; at most 12000000 (docs/limits.md)");
  // An OBJ whose material library is a device: the model reads, with a warning.
  std::ofstream(dir / "dev.obj") << "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  ::setenv("AAPAT_TRUST_MODELS", "1", 1);  // past the folder rule, to the device itself
  const std::shared_ptr<const Mesh> dev = read_mesh((dir / "dev.obj").string());
  ::unsetenv("AAPAT_TRUST_MODELS");
  ASSERT_EQ(dev->warnings.size(), 1u);
  EXPECT_NE(dev->warnings[0].find("a file it names was not read"), std::string::npos)
      << dev->warnings[0];
  EXPECT_NE(dev->warnings[0].find("/dev/zero"), std::string::npos) << dev->warnings[0];
  fs::remove_all(dir);
}

}  // namespace
}  // namespace aapat
