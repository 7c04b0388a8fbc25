// Areas and moments of faces, and simple size measures of a polyhedron.
//
// Every face integral is a sum over the fan triangles (v0, vi, vi+1), taken
// relative to v0 so that blocks far from the origin keep their precision.
// Faces are convex, so the fan covers each face exactly once.
#include "geometry/polyhedron.hpp"

#include <algorithm>
#include <cmath>

namespace polydem {

Vec3 face_vector_area(const Polyhedron& p, int face) {
  const auto& loop = p.faces[face];
  const Vec3& o = p.vertices[loop[0]];
  Vec3 a = Vec3::Zero();
  for (size_t i = 1; i + 1 < loop.size(); ++i) a += (p.vertices[loop[i]] - o).cross(p.vertices[loop[i + 1]] - o);
  return 0.5 * a;
}

double face_area(const Polyhedron& p, int face) { return face_vector_area(p, face).norm(); }

Vec3 face_centroid(const Polyhedron& p, int face) {
  const auto& loop = p.faces[face];
  const Vec3& o = p.vertices[loop[0]];
  const Vec3& n = p.normals[face];
  double area = 0;
  Vec3 moment = Vec3::Zero();
  for (size_t i = 1; i + 1 < loop.size(); ++i) {
    const Vec3 a = p.vertices[loop[i]] - o, b = p.vertices[loop[i + 1]] - o;
    const double t = 0.5 * n.dot(a.cross(b));
    area += t;
    moment += t * (a + b) / 3.0;  // triangle centroid relative to o is (0 + a + b) / 3
  }
  return o + moment / area;
}

double surface_area(const Polyhedron& p) {
  double s = 0;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) s += face_area(p, f);
  return s;
}

double face_polar_moment(const Polyhedron& p, int face, const Vec3& c) {
  // Over a triangle with corners p0, p1, p2 (relative to c):
  //   ∫ |x|² dA = A/12 (|p0|² + |p1|² + |p2|² + |p0 + p1 + p2|²),
  // exact because the integrand is quadratic.
  const auto& loop = p.faces[face];
  const Vec3 o = p.vertices[loop[0]] - c;
  double j = 0;
  for (size_t i = 1; i + 1 < loop.size(); ++i) {
    const Vec3 a = p.vertices[loop[i]] - c, b = p.vertices[loop[i + 1]] - c;
    const double area = 0.5 * (a - o).cross(b - o).norm();
    j += area / 12.0 * (o.squaredNorm() + a.squaredNorm() + b.squaredNorm() + (o + a + b).squaredNorm());
  }
  return j;
}

double bounding_radius(const Polyhedron& p, const Vec3& c) {
  double r2 = 0;
  for (const auto& v : p.vertices) r2 = std::max(r2, (v - c).squaredNorm());
  return std::sqrt(r2);
}

double bounding_box_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0;
  Vec3 lo = points[0], hi = points[0];
  for (const auto& v : points) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

}  // namespace polydem
