// A glTF model's structure checked before assimp reads it. assimp's glTF
// importer recurses once per nested node (20,000 nested nodes overflow the
// stack inside ReadFile), expands a node listed twice as a child into two
// copies (21 nodes that each list the next twice: 2 million nodes, 4 GB
// from a 774-byte file), and allocates an accessor's count before reading
// its data (a sparse accessor of count 10^8: 3.9 GB from 456 bytes). The
// JSON is read here, without recursion, and refused past aapat's limits
// (docs/limits.md) before any of that happens.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace aapat {

inline constexpr int kMaxModelNodeDepth = 256;           // nodes nested in nodes
inline constexpr size_t kMaxModelNodes = 1'000'000;      // after a node graph is expanded
inline constexpr size_t kMaxAccessorCount = 12'000'000;  // elements of one accessor

// True when `bytes` are a glTF model: a binary .glb, or JSON text whose
// object has an "asset" (what assimp's importer recognizes).
bool looks_like_gltf(std::string_view bytes, std::string_view path);

// Throws Error naming `path` and the limit when the model's JSON nests too
// deep or does not parse, a node's children form a cycle or refer outside the
// nodes, nodes nest deeper than kMaxModelNodeDepth, the scene expands to more
// than kMaxModelNodes nodes, or an accessor (or its sparse part) holds more
// than kMaxAccessorCount elements or a buffer more bytes than a model file may.
void prescan_gltf(std::string_view bytes, const std::string& path);

}  // namespace aapat
