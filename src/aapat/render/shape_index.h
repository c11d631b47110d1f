// A spatial index over a scene file's shapes, so that the grey level at a
// point looks at the few shapes near it instead of all of them: a uniform
// grid over the shapes' bounding boxes (each cell lists the shapes whose box
// overlaps it, in painting order, less those that miss the whole cell and
// those under a shape that holds the whole cell), and for long polygons
// their edges binned in horizontal bands. Answers exactly what the plain
// scan answers.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

struct Shape;

class ShapeIndex {
 public:
  explicit ShapeIndex(const std::vector<Shape>& shapes);
  // The last shape in painting order that contains p, or -1.
  int top_shape_at(const std::vector<Shape>& shapes, Vec2 p) const;

 private:
  struct Bands {  // a polygon's edges by the horizontal band their y range touches
    double y0 = 0, inv_height = 0;
    std::vector<std::vector<uint32_t>> edges;  // edge i runs from vertex i-1 to vertex i
  };
  bool contains(const Shape& s, size_t index, Vec2 p) const;
  // Drops from each cell's list the shapes that miss the whole cell and
  // those under one that holds it (covered_).
  void classify_cells(const std::vector<Shape>& shapes);

  double x0_ = 0, y0_ = 0, inv_cell_w_ = 0, inv_cell_h_ = 0;
  int cols_ = 0, rows_ = 0;
  std::vector<std::vector<uint32_t>> cells_;  // shapes that may hold part of the cell
  std::vector<int> covered_;                  // per cell, the top shape that holds all of it, or -1
  std::vector<Bands> bands_;                  // per shape; empty for circles and short polygons
};

// Even-odd rule: a ray to +x crosses the boundary an odd number of times.
bool in_polygon(Vec2 p, const std::vector<Vec2>& poly);

}  // namespace aapat
