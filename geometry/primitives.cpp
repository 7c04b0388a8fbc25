// Simple block shapes built directly from their faces (no hull needed).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "geometry/polyhedron.hpp"

namespace polydem {

Polyhedron make_box(const Vec3& size, const Vec3& center) {
  if (!(size.minCoeff() > 0) || !size.allFinite() || !center.allFinite()) {
    std::ostringstream m;
    m << "make_box: size (" << size.transpose() << ") must be positive and finite";
    throw GeometryError(m.str());
  }
  const Vec3 h = 0.5 * size;
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i)  // bit 0: x, bit 1: y, bit 2: z (set = + side)
    v.push_back(center + Vec3((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
  // Each loop is counter-clockwise seen from outside.
  std::vector<std::vector<int>> faces = {
      {0, 4, 6, 2},  // -x
      {1, 3, 7, 5},  // +x
      {0, 1, 5, 4},  // -y
      {2, 6, 7, 3},  // +y
      {0, 2, 3, 1},  // -z
      {4, 5, 7, 6},  // +z
  };
  return make_polyhedron(std::move(v), std::move(faces));
}

Polyhedron make_prism(const std::vector<Vec2>& polygon, double z0, double z1) {
  auto fail = [](const std::string& what) { throw GeometryError("make_prism: " + what); };
  const int n = static_cast<int>(polygon.size());
  if (n < 3) fail("polygon has " + std::to_string(n) + " points (need at least 3)");
  if (!std::isfinite(z0) || !std::isfinite(z1) || !(z1 > z0)) fail("need z1 > z0 (both finite)");
  for (const auto& q : polygon)
    if (!q.allFinite()) fail("polygon has a non-finite point");

  Vec2 lo = polygon[0], hi = polygon[0];
  for (const auto& q : polygon) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const double tol = 1e-9 * (hi - lo).norm();

  // Shoelace sign tells the orientation; reverse clockwise input.
  double twice_area = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % n];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  std::vector<Vec2> poly = polygon;
  if (twice_area < 0) std::reverse(poly.begin(), poly.end());

  for (int i = 0; i < n; ++i)
    if ((polygon[(i + 1) % n] - polygon[i]).norm() <= tol)
      fail("repeated point: points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide");

  // Convex and simple: every corner turns left, and the turns add up to one
  // full revolution (a pentagram turns left everywhere but winds twice).
  double turning = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 e0 = poly[(i + 1) % n] - poly[i];
    const Vec2 e1 = poly[(i + 2) % n] - poly[(i + 1) % n];
    const std::string corner = "point " + std::to_string(twice_area < 0 ? n - 1 - (i + 1) % n : (i + 1) % n);
    const double cross = e0.x() * e1.y() - e0.y() * e1.x();
    if (std::abs(cross) <= tol * (e0.norm() + e1.norm()))
      fail("collinear points at " + corner + " (remove it: it is not a corner)");
    if (cross < 0) fail("polygon is not convex at " + corner);
    turning += std::atan2(cross, e0.dot(e1));
  }
  if (std::abs(turning - 2 * std::numbers::pi) > 1e-6) fail("polygon is self-intersecting (winds more than once)");

  std::vector<Vec3> v;
  for (const auto& q : poly) v.emplace_back(q.x(), q.y(), z0);
  for (const auto& q : poly) v.emplace_back(q.x(), q.y(), z1);
  std::vector<std::vector<int>> faces;
  std::vector<int> bottom, top;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);  // seen from below: clockwise in xy
  for (int i = 0; i < n; ++i) top.push_back(n + i);
  faces.push_back(bottom);
  faces.push_back(top);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    faces.push_back({i, j, n + j, n + i});  // outward normal lies to the right of the edge i->j
  }
  return make_polyhedron(std::move(v), std::move(faces));
}

}  // namespace polydem
