// Cutting convex blocks by planes (geometry/cut.hpp has the conventions).
// The pieces' faces come from CGAL's hull of their corners (convex_hull(),
// exact predicates); this file only decides which corners each piece has.
#include "geometry/cut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace polydem {

namespace {

// Relative to the block's bounding-box diagonal: a corner this close to the
// plane is on it; one closer than kNeedle but not on it is an error.
constexpr double kOnPlane = 1e-12;
constexpr double kNeedle = 1e-7;

// sin and cos of an angle in degrees, exact at multiples of 90°.
void sin_cos_degrees(double deg, double& s, double& c) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360.0;
  if (r == 0.0) { s = 0; c = 1; return; }
  if (r == 90.0) { s = 1; c = 0; return; }
  if (r == 180.0) { s = 0; c = -1; return; }
  if (r == 270.0) { s = -1; c = 0; return; }
  const double a = r * std::numbers::pi / 180.0;
  s = std::sin(a);
  c = std::cos(a);
}

// The point where the plane n·x = d crosses the edge from `lo` (below) to
// `hi` (above), put on the plane exactly in the normal's largest coordinate.
Vec3 crossing(const Vec3& lo, const Vec3& hi, double s_lo, double s_hi, const Vec3& n, double d) {
  const double t = s_lo / (s_lo - s_hi);  // s_lo < 0 < s_hi: t in (0, 1)
  Vec3 x = lo + t * (hi - lo);
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) > std::abs(n[k])) k = i;
  double rest = d;
  for (int i = 0; i < 3; ++i)
    if (i != k) rest -= n[i] * x[i];
  x[k] = rest / n[k];
  return x;
}

}  // namespace

Vec3 joint_set_normal(double dip_degrees, double dip_direction_degrees) {
  double sd = 0, cd = 0, sa = 0, ca = 0;
  sin_cos_degrees(dip_degrees, sd, cd);
  sin_cos_degrees(dip_direction_degrees, sa, ca);
  return {sd * sa, sd * ca, cd};
}

PlaneReach plane_reach(const Polyhedron& p, const Vec3& n, double d) {
  PlaneReach r;
  for (const Vec3& v : p.vertices) {
    const double s = n.dot(v) - d;
    r.below = std::max(r.below, -s);
    r.above = std::max(r.above, s);
  }
  return r;
}

PlanePieces split_by_plane(const Polyhedron& p, const Vec3& n, double d) {
  const double size = bounding_box_diagonal(p.vertices);
  const double on = kOnPlane * size, needle = kNeedle * size;
  const std::size_t nv = p.vertices.size();
  std::vector<double> s(nv);
  std::vector<int> side(nv);
  bool any_below = false, any_above = false;
  for (std::size_t v = 0; v < nv; ++v) {
    s[v] = n.dot(p.vertices[v]) - d;
    side[v] = std::abs(s[v]) <= on ? 0 : (s[v] < 0 ? -1 : 1);
    any_below = any_below || side[v] < 0;
    any_above = any_above || side[v] > 0;
  }
  if (!any_below || !any_above) throw GeometryError("split_by_plane: the plane does not cross the block");
  for (std::size_t v = 0; v < nv; ++v) {
    if (side[v] != 0 && std::abs(s[v]) <= needle) {
      std::ostringstream m;
      m << "the plane passes " << std::abs(s[v]) << " m from corner " << v << " of the block (closer than "
        << kNeedle << " of its size without going through it: the pieces would have needle-thin faces); "
        << "move the plane";
      throw GeometryError(m.str());
    }
  }
  std::vector<Vec3> below, above;
  for (std::size_t v = 0; v < nv; ++v) {
    if (side[v] <= 0) below.push_back(p.vertices[v]);
    if (side[v] >= 0) above.push_back(p.vertices[v]);
  }
  for (const auto& e : p.edges) {
    const int a = e[0], b = e[1];
    if (side[a] * side[b] >= 0) continue;
    const int lo = side[a] < 0 ? a : b, hi = side[a] < 0 ? b : a;
    const Vec3 x = crossing(p.vertices[lo], p.vertices[hi], s[lo], s[hi], n, d);
    below.push_back(x);
    above.push_back(x);
  }
  return {convex_hull(below), convex_hull(above)};
}

double joint_plane_offset(const JointSet& set, int k) {
  return set.normal.dot(set.origin) + static_cast<double>(k) * set.spacing;
}

std::vector<Polyhedron> cut_by_joint_set(const Polyhedron& p, const JointSet& set) {
  std::vector<Polyhedron> pieces{p};
  const double on = kOnPlane * bounding_box_diagonal(p.vertices);
  const double thin = std::max(set.min_thickness, on);
  for (int k = 0; k < set.count; ++k) {
    const double d = joint_plane_offset(set, k);
    std::vector<Polyhedron> next;
    for (Polyhedron& piece : pieces) {
      const PlaneReach r = plane_reach(piece, set.normal, d);
      if (r.below <= thin || r.above <= thin) {
        next.push_back(std::move(piece));
        continue;
      }
      PlanePieces two = split_by_plane(piece, set.normal, d);
      next.push_back(std::move(two.below));
      next.push_back(std::move(two.above));
    }
    pieces = std::move(next);
  }
  return pieces;
}

double penetration_depth(const Polyhedron& a, const Polyhedron& b, Vec3* axis) {
  double best = std::numeric_limits<double>::infinity();
  Vec3 best_axis = Vec3::UnitZ();
  const auto test = [&](const Vec3& u) {
    double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
    for (const Vec3& v : a.vertices) {
      const double x = u.dot(v);
      a0 = std::min(a0, x);
      a1 = std::max(a1, x);
    }
    for (const Vec3& v : b.vertices) {
      const double x = u.dot(v);
      b0 = std::min(b0, x);
      b1 = std::max(b1, x);
    }
    const double overlap = std::min(a1 - b0, b1 - a0);
    if (overlap < best) {
      best = overlap;
      best_axis = u;
    }
  };
  for (const Vec3& u : a.normals) test(u);
  for (const Vec3& u : b.normals) test(u);
  for (const auto& ea : a.edges) {
    const Vec3 da = a.vertices[ea[1]] - a.vertices[ea[0]];
    for (const auto& eb : b.edges) {
      const Vec3 db = b.vertices[eb[1]] - b.vertices[eb[0]];
      const Vec3 c = da.cross(db);
      const double len = c.norm();
      if (!(len > 1e-9 * da.norm() * db.norm())) continue;  // parallel edges: covered by the face normals
      test(c / len);
      if (best <= 0) break;
    }
    if (best <= 0) break;
  }
  if (axis) *axis = best_axis;
  return best;
}

std::optional<double> overlap_volume(const Polyhedron& a, const Polyhedron& b) {
  Polyhedron cur = a;
  const double on = kOnPlane * bounding_box_diagonal(a.vertices);
  for (std::size_t f = 0; f < b.normals.size(); ++f) {
    const PlaneReach r = plane_reach(cur, b.normals[f], b.offsets[f]);
    if (r.below <= on) return 0.0;  // a lies in front of this face of b
    if (r.above <= on) continue;    // wholly behind it
    try {
      cur = split_by_plane(cur, b.normals[f], b.offsets[f]).below;
    } catch (const GeometryError&) {
      return std::nullopt;
    }
  }
  return mass_properties(cur).volume;
}

}  // namespace polydem
