// Model files through Debian's assimp: glTF 2.0 (.gltf, .glb), glTF 1.0,
// OBJ (with its .mtl), PLY, STL and the other formats assimp reads, as one
// triangle mesh (render/mesh.h) with the nodes' transforms applied.
//
// Taken: triangles (polygons are triangulated; points and lines dropped),
// texture coordinates of the first set, vertex colours of the first set,
// each material's base colour (glTF's baseColorFactor, else the diffuse
// colour) and base-colour texture (PNG, a file beside the model or
// embedded), and the first camera. glTF's colour factors and vertex colours
// are linear and are carried to display values; other formats' colours are
// taken as display values. A texture that cannot be read (missing, or not a
// PNG) leaves the material's colour and a warning.
#pragma once

#include <memory>
#include <string>

#include "aapat/render/mesh.h"

namespace aapat {

// The largest model file read (docs/limits.md), checked before assimp parses it.
inline constexpr size_t kMaxModelFileBytes = size_t{1} << 30;

// Throws Error naming the file and the problem: not a file, too large, a
// format or content assimp refuses, no triangles, an index out of range, a
// value that is not finite, or a limit of render/mesh.h exceeded. A model
// read again in the same process whose files (the model, its buffers,
// materials and textures) all hold the same bytes is the mesh already read
// (a study resolves each view more than once); a file rewritten, whatever
// its size and time, is read anew.
std::shared_ptr<const Mesh> read_mesh(const std::string& path);

}  // namespace aapat
