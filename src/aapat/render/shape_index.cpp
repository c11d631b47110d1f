#include "aapat/render/shape_index.h"

#include <algorithm>
#include <cmath>

#include "aapat/render/scene.h"

namespace aapat {
namespace {

constexpr size_t kMaxCellEntries = size_t{1} << 24;  // shape-in-cell entries, memory bound
constexpr size_t kBandedPolygon = 32;                // vertices past which edges are banded

struct Box {
  double x0, y0, x1, y1;
};

Box bounds(const Shape& s) {
  if (s.polygon.empty())
    return {s.centre.x - s.radius, s.centre.y - s.radius, s.centre.x + s.radius,
            s.centre.y + s.radius};
  Box b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Vec2& v : s.polygon)
    b = {std::min(b.x0, v.x), std::min(b.y0, v.y), std::max(b.x1, v.x), std::max(b.y1, v.y)};
  return b;
}

bool crosses(Vec2 p, Vec2 a, Vec2 b) {
  return (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
}

}  // namespace

bool in_polygon(Vec2 p, const std::vector<Vec2>& poly) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if (crosses(p, poly[i], poly[j])) inside = !inside;
  return inside;
}

ShapeIndex::ShapeIndex(const std::vector<Shape>& shapes) {
  if (shapes.empty()) return;
  std::vector<Box> boxes;
  Box all{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Shape& s : shapes) {
    boxes.push_back(bounds(s));
    const Box& b = boxes.back();
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1),
           std::max(all.y1, b.y1)};
  }
  x0_ = all.x0;
  y0_ = all.y0;
  const double w = std::max(all.x1 - all.x0, 1e-9), h = std::max(all.y1 - all.y0, 1e-9);
  // About one shape per cell; coarser while large shapes would fill too many cells.
  int side = std::clamp(static_cast<int>(std::ceil(std::sqrt(double(shapes.size())))), 1, 512);
  for (;; side = std::max(1, side / 2)) {
    cols_ = rows_ = side;
    inv_cell_w_ = cols_ / w;
    inv_cell_h_ = rows_ / h;
    size_t entries = 0;
    for (const Box& b : boxes) {
      const auto c0 =
          std::clamp(static_cast<long>((b.x0 - x0_) * inv_cell_w_), 0L, long(cols_ - 1));
      const auto c1 =
          std::clamp(static_cast<long>((b.x1 - x0_) * inv_cell_w_), 0L, long(cols_ - 1));
      const auto r0 =
          std::clamp(static_cast<long>((b.y0 - y0_) * inv_cell_h_), 0L, long(rows_ - 1));
      const auto r1 =
          std::clamp(static_cast<long>((b.y1 - y0_) * inv_cell_h_), 0L, long(rows_ - 1));
      entries += static_cast<size_t>(c1 - c0 + 1) * static_cast<size_t>(r1 - r0 + 1);
    }
    if (entries <= kMaxCellEntries || side == 1) break;
  }
  cells_.assign(static_cast<size_t>(cols_) * rows_, {});
  for (size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    const int c0 = std::clamp(static_cast<int>((b.x0 - x0_) * inv_cell_w_), 0, cols_ - 1);
    const int c1 = std::clamp(static_cast<int>((b.x1 - x0_) * inv_cell_w_), 0, cols_ - 1);
    const int r0 = std::clamp(static_cast<int>((b.y0 - y0_) * inv_cell_h_), 0, rows_ - 1);
    const int r1 = std::clamp(static_cast<int>((b.y1 - y0_) * inv_cell_h_), 0, rows_ - 1);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        cells_[static_cast<size_t>(r) * cols_ + c].push_back(static_cast<uint32_t>(i));
  }
  // Long polygons: each edge in every band its y range touches.
  bands_.resize(shapes.size());
  for (size_t i = 0; i < shapes.size(); ++i) {
    const auto& poly = shapes[i].polygon;
    if (poly.size() <= kBandedPolygon) continue;
    Bands& bands = bands_[i];
    const int count = std::clamp(static_cast<int>(std::sqrt(double(poly.size()))), 1, 1024);
    bands.y0 = boxes[i].y0;
    bands.inv_height = count / std::max(boxes[i].y1 - boxes[i].y0, 1e-9);
    bands.edges.assign(count, {});
    auto band = [&](double y) {
      return std::clamp(static_cast<int>((y - bands.y0) * bands.inv_height), 0, count - 1);
    };
    for (size_t e = 0; e < poly.size(); ++e) {
      const Vec2 a = poly[e], b = poly[e == 0 ? poly.size() - 1 : e - 1];
      for (int k = band(std::min(a.y, b.y)); k <= band(std::max(a.y, b.y)); ++k)
        bands.edges[k].push_back(static_cast<uint32_t>(e));
    }
  }
}

bool ShapeIndex::contains(const Shape& s, size_t index, Vec2 p) const {
  if (s.polygon.empty()) return vector_length(p.x - s.centre.x, p.y - s.centre.y) <= s.radius;
  const Bands& bands = bands_[index];
  if (bands.edges.empty()) return in_polygon(p, s.polygon);
  // Only an edge whose y range holds p.y can cross the ray: p's band has them all.
  const double t = (p.y - bands.y0) * bands.inv_height;
  if (!(t >= 0 && t < static_cast<double>(bands.edges.size()) + 1)) return false;
  const int k = std::min(static_cast<int>(t), static_cast<int>(bands.edges.size()) - 1);
  bool inside = false;
  const auto& poly = s.polygon;
  for (uint32_t e : bands.edges[k])
    if (crosses(p, poly[e], poly[e == 0 ? poly.size() - 1 : e - 1])) inside = !inside;
  return inside;
}

int ShapeIndex::top_shape_at(const std::vector<Shape>& shapes, Vec2 p) const {
  if (cells_.empty()) return -1;
  const double cx = (p.x - x0_) * inv_cell_w_, cy = (p.y - y0_) * inv_cell_h_;
  // Outside every box (with a cell of slack for the boxes' closed edges).
  if (!(cx >= -1 && cy >= -1 && cx <= cols_ + 1 && cy <= rows_ + 1)) return -1;
  const int c = std::clamp(static_cast<int>(std::floor(cx)), 0, cols_ - 1);
  const int r = std::clamp(static_cast<int>(std::floor(cy)), 0, rows_ - 1);
  const auto& list = cells_[static_cast<size_t>(r) * cols_ + c];
  for (auto it = list.rbegin(); it != list.rend(); ++it)
    if (contains(shapes[*it], *it, p)) return static_cast<int>(*it);
  return -1;
}

}  // namespace aapat
