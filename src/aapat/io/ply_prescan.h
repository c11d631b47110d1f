// A PLY model's header and, for ASCII files, its faces, checked before
// assimp reads it: assimp allocates an element's count before reading any
// of it (a header claiming 10^12 vertices ends in std::bad_alloc), and reads
// an ASCII face whose list count exceeds the indices on its line from the
// lines that follow (a face that says 255 indices and gives 3 became 254
// triangles).
#pragma once

#include <string>
#include <string_view>

namespace aapat {

// True when `bytes` start as a PLY file does ("ply" and a line end).
bool looks_like_ply(std::string_view bytes);

// Throws Error naming `path` when the header does not end, the vertex count
// passes kMaxMeshVertices or the face count kMaxMeshTriangles
// (render/mesh.h), or, in an ASCII file whose faces hold one index list and
// nothing else, a face's line gives another number of indices than it lists.
void prescan_ply(std::string_view bytes, const std::string& path);

}  // namespace aapat
