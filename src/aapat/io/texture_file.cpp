#include "aapat/io/texture_file.h"

#include <fmt/format.h>
#include <png.h>

#include <map>
#include <mutex>

#include "aapat/core/hash.h"
#include "aapat/io/atomic_file.h"

namespace aapat {

namespace {

Texture decode_texture_png(const std::string& bytes, const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw Error(fmt::format("texture file '{}': not a PNG image ({})", path, image.message));
  struct Release {
    png_image* image;
    ~Release() { png_image_free(image); }
  } release{&image};
  if (image.width < 1 || image.height < 1 || image.width > kMaxTextureSide ||
      image.height > kMaxTextureSide)
    throw Error(fmt::format("texture file '{}': {}x{} pixels; each side must be 1 to {}", path,
                            image.width, image.height, kMaxTextureSide));
  image.format = PNG_FORMAT_GRAY;  // colour to luminance, alpha dropped, 16 bits to 8
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr))
    throw Error(fmt::format("texture file '{}': cannot decode it ({})", path, image.message));
  const int w = static_cast<int>(image.width), h = static_cast<int>(image.height);
  Texture t{path, w, h, std::vector<double>(static_cast<size_t>(w) * h)};
  for (int j = 0; j < h; ++j)  // PNG rows run from the top; texture rows from the bottom
    for (int i = 0; i < w; ++i)
      t.texels[static_cast<size_t>(j) * w + i] =
          pixels[static_cast<size_t>(h - 1 - j) * w + i] / 255.0;
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
