#include "aapat/io/reference_cache.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "aapat/core/hash.h"
#include "aapat/io/atomic_file.h"
#include "aapat/render/color_render.h"
#include "aapat/work/work_items.h"

namespace aapat {
namespace {

// Version 2 adds the values' checksum: a file whose values were changed after
// it was written is rendered afresh, not trusted. Version 3 takes it with
// checksum64 (fnv1a cost 5% of a cached 1024² render; this, 0.3%). Version 4:
// references are summed pixel by pixel (render/pixel_splat.h), which moves
// their last bits, so a version 3 entry is rendered afresh, not mixed in.
constexpr std::string_view kMagic = "aapat-reference 4\n";

// The line between the key and the values: their checksum.
std::string checksum_line(std::string_view values) {
  return fmt::format("values {:016x}\n", checksum64(values));
}
constexpr size_t kChecksumLineBytes = 24;  // "values " + 16 hex digits + "\n"

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

ReferenceSource cached_references(std::string dir, Warn warn, ReferenceSource render) {
  remove_orphaned_temporaries(dir);  // a killed run's half-written entries
  // Set by the first failure to write: warned once, not tried again.
  auto unwritable = std::make_shared<bool>(false);
  return [dir = std::move(dir), warn, unwritable, render = std::move(render)](
             const Scene& scene, int width, int height, const ReferenceSettings& r, double offset) {
    const std::string key = key_text(scene, width, height, r, offset);
    const std::string path = fmt::format("{}/reference-{:016x}.bin", dir, fnv1a(key));
    const int channels = scene_channels(scene);
    const size_t bytes = sizeof(double) * static_cast<size_t>(width) * height * channels;
    // The lookup is one work item (work/work_items.h), so that every process
    // of a cluster run agrees on whether the reference is rendered.
    const std::string head = std::string(kMagic) + key;
    const std::string found = run_as_one_item([&] {
      // Not empty even for a miss: a checkpoint keeps the answer. '\2': this
      // reference, damaged.
      const std::string miss(1, '\0'), damaged(1, '\2');
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) return miss;
      std::string data;
      try {
        data = read_file(path, "cached reference", head.size() + kChecksumLineBytes + bytes, false);
      } catch (const Error&) {  // unreadable: recomputed below
      }
      // A file that is not this reference (collision, older format) is recomputed.
      if (data.compare(0, head.size(), head) != 0) return miss;
      // This reference, whose values must be what was written: their length,
      // checksum and finiteness.
      if (data.size() != head.size() + kChecksumLineBytes + bytes) return damaged;
      const std::string_view values =
          std::string_view(data).substr(head.size() + kChecksumLineBytes);
      if (data.compare(head.size(), kChecksumLineBytes, checksum_line(values)) != 0) return damaged;
      for (size_t k = 0; k < bytes; k += sizeof(double)) {
        double v;
        std::memcpy(&v, values.data() + k, sizeof v);
        if (!std::isfinite(v)) return damaged;
      }
      return '\1' + std::string(values);
    });
    if (found.size() == 1 && found[0] == '\2' && warn)
      warn(
          fmt::format("cached reference {} does not hold the values written to it (its "
                      "checksum or length differs); rendering it afresh",
                      path));
    if (bytes > 0 && found.size() == bytes + 1 && found[0] == '\1') {
      Image image{width, height, offset, std::vector<double>(bytes / sizeof(double)), channels};
      std::memcpy(image.values.data(), found.data() + 1, bytes);
      return image;
    }
    Image image = render(scene, width, height, r, offset);
    if (*unwritable) return image;
    try {
      ensure_directory(dir, "reference cache");
      const std::string_view values(reinterpret_cast<const char*>(image.values.data()), bytes);
      std::string data = std::string(kMagic) + key + checksum_line(values);
      data.append(values);
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
