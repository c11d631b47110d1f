#include "aapat/io/texture_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "aapat/core/hash.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/png_image.h"

namespace aapat {

namespace {

Texture decode_texture_png(const std::string& bytes, const std::string& path) {
  // The one PNG decoder (values as stored, io/png_image.h), with the
  // texture's size limits; colour becomes its luminance: Rec. 709 weights in
  // linear light, encoded back to sRGB and to 8-bit levels (grey files keep
  // their values).
  const ColorImage image =
      decode_png_color(bytes, path, "texture file",
                       {static_cast<uint32_t>(kMaxTextureSide),
                        static_cast<size_t>(kMaxTextureSide) * kMaxTextureSide})
          .image;
  const int w = image.width, h = image.height;
  Texture t{path, w, h, std::vector<double>(static_cast<size_t>(w) * h)};
  for (int j = 0; j < h; ++j)  // PNG rows run from the top; texture rows from the bottom
    for (int i = 0; i < w; ++i) {
      const float* rgb = &image.rgb[3 * (static_cast<size_t>(h - 1 - j) * w + i)];
      const float y =
          rgb[0] == rgb[1] && rgb[1] == rgb[2]
              ? rgb[0]
              : linear_to_srgb(0.2126f * srgb_to_linear(rgb[0]) + 0.7152f * srgb_to_linear(rgb[1]) +
                               0.0722f * srgb_to_linear(rgb[2]));
      // 8-bit levels, as the file holds them (k / 255 exactly for grey).
      t.texels[static_cast<size_t>(j) * w + i] =
          static_cast<double>(std::clamp(std::lround(y * 255.0f), 0L, 255L)) / 255.0;
    }
  return t;
}

}  // namespace

Texture read_texture_png(const std::string& path) {
  return decode_texture_png(read_file(path, "texture file", kMaxTextureFileBytes), path);
}

std::shared_ptr<const TexturedSurface> load_texture(const std::string& spec_or_path) {
  // Kept by spec, and a file by its content as well: a process that renders
  // again after the file changed (Python, a host program) sees the new
  // texture. The file is read every time (which also binds a checkpoint to
  // it, core/read_file.h); only the decoding and the mipmaps are saved.
  static std::mutex lock;
  static std::map<std::string, std::shared_ptr<const TexturedSurface>> loaded;
  const bool file = spec_or_path.ends_with(".png");
  const std::string bytes =
      file ? read_file(spec_or_path, "texture file", kMaxTextureFileBytes) : std::string();
  const std::string key =
      file ? fmt::format("{}\n{} {:016x}", spec_or_path, bytes.size(), checksum64(bytes))
           : spec_or_path;
  {
    std::lock_guard<std::mutex> guard(lock);
    if (const auto it = loaded.find(key); it != loaded.end()) return it->second;
  }
  Texture t = file ? decode_texture_png(bytes, spec_or_path) : make_texture(spec_or_path);
  validate(t, spec_or_path);
  auto surface = std::make_shared<const TexturedSurface>(std::move(t));
  std::lock_guard<std::mutex> guard(lock);
  if (loaded.size() >= 64) loaded.clear();  // a long session's edits do not pile up
  return loaded.try_emplace(key, std::move(surface)).first->second;
}

Scene with_texture(Scene scene, const std::string& texture) {
  if (auto* board = std::get_if<CheckerboardScene>(&scene.shape)) {
    board->texture = load_texture(texture);
    return scene;
  }
  if (auto* shapes = std::get_if<ShapesScene>(&scene.shape)) {
    bool any = false;
    for (Shape& s : shapes->shapes)
      if (!s.uv.empty() && !s.texture) {
        s.texture = load_texture(texture);
        any = true;
      }
    if (!any)
      throw ParameterError("texture",
                           " applies to the shapes with texture coordinates (\"uv\") "
                           "and no texture of their own; this scene file has none");
    index_shapes(*shapes);
    return scene;
  }
  throw ParameterError("texture", fmt::format(" {}: this scene has no texture coordinates; "
                                              "textures go on the checkerboard's ground and on "
                                              "scene files' polygons with \"uv\"",
                                              texture));
}

}  // namespace aapat
