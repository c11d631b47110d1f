#include "aapat/io/gltf_prescan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/json_depth.h"
#include "aapat/io/mesh_file.h"

namespace aapat {
namespace {

using Json = nlohmann::json;

uint32_t le32(std::string_view b, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
  return v;
}

// The JSON chunk of a .glb (the first chunk: 'JSON'), or the text itself.
std::string_view json_text(std::string_view bytes, const std::string& path) {
  if (!bytes.starts_with("glTF")) return bytes;
  if (bytes.size() < 20)
    throw Error(fmt::format("model '{}': a binary glTF shorter than its header", path));
  const uint32_t length = le32(bytes, 12), type = le32(bytes, 16);
  if (type != 0x4E4F534Au || length > bytes.size() - 20)
    throw Error(fmt::format("model '{}': a binary glTF whose first chunk is not its JSON", path));
  return bytes.substr(20, length);
}

// An array member's entries, or none when it is missing or not an array.
const Json& array_of(const Json& object, const char* key) {
  static const Json kNone = Json::array();
  if (!object.is_object()) return kNone;
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : kNone;
}

// A non-negative integer member, or `fallback`.
uint64_t count_of(const Json& object, const char* key, uint64_t fallback = 0) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number()) return fallback;
  const double v = it->get<double>();
  return v >= 0 && v < 1.8e19 ? static_cast<uint64_t>(v) : UINT64_MAX;
}

// Nodes: indices in range, no cycle, nesting and expansion within the limits.
// Iterative depth-first search in post-order, so that no recursion grows with
// the model; a node's depth below it and its expanded size are memoized.
void check_nodes(const Json& nodes, const std::string& path) {
  const size_t n = nodes.size();
  if (n > kMaxModelNodes)
    throw Error(
        fmt::format("model '{}': {} nodes; at most {} (docs/limits.md)", path, n, kMaxModelNodes));
  std::vector<std::vector<size_t>> children(n);
  std::vector<bool> is_child(n, false);
  for (size_t i = 0; i < n; ++i)
    for (const Json& c : array_of(nodes[i], "children")) {
      const double v = c.is_number() ? c.get<double>() : -1;
      if (!(v >= 0 && v < static_cast<double>(n)) || v != static_cast<double>(size_t(v)))
        throw Error(fmt::format("model '{}': node {} has child {}, not a node of the model", path,
                                i, c.dump()));
      children[i].push_back(static_cast<size_t>(v));
      is_child[static_cast<size_t>(v)] = true;
    }
  enum : uint8_t { kNew, kOpen, kDone };
  std::vector<uint8_t> state(n, kNew);
  std::vector<size_t> height(n, 0), size(n, 0);
  size_t total = 0;
  for (size_t root = 0; root < n; ++root) {
    if (state[root] == kNew) {
      std::vector<std::pair<size_t, size_t>> stack{{root, 0}};  // node, next child
      state[root] = kOpen;
      while (!stack.empty()) {
        auto& [node, next] = stack.back();
        if (next < children[node].size()) {
          const size_t c = children[node][next++];
          if (state[c] == kOpen)
            throw Error(
                fmt::format("model '{}': node {} is its own descendant (a cycle)", path, c));
          if (state[c] == kNew) {
            state[c] = kOpen;
            stack.push_back({c, 0});
          }
          continue;
        }
        size_t h = 1, s = 1;
        for (size_t c : children[node]) {
          h = std::max(h, height[c] + 1);
          s = std::min(kMaxModelNodes + 1, s + size[c]);
        }
        height[node] = h;
        size[node] = s;
        state[node] = kDone;
        if (h > static_cast<size_t>(kMaxModelNodeDepth))
          throw Error(fmt::format("model '{}': nodes nested more than {} deep (docs/limits.md)",
                                  path, kMaxModelNodeDepth));
        stack.pop_back();
      }
    }
    if (!is_child[root]) total = std::min(kMaxModelNodes + 1, total + size[root]);
  }
  if (total > kMaxModelNodes)
    throw Error(
        fmt::format("model '{}': its nodes expand to more than {} (a node listed as a "
                    "child more than once is copied; docs/limits.md)",
                    path, kMaxModelNodes));
}

void check_sizes(const Json& doc, const std::string& path) {
  const Json& accessors = array_of(doc, "accessors");
  for (size_t i = 0; i < accessors.size(); ++i) {
    const uint64_t count = count_of(accessors[i], "count");
    const uint64_t sparse = accessors[i].is_object() && accessors[i].contains("sparse")
                                ? count_of(accessors[i]["sparse"], "count")
                                : 0;
    if (count > kMaxAccessorCount || sparse > kMaxAccessorCount)
      throw Error(
          fmt::format("model '{}': accessor {} holds {} elements; at most {} "
                      "(docs/limits.md)",
                      path, i, std::max(count, sparse), kMaxAccessorCount));
  }
  for (const char* key : {"buffers", "bufferViews"}) {
    const Json& list = array_of(doc, key);
    for (size_t i = 0; i < list.size(); ++i)
      if (count_of(list[i], "byteLength") > kMaxModelFileBytes)
        throw Error(fmt::format("model '{}': {} {} is {} bytes; at most {} (docs/limits.md)", path,
                                key, i, count_of(list[i], "byteLength"), kMaxModelFileBytes));
  }
}

}  // namespace

bool looks_like_gltf(std::string_view bytes, std::string_view path) {
  if (bytes.starts_with("glTF")) return true;
  const auto dot = path.rfind('.');
  std::string ext(dot == std::string_view::npos ? "" : path.substr(dot));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".gltf" || ext == ".glb";
}

void prescan_gltf(std::string_view bytes, const std::string& path) {
  const std::string_view text = json_text(bytes, path);
  check_json_depth(text, fmt::format("model '{}'", path));
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::exception& e) {
    throw Error(fmt::format("model '{}': not valid glTF JSON ({})", path, e.what()));
  }
  check_nodes(array_of(doc, "nodes"), path);
  check_sizes(doc, path);
}

}  // namespace aapat
