// Textures by name: a PNG file (grey, or colour turned to its luminance;
// io/png_image.h's decoder) or a procedural texture spec (render/texture.h),
// each loaded once per process with both mipmap pyramids; and a scene given
// its texture.
#pragma once

#include <memory>
#include <string>

#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"

namespace aapat {

// Limits of a texture file (docs/limits.md): the file's bytes, and each side
// at most kMaxTextureSide texels, checked before the pixels are decoded.
inline constexpr size_t kMaxTextureFileBytes = 256u << 20;

// A PNG file's texels in [0, 1], row 0 at the bottom. Throws Error naming the
// file: missing, not a PNG, of no size, or too large.
Texture read_texture_png(const std::string& path);

// `path.png` or a procedural spec (`checker:cells=8`); the same name gives
// the same shared surface.
std::shared_ptr<const TexturedSurface> load_texture(const std::string& spec_or_path);

// The scene with `texture` on what takes one: the checkerboard's ground, and
// a scene file's shapes that have texture coordinates but no texture of their
// own. Any other scene is refused by name.
Scene with_texture(Scene scene, const std::string& texture);

}  // namespace aapat
