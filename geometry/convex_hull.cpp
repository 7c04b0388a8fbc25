// Convex hull of a point set with CGAL, turned into polygonal faces.
//
// CGAL::convex_hull_3 (exact predicates, so the hull is combinatorially right
// even for exactly coplanar input such as the corners of a box) returns a
// triangulated surface. A block face must be one polygon, so triangles lying
// in a common plane are grown into regions: seeds are taken largest first
// (their normals are the most accurate) and a neighbour joins when all its
// corners lie within the merge tolerance of the seed's plane and it faces the
// same way. The boundary of each region is its polygon. Hull points that end
// up in fewer than three polygons lie inside a face or along an edge and are
// not corners, so they are dropped.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <numeric>
#include <string>

#include "geometry/merged_hull.hpp"

namespace polydem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

struct Triangle {
  std::array<int, 3> v;   // corners, CCW from outside; edge k runs v[k] -> v[k+1]
  std::array<int, 3> nb;  // triangle across edge k
  Vec3 normal;            // unit, outward
  double area;
};

Vec3 to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Exact test first: the common degenerate inputs (all points in a plane or on
// a line) must be rejected before CGAL is asked for a 3D hull.
void require_spanning(const std::vector<Point>& pts) {
  size_t i1 = 1;
  while (i1 < pts.size() && pts[i1] == pts[0]) ++i1;
  if (i1 == pts.size()) throw GeometryError("convex hull: all points coincide");
  size_t i2 = i1 + 1;
  while (i2 < pts.size() && CGAL::collinear(pts[0], pts[i1], pts[i2])) ++i2;
  if (i2 == pts.size()) throw GeometryError("convex hull: all points are collinear");
  size_t i3 = i2 + 1;
  while (i3 < pts.size() && CGAL::coplanar(pts[0], pts[i1], pts[i2], pts[i3])) ++i3;
  if (i3 == pts.size()) throw GeometryError("convex hull: all points are coplanar");
}

std::vector<Triangle> hull_triangles(const std::vector<Point>& pts, std::vector<Vec3>& corners) {
  Mesh mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  if (mesh.has_garbage()) mesh.collect_garbage();  // so that idx() is a dense 0..n-1 numbering
  corners.clear();
  for (auto v : mesh.vertices()) corners.push_back(to_vec(mesh.point(v)));
  std::vector<Triangle> tris(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    Triangle& t = tris[f.idx()];
    auto h = mesh.halfedge(f);
    for (int k = 0; k < 3; ++k, h = mesh.next(h)) {
      if (k > 0 && h == mesh.halfedge(f)) throw GeometryError("convex hull: CGAL returned a non-triangular facet");
      t.v[k] = static_cast<int>(mesh.source(h).idx());
      t.nb[k] = static_cast<int>(mesh.face(mesh.opposite(h)).idx());
    }
    const Vec3 c = (corners[t.v[1]] - corners[t.v[0]]).cross(corners[t.v[2]] - corners[t.v[0]]);
    t.area = 0.5 * c.norm();
    t.normal = t.area > 0 ? Vec3(c.normalized()) : Vec3::Zero();
  }
  return tris;
}

// Region growing: returns the region id of every triangle.
std::vector<int> coplanar_regions(const std::vector<Triangle>& tris, const std::vector<Vec3>& corners, double tol,
                                  int& n_regions) {
  std::vector<int> order(tris.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return tris[a].area > tris[b].area; });
  std::vector<int> region(tris.size(), -1);
  n_regions = 0;
  for (int seed : order) {
    if (region[seed] >= 0) continue;
    const int r = n_regions++;
    const Vec3 n = tris[seed].normal;
    const double d = n.dot(corners[tris[seed].v[0]]);
    std::vector<int> stack{seed};
    region[seed] = r;
    while (!stack.empty()) {
      const Triangle& t = tris[stack.back()];
      stack.pop_back();
      for (int nb : t.nb) {
        if (region[nb] >= 0 || tris[nb].normal.dot(n) <= 0) continue;
        bool in_plane = true;
        for (int v : tris[nb].v) in_plane = in_plane && std::abs(n.dot(corners[v]) - d) <= tol;
        if (!in_plane) continue;
        region[nb] = r;
        stack.push_back(nb);
      }
    }
  }
  return region;
}

// The boundary of one region, walked as a loop (CCW from outside, like the
// triangles it came from).
std::vector<int> region_boundary(const std::vector<Triangle>& tris, const std::vector<int>& region, int r) {
  std::map<int, int> next;  // boundary edge source -> target
  for (size_t i = 0; i < tris.size(); ++i) {
    if (region[i] != r) continue;
    for (int k = 0; k < 3; ++k)
      if (region[tris[i].nb[k]] != r)
        if (!next.emplace(tris[i].v[k], tris[i].v[(k + 1) % 3]).second)
          throw GeometryError("convex hull: merged face " + std::to_string(r) + " touches itself at a vertex");
  }
  if (next.empty()) throw GeometryError("convex hull: merged face " + std::to_string(r) + " has no boundary");
  std::vector<int> loop{next.begin()->first};
  while (true) {
    const auto it = next.find(loop.back());
    if (it == next.end()) throw GeometryError("convex hull: merged face " + std::to_string(r) + " is not closed");
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
    if (loop.size() > next.size()) break;
  }
  if (loop.size() != next.size())
    throw GeometryError("convex hull: merged face " + std::to_string(r) + " is not a single polygon");
  return loop;
}

}  // namespace

HullPolygons merged_hull(const std::vector<Vec3>& points, double merge_rel_tol) {
  if (points.size() < 4)
    throw GeometryError("convex hull: " + std::to_string(points.size()) + " points (need at least 4)");
  std::vector<Point> pts;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) throw GeometryError("convex hull: point " + std::to_string(i) + " is not finite");
    pts.emplace_back(points[i].x(), points[i].y(), points[i].z());
  }
  require_spanning(pts);

  std::vector<Vec3> corners;
  const std::vector<Triangle> tris = hull_triangles(pts, corners);
  const double tol = merge_rel_tol * bounding_box_diagonal(corners);
  int n_regions = 0;
  const std::vector<int> region = coplanar_regions(tris, corners, tol, n_regions);
  if (n_regions < 4) throw GeometryError("convex hull: the points are nearly coplanar (flat hull)");

  std::vector<std::vector<int>> loops;
  std::vector<int> n_faces_at(corners.size(), 0);
  for (int r = 0; r < n_regions; ++r) {
    loops.push_back(region_boundary(tris, region, r));
    for (int v : loops.back()) ++n_faces_at[v];
  }

  // Keep the true corners, numbered in a canonical order: CGAL's hull lists
  // its vertices in an order that depends on heap addresses (it keeps a
  // std::map keyed by vertex handles), so the same points built twice in
  // one process (a study, a Python script) came out numbered differently,
  // and a block's vertex and face order feed every sum of the contact
  // search. Corners are input points, exact copies, so sorting them by
  // (x, y, z) and the faces by their id sequence numbers the same hull the
  // same way every time.
  std::vector<int> kept;
  for (size_t v = 0; v < corners.size(); ++v)
    if (n_faces_at[v] >= 3) kept.push_back(static_cast<int>(v));
  std::sort(kept.begin(), kept.end(), [&](int a, int b) {
    const Vec3 &p = corners[a], &q = corners[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;  // a repeated point: both are kept as CGAL gave them
  });
  HullPolygons out;
  std::vector<int> new_id(corners.size(), -1);
  for (int v : kept) {
    new_id[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(corners[v]);
  }
  for (const auto& loop : loops) {
    std::vector<int> face;
    for (int v : loop)
      if (new_id[v] >= 0) face.push_back(new_id[v]);
    if (face.size() < 3) throw GeometryError("convex hull: a merged face has fewer than 3 corners");
    // Start each loop at its smallest vertex id (the orientation kept).
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    out.faces.push_back(std::move(face));
  }
  std::sort(out.faces.begin(), out.faces.end());
  return out;
}

Polyhedron convex_hull(const std::vector<Vec3>& points) {
  HullPolygons h = merged_hull(points);
  return make_polyhedron(std::move(h.vertices), std::move(h.faces));
}

}  // namespace polydem
