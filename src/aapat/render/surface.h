// What a point of the image sees and how it is shaded, apart: the primitive
// (coverage, which multisampling takes at every sample) and its shading
// (which multisampling evaluates once per pixel and primitive). Textured
// primitives know their texture coordinates and the Jacobian d(s, t)/d(x, y)
// at any point: analytically for the plane in perspective, by
// perspective-correct interpolation for a scene file's polygons.
#pragma once

#include <optional>

#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"

namespace aapat {

// 0 for the background (the sky, outside every shape). The analytic scenes'
// flat regions are primitives of their own grey (the checkerboard's white
// and black squares 1 and 2, a white shape 1); the zone plate is one shaded
// primitive; a scene file's shape k is k + 1.
int primitive_at(const Scene& scene, Vec2 p);

// The value of `primitive` at p: its grey, or its shading there (a texture
// looked up through `filter` with the Jacobian at p times `footprint`, the
// sample spacing in pixels; the zone plate's function). `lookups` gains the
// texture lookups made.
double shade_primitive(const Scene& scene, int primitive, Vec2 p, const TextureFilter& filter,
                       double footprint = 1, int* lookups = nullptr);

// The colour of `primitive` at p, as shade_primitive: a mesh scene's three
// channels at once (lookups counted once, for the red channel's texture);
// a grey scene's value in all three.
Rgb shade_primitive_colour(const Scene& scene, int primitive, Vec2 p, const TextureFilter& filter,
                           double footprint = 1, int* lookups = nullptr);
// The colour at p with exact texels, as shade.
Rgb shade_colour(const Scene& scene, Vec2 p);

// Whether any primitive's value varies over it (a texture, the zone plate):
// only then do multisampling and supersampling differ.
bool has_shading(const Scene& scene);
bool has_texture(const Scene& scene);

// A textured primitive's texture coordinates at p, in texels of level 0, and
// their Jacobian in texels per pixel; nothing for an untextured one.
struct TextureCoordinates {
  double s = 0, t = 0;
  TextureJacobian j;
};
std::optional<TextureCoordinates> texture_coordinates(const Scene& scene, int primitive, Vec2 p);

}  // namespace aapat
