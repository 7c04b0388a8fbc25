// Building a Polyhedron from vertices and face loops, and moving it rigidly.
#include "geometry/polyhedron.hpp"

#include <map>

#include <algorithm>
#include <string>

namespace polydem {

Polyhedron make_polyhedron(std::vector<Vec3> vertices, std::vector<std::vector<int>> faces) {
  // Index errors must be caught before anything dereferences them; the
  // geometric checks are left to validate().
  const int nv = static_cast<int>(vertices.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3)
      throw GeometryError("face " + std::to_string(f) + " has " + std::to_string(faces[f].size()) +
                          " vertices (need at least 3)");
    for (int i : faces[f])
      if (i < 0 || i >= nv)
        throw GeometryError("face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
                            ", but there are only " + std::to_string(nv) + " vertices");
  }
  for (int i = 0; i < nv; ++i)
    if (!vertices[i].allFinite()) throw GeometryError("vertex " + std::to_string(i) + " is not finite");

  Polyhedron p;
  p.vertices = std::move(vertices);
  p.faces = std::move(faces);
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& loop = p.faces[f];
    // The area-weighted (Newell) normal rather than one corner's cross
    // product: it stays meaningful when a corner is nearly straight.
    Vec3 n = face_vector_area(p, f);
    const double len = n.norm();
    n = len > 0 ? Vec3(n / len) : Vec3::Zero();  // zero normal: validate() reports the degenerate face
    double d = 0;
    for (int i : loop) d += n.dot(p.vertices[i]);  // mean over the loop: a best fit for slightly warped faces
    p.normals.push_back(n);
    p.offsets.push_back(d / static_cast<double>(loop.size()));
  }
  for (const auto& loop : p.faces)
    for (size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      p.edges.push_back({std::min(a, b), std::max(a, b)});
    }
  // Sorted, so that edge ids (and any contact keys built on them) do not
  // depend on the order faces happened to be listed in.
  std::sort(p.edges.begin(), p.edges.end());
  p.edges.erase(std::unique(p.edges.begin(), p.edges.end()), p.edges.end());
  // Each directed edge a → b of a face meets b → a in its neighbour.
  std::map<std::pair<int, int>, int> face_of;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& loop = p.faces[f];
    for (std::size_t i = 0; i < loop.size(); ++i) face_of[{loop[i], loop[(i + 1) % loop.size()]}] = f;
  }
  p.neighbours.resize(p.faces.size());
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const auto& loop = p.faces[f];
    p.neighbours[f].assign(loop.size(), -1);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto it = face_of.find({loop[(i + 1) % loop.size()], loop[i]});
      if (it != face_of.end()) p.neighbours[f][i] = it->second;
    }
  }
  validate(p);
  return p;
}

Polyhedron transformed(const Polyhedron& p, const Mat3& R, const Vec3& t) {
  Polyhedron q = p;
  for (auto& v : q.vertices) v = R * v + t;
  for (size_t f = 0; f < q.normals.size(); ++f) {
    q.normals[f] = R * p.normals[f];
    q.offsets[f] = p.offsets[f] + q.normals[f].dot(t);  // n'·(R x + t) = n·x + n'·t
  }
  return q;
}

}  // namespace polydem
