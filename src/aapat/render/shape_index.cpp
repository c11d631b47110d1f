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

// Whether segment ab may meet the closed box: false only when it surely does
// not (its bounding box is apart, or the box's corners are all strictly on
// one side of its line).
bool may_meet(Vec2 a, Vec2 b, const Box& box) {
  if (std::max(a.x, b.x) < box.x0 || std::min(a.x, b.x) > box.x1 || std::max(a.y, b.y) < box.y0 ||
      std::min(a.y, b.y) > box.y1)
    return false;
  int above = 0, below = 0;
  for (const Vec2 q :
       {Vec2{box.x0, box.y0}, Vec2{box.x1, box.y0}, Vec2{box.x0, box.y1}, Vec2{box.x1, box.y1}}) {
    const double side = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    above += side > 0;
    below += side < 0;
  }
  return !(above == 4 || below == 4);
}

// Where a shape stands to a whole box: every point of it inside the shape,
// none, or some (the edge passes through it, or too near to tell).
enum class Cover { inside, outside, partly };

// Polygons with more edges than this are not classified (the cost is edges
// times cells), nor when the shapes' cells hold more than kClassifiedEdges
// edges in all: those cells test every point as before.
constexpr size_t kClassifiedPolygon = 64;
constexpr size_t kClassifiedEdges = size_t{1} << 24;

Cover cover(const Shape& s, const Box& box) {
  if (s.polygon.empty()) {
    // A disc holds a box when it holds its farthest corner, and misses it
    // when it misses its nearest point, with a relative slack far beyond the
    // rounding of vector_length.
    const double dx_far = std::max(std::abs(box.x0 - s.centre.x), std::abs(box.x1 - s.centre.x)),
                 dy_far = std::max(std::abs(box.y0 - s.centre.y), std::abs(box.y1 - s.centre.y));
    const double dx_near = std::max({0.0, box.x0 - s.centre.x, s.centre.x - box.x1}),
                 dy_near = std::max({0.0, box.y0 - s.centre.y, s.centre.y - box.y1});
    const double slack =
        1e-9 * (1 + s.radius + std::abs(s.centre.x) + std::abs(s.centre.y) + dx_far + dy_far);
    if (vector_length(dx_far, dy_far) < s.radius - slack) return Cover::inside;
    if (vector_length(dx_near, dy_near) > s.radius + slack) return Cover::outside;
    return Cover::partly;
  }
  // No edge meets the box: the even-odd parity is the same all over it, the
  // box's centre's (far from every edge, so the crossing tests are exact).
  const auto& poly = s.polygon;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if (may_meet(poly[i], poly[j], box)) return Cover::partly;
  return in_polygon({(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2}, poly) ? Cover::inside
                                                                          : Cover::outside;
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
  // About one shape per cell, and at least 32 x 32 cells, so that a few
  // large shapes leave most cells wholly inside or outside them (classified
  // below); coarser while large shapes would fill too many cells.
  int side = std::clamp(static_cast<int>(std::ceil(std::sqrt(double(shapes.size())))), 32, 512);
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
  classify_cells(shapes);
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

void ShapeIndex::classify_cells(const std::vector<Shape>& shapes) {
  covered_.assign(cells_.size(), -1);
  size_t edges = 0;
  for (const auto& list : cells_)
    for (const uint32_t i : list)
      edges += std::min(shapes[i].polygon.size(), kClassifiedPolygon + 1);
  if (edges > kClassifiedEdges) return;
  // Each cell as top_shape_at reads it: the points whose floor((x - x0) /
  // cell) is the cell, and on the grid's border the cell of slack it clamps
  // in, grown by a margin far beyond the rounding of that lookup.
  const double cell_w = 1 / inv_cell_w_, cell_h = 1 / inv_cell_h_;
  const double margin = 1e-6 * std::max(cell_w, cell_h) +
                        1e-9 * (std::abs(x0_) + std::abs(y0_) + cols_ * cell_w + rows_ * cell_h);
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < cols_; ++c) {
      const Box box{x0_ + (c - (c == 0)) * cell_w - margin, y0_ + (r - (r == 0)) * cell_h - margin,
                    x0_ + (c + 1 + (c == cols_ - 1)) * cell_w + margin,
                    y0_ + (r + 1 + (r == rows_ - 1)) * cell_h + margin};
      const size_t at = static_cast<size_t>(r) * cols_ + c;
      std::vector<uint32_t>& list = cells_[at];
      // From the top shape down: one that holds the whole cell answers for
      // every point the shapes above it miss, and those below never matter;
      // one that misses the whole cell is never tested.
      std::vector<uint32_t> kept;
      for (size_t k = list.size(); k-- > 0;) {
        const Shape& s = shapes[list[k]];
        const Cover how = s.polygon.size() > kClassifiedPolygon ? Cover::partly : cover(s, box);
        if (how == Cover::inside) {
          covered_[at] = static_cast<int>(list[k]);
          break;
        }
        if (how == Cover::partly) kept.push_back(list[k]);
      }
      list.assign(kept.rbegin(), kept.rend());  // painting order again
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
  const size_t at = static_cast<size_t>(r) * cols_ + c;
  const auto& list = cells_[at];
  for (auto it = list.rbegin(); it != list.rend(); ++it)
    if (contains(shapes[*it], *it, p)) return static_cast<int>(*it);
  return covered_[at];
}

}  // namespace aapat
