// Fuzzes a glTF model's bytes through the model reader: the prescan
// (io/gltf_prescan.h) and then assimp. Any bytes give a mesh or an Error; no
// crash, no allocation past the fuzzer's memory limit. The seeds include the
// node-graph bombs (nodes nested deep, a child listed twice at each level)
// and a sparse accessor with a huge count, each cut small enough to mutate.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "aapat/core/geometry.h"
#include "aapat/io/mesh_file.h"
#include "aapat/render/mesh.h"

namespace {

// The folder the model's bytes are written to (a glTF is read from a file),
// one per process, removed when the process exits: fuzzing left one behind
// in the temporary folder per target and run.
struct ScratchFolder {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("aapat-gltf-fuzz-" + std::to_string(::getpid()));
  ScratchFolder() { std::filesystem::create_directories(dir); }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const ScratchFolder scratch;
  const std::string path = (scratch.dir / "model.gltf").string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const std::shared_ptr<const aapat::Mesh> mesh = aapat::read_mesh(path);
    if (mesh->triangles.size() > aapat::kMaxMeshTriangles) __builtin_trap();
  } catch (const aapat::Error&) {
  }
  return 0;
}
