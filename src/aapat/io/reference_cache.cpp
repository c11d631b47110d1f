#include "aapat/io/reference_cache.h"

#include "aapat/render/color_render.h"

#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "aapat/core/hash.h"
#include "aapat/io/atomic_file.h"
#include "aapat/work/work_items.h"

namespace aapat {
namespace {

constexpr std::string_view kMagic = "aapat-reference 1\n";

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

ReferenceSource cached_references(std::string dir, Warn warn) {
  // Set by the first failure to write: warned once, not tried again.
  auto unwritable = std::make_shared<bool>(false);
  return [dir = std::move(dir), warn, unwritable](const Scene& scene, int width, int height,
                                                  const ReferenceSettings& r, double offset) {
    const std::string key = key_text(scene, width, height, r, offset);
    const std::string path = fmt::format("{}/reference-{:016x}.bin", dir, fnv1a(key));
    const int channels = scene_channels(scene);
    const size_t bytes = sizeof(double) * static_cast<size_t>(width) * height * channels;
    // The lookup is one work item (work/work_items.h), so that every process
    // of a cluster run agrees on whether the reference is rendered.
    const std::string head = std::string(kMagic) + key;
    const std::string found = run_as_one_item([&] {
      // Not empty even for a miss: a checkpoint keeps the answer.
      const std::string miss(1, '\0');
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) return miss;
      std::string data;
      try {
        data = read_file(path, "cached reference", kMagic.size() + key.size() + bytes);
      } catch (const Error&) {  // unreadable: recomputed below
      }
      // A file that is not exactly this reference (collision, older format) is recomputed.
      if (data.size() == head.size() + bytes && data.compare(0, head.size(), head) == 0)
        return '\1' + data.substr(head.size());
      return miss;
    });
    if (bytes > 0 && found.size() == bytes + 1 && found[0] == '\1') {
      Image image{width, height, offset, std::vector<double>(bytes / sizeof(double)), channels};
      std::memcpy(image.values.data(), found.data() + 1, bytes);
      return image;
    }
    Image image = render_reference(scene, width, height, r, offset);
    if (*unwritable) return image;
    try {
      ensure_directory(dir, "reference cache");
      std::string data = std::string(kMagic) + key;
      data.append(reinterpret_cast<const char*>(image.values.data()), bytes);
      write_file_now(path, data, /*keep_on_rollback=*/true);  // valid whatever the run does next
    } catch (const Error& e) {
      *unwritable = true;
      if (warn) warn(std::string(e.what()) + "; continuing without the reference cache");
    }
    return image;
  };
}

ReferenceSource remembered_references(ReferenceSource source) {
  struct Memory {
    std::mutex mutex;
    std::map<std::string, Image> images;
    size_t bytes = 0;
  };
  auto memory = std::make_shared<Memory>();
  return [source = std::move(source), memory](const Scene& scene, int width, int height,
                                              const ReferenceSettings& r, double offset) {
    constexpr size_t kMaxBytes = size_t{1} << 30;
    const std::string key = key_text(scene, width, height, r, offset);
    {
      const std::lock_guard lock(memory->mutex);
      if (auto it = memory->images.find(key); it != memory->images.end()) return it->second;
    }
    Image image = source(scene, width, height, r, offset);
    const std::lock_guard lock(memory->mutex);
    const size_t bytes = image.values.size() * sizeof(double);
    if (memory->bytes + bytes <= kMaxBytes) {
      memory->images.emplace(key, image);
      memory->bytes += bytes;
    }
    return image;
  };
}

}  // namespace aapat
