// The checks every Polyhedron passes before any later stage sees it.
//
// Order matters for the messages: structure first (so that later checks can
// index safely), then closure and orientation, then the metric checks. All
// lengths are compared against tol = rel_tol * bounding-box diagonal, areas
// against tol * diagonal and volumes against tol * diagonal², so the answer
// does not depend on the units of the model.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "geometry/polyhedron.hpp"

namespace polydem {

namespace {

// Called as fail(m << "what" << index): operator<< hands back the ostream
// base of the ostringstream m, hence the cast.
[[noreturn]] void fail(const std::ostream& msg) {
  throw GeometryError("invalid polyhedron: " + static_cast<const std::ostringstream&>(msg).str());
}

void check_structure(const Polyhedron& p) {
  std::ostringstream m;
  const int nv = static_cast<int>(p.vertices.size());
  const int nf = static_cast<int>(p.faces.size());
  if (nv < 4) fail(m << "has " << nv << " vertices (need at least 4)");
  if (nf < 4) fail(m << "has " << nf << " faces (need at least 4)");
  if (p.normals.size() != p.faces.size() || p.offsets.size() != p.faces.size())
    fail(m << "normals/offsets do not match the " << nf << " faces (build it with make_polyhedron)");
  for (int i = 0; i < nv; ++i)
    if (!p.vertices[i].allFinite()) fail(m << "vertex " << i << " is not finite");
  for (int f = 0; f < nf; ++f) {
    const auto& loop = p.faces[f];
    if (loop.size() < 3) fail(m << "face " << f << " has " << loop.size() << " vertices (need at least 3)");
    for (size_t k = 0; k < loop.size(); ++k) {
      if (loop[k] < 0 || loop[k] >= nv) fail(m << "face " << f << " refers to missing vertex " << loop[k]);
      for (size_t l = 0; l < k; ++l)
        if (loop[l] == loop[k]) fail(m << "face " << f << " visits vertex " << loop[k] << " twice");
    }
  }
}

void check_duplicate_vertices(const Polyhedron& p, double tol) {
  std::ostringstream m;
  for (size_t i = 0; i < p.vertices.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if ((p.vertices[i] - p.vertices[j]).norm() <= tol)
        fail(m << "vertices " << j << " and " << i << " coincide (duplicate vertex)");
}

// Closed and consistently oriented: every directed edge a->b is used by
// exactly one face and its reverse b->a by exactly one other face.
void check_closure(const Polyhedron& p) {
  std::ostringstream m;
  std::map<std::pair<int, int>, int> owner;  // directed edge -> face (ordered: deterministic messages)
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& loop = p.faces[f];
    for (size_t k = 0; k < loop.size(); ++k) {
      const std::pair<int, int> e{loop[k], loop[(k + 1) % loop.size()]};
      const auto [it, inserted] = owner.emplace(e, f);
      if (!inserted)
        fail(m << "edge " << e.first << "->" << e.second << " is used in the same direction by faces " << it->second
               << " and " << f << " (flipped face or non-manifold edge)");
    }
  }
  for (const auto& [e, f] : owner)
    if (!owner.count({e.second, e.first}))
      fail(m << "edge " << e.first << "-" << e.second << " of face " << f
             << " has no neighbouring face (the surface is open)");

  std::vector<char> used(p.vertices.size(), 0);
  std::vector<std::array<int, 2>> edges;
  for (const auto& [e, f] : owner) {
    used[e.first] = 1;
    if (e.first < e.second) edges.push_back({e.first, e.second});
  }
  for (size_t i = 0; i < used.size(); ++i)
    if (!used[i]) fail(m << "vertex " << i << " is not used by any face");
  if (edges != p.edges) fail(m << "edge list does not match the faces (build it with make_polyhedron)");
}

void check_faces(const Polyhedron& p, double tol, double diag) {
  std::ostringstream m;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const Vec3 a = face_vector_area(p, f);
    if (a.norm() <= tol * diag) fail(m << "face " << f << " has zero area (degenerate face)");
    const Vec3& n = p.normals[f];
    if (std::abs(n.norm() - 1) > 1e-9 || n.dot(a) <= 0)
      fail(m << "face " << f << " normal is not the outward unit normal of its vertex loop");
    for (int v : p.faces[f]) {
      const double off = n.dot(p.vertices[v]) - p.offsets[f];
      if (std::abs(off) > tol)
        fail(m << "face " << f << " is not planar: vertex " << v << " is " << off << " off its plane");
    }
  }
}

void check_volume(const Polyhedron& p, double tol, double diag) {
  std::ostringstream m;
  const double v = mass_properties(p).volume;
  if (v < -tol * diag * diag) fail(m << "volume " << v << " is negative (faces are oriented inward)");
  if (v <= tol * diag * diag) fail(m << "volume " << v << " is not positive (flat or degenerate shape)");
}

void check_convexity(const Polyhedron& p, double tol) {
  std::ostringstream m;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f)
    for (int v = 0; v < static_cast<int>(p.vertices.size()); ++v) {
      const double out = p.normals[f].dot(p.vertices[v]) - p.offsets[f];
      if (out > tol) fail(m << "not convex: vertex " << v << " lies " << out << " in front of the plane of face " << f);
    }
}

// Two faces sharing an edge in one plane are one face cut in two; later
// stages assume faces are maximal (a face-face contact is one patch), so the
// caller must merge them. The tolerance is tighter than for planarity so that
// faces merged by convex_hull() are never flagged here.
void check_coplanar_neighbours(const Polyhedron& p, double tol) {
  std::ostringstream m;
  std::map<std::pair<int, int>, int> owner;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& loop = p.faces[f];
    for (size_t k = 0; k < loop.size(); ++k) owner[{loop[k], loop[(k + 1) % loop.size()]}] = f;
  }
  for (const auto& [e, f] : owner) {
    const int g = owner.at({e.second, e.first});
    if (g <= f) continue;
    bool coplanar = p.normals[f].dot(p.normals[g]) > 0;
    for (int v : p.faces[g]) coplanar = coplanar && std::abs(p.normals[f].dot(p.vertices[v]) - p.offsets[f]) <= tol;
    if (coplanar) fail(m << "faces " << f << " and " << g << " are coplanar neighbours (merge them into one face)");
  }
}

}  // namespace

void validate(const Polyhedron& p, double rel_tol) {
  check_structure(p);
  const double diag = bounding_box_diagonal(p.vertices);
  const double tol = rel_tol * diag;
  check_duplicate_vertices(p, tol);
  check_closure(p);
  check_faces(p, tol, diag);
  check_volume(p, tol, diag);
  check_convexity(p, tol);
  check_coplanar_neighbours(p, 0.1 * tol);
}

}  // namespace polydem
