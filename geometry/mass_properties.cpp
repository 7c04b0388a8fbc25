// Volume, centroid and inertia of a polyhedron by the divergence theorem.
//
// The solid is split into tetrahedra (r, v0, vi, vi+1): one per fan triangle
// of each face, all sharing the reference point r. Signed volumes make the
// pieces outside the solid cancel, so r need not be inside; it is the mean of
// the vertices only to keep the numbers small. For a tetrahedron with corners
// 0, a, b, c (relative to r) and D = a·(b×c):
//   V         = D / 6
//   ∫ x dV    = V (a + b + c) / 4
//   ∫ x xᵀ dV = D/120 (a aᵀ + b bᵀ + c cᵀ + s sᵀ),  s = a + b + c
// which are exact for polynomials of these degrees, so the result is exact
// up to round-off for any closed polyhedron with planar faces.
#include "geometry/polyhedron.hpp"

namespace polydem {

MassProperties mass_properties(const Polyhedron& p) {
  Vec3 r = Vec3::Zero();
  for (const auto& v : p.vertices) r += v;
  if (!p.vertices.empty()) r /= static_cast<double>(p.vertices.size());

  double volume = 0;
  Vec3 first = Vec3::Zero();   // ∫ x dV about r
  Mat3 second = Mat3::Zero();  // ∫ x xᵀ dV about r
  for (const auto& loop : p.faces) {
    const Vec3 a = p.vertices[loop[0]] - r;
    for (size_t i = 1; i + 1 < loop.size(); ++i) {
      const Vec3 b = p.vertices[loop[i]] - r, c = p.vertices[loop[i + 1]] - r;
      const double det = a.dot(b.cross(c));
      const Vec3 s = a + b + c;
      volume += det / 6.0;
      first += det / 24.0 * s;
      second += det / 120.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }

  MassProperties m;
  m.volume = volume;
  if (volume == 0) return m;  // degenerate: validate() rejects such shapes
  const Vec3 g = first / volume;
  const Mat3 cov = second - volume * g * g.transpose();  // parallel-axis shift to the centroid
  m.centroid = r + g;
  m.inertia = cov.trace() * Mat3::Identity() - cov;
  return m;
}

}  // namespace polydem
