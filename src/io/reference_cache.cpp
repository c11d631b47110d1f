#include "io/reference_cache.h"

#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "io/atomic_file.h"

namespace aapat {
namespace {

constexpr std::string_view kMagic = "aapat-reference 1\n";

uint64_t fnv1a(std::string_view text) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string key_text(const Scene& scene, int width, int height, const ReferenceSettings& r,
                     double offset) {
  return fmt::format("{}size {} {} offset {:.17g} samples {} filter {} seed {}\n",
                     canonical_text(scene), width, height, offset, r.samples, r.filter, r.seed);
}

}  // namespace

std::string default_cache_dir() {
  if (const char* dir = std::getenv("AAPAT_CACHE"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/aapat";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.cache/aapat";
  return ".aapat-cache";
}

ReferenceSource cached_references(std::string dir) {
  return [dir = std::move(dir)](const Scene& scene, int width, int height,
                                const ReferenceSettings& r, double offset) {
    const std::string key = key_text(scene, width, height, r, offset);
    const std::string path = fmt::format("{}/reference-{:016x}.bin", dir, fnv1a(key));
    const size_t bytes = sizeof(double) * static_cast<size_t>(width) * height;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
      const std::string data = read_file(path, "cached reference");
      const std::string head = std::string(kMagic) + key;
      // A file that is not exactly this reference (collision, older format) is recomputed.
      if (data.size() == head.size() + bytes && data.compare(0, head.size(), head) == 0) {
        Image image{width, height, offset,
                    std::vector<double>(static_cast<size_t>(width) * height)};
        std::memcpy(image.values.data(), data.data() + head.size(), bytes);
        return image;
      }
    }
    Image image = render_reference(scene, width, height, r, offset);
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(fmt::format("reference cache: cannot create '{}': {}", dir, ec.message()));
    std::string data = std::string(kMagic) + key;
    data.append(reinterpret_cast<const char*>(image.values.data()), bytes);
    write_file_atomically(path, data);
    return image;
  };
}

}  // namespace aapat
