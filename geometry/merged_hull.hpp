// Internal to geometry/: the convex hull as polygons, before it becomes a
// Polyhedron. Shared by convex_hull() and halfspace_intersection(), which
// hulls the dual points. No CGAL here (see polyhedron.hpp).
#pragma once

#include <vector>

#include "geometry/polyhedron.hpp"

namespace polydem {

struct HullPolygons {
  std::vector<Vec3> vertices;            // hull corners only (a subset of the input points)
  std::vector<std::vector<int>> faces;   // CCW from outside, coplanar facets merged
};

// Hull facets whose corners lie within merge_rel_tol * (bounding-box diagonal)
// of a common plane become one polygon; points that end up inside a face or
// along an edge are dropped. Throws GeometryError for fewer than four points
// or (nearly) coplanar points.
HullPolygons merged_hull(const std::vector<Vec3>& points, double merge_rel_tol = 2.5e-10);

}  // namespace polydem
