// Convex polyhedra: the shape of one block (a stone, a base, the solid tip).
//
// Plain data plus free functions. Faces are vertex index loops, counter-
// clockwise seen from outside, so the right-hand normal points outward. Every
// Polyhedron that leaves make_polyhedron() has been validated (closed,
// convex, planar faces, positive volume); later stages rely on that.
// No CGAL in this header: CGAL is slow to compile and stays in geometry/*.cpp.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace polydem {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// The cross-product matrix [r]×: [r]×·v = r × v.
inline Mat3 cross_matrix(const Vec3& r) {
  Mat3 m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

// Invalid geometry (open, non-convex, degenerate, ...). The message says what
// is wrong and where (face/vertex index).
struct GeometryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Polyhedron {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;  // CCW from outside
  std::vector<Vec3> normals;            // outward unit normal per face
  std::vector<double> offsets;          // face plane: normals[f]·x = offsets[f]
  std::vector<std::array<int, 2>> edges;  // unique undirected edges, [0] < [1]
  // Per face, per edge of its loop (faces[f][i] → faces[f][i+1]): the face
  // across that edge.
  std::vector<std::vector<int>> neighbours;
};

// Builds normals, offsets and edges, then validates. Throws GeometryError.
// Coplanar neighbouring faces are allowed in input only if merged by caller.
Polyhedron make_polyhedron(std::vector<Vec3> vertices, std::vector<std::vector<int>> faces);

// Checks closure (every edge shared by exactly two faces with opposite
// orientation), planarity of faces, convexity (every vertex on or behind every
// face plane) and positive volume. Tolerances are relative to the size of the
// polyhedron (rel_tol times its bounding-box diagonal). Throws GeometryError.
void validate(const Polyhedron& p, double rel_tol = 1e-9);

// Volume, centroid and inertia tensor about the centroid for unit density,
// by the divergence theorem over a fan triangulation of each face (exact for
// polyhedra up to round-off).
struct MassProperties {
  double volume = 0;
  Vec3 centroid = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();  // about centroid, unit density (multiply by rho)
};
MassProperties mass_properties(const Polyhedron& p);

// x -> R x + t for every vertex; normals and offsets follow.
Polyhedron transformed(const Polyhedron& p, const Mat3& R, const Vec3& t);

// Axis-aligned box of the given full size centred at `center`.
Polyhedron make_box(const Vec3& size, const Vec3& center = Vec3::Zero());

// Right prism: convex polygon in the xy-plane (either orientation; repeated or
// collinear points are rejected), extruded from z0 to z1 (z1 > z0).
Polyhedron make_prism(const std::vector<Vec2>& polygon, double z0, double z1);

// Convex hull of points (CGAL, exact predicates). Coplanar hull facets are
// merged into one polygonal face. Throws GeometryError if the points are
// coplanar or fewer than four.
Polyhedron convex_hull(const std::vector<Vec3>& points);

// Intersection of half-spaces n·x <= d (CGAL). Throws GeometryError if the
// intersection is empty, unbounded or degenerate. `interior` must be a point
// strictly inside all half-spaces.
Polyhedron halfspace_intersection(const std::vector<Vec3>& normals, const std::vector<double>& offsets,
                                  const Vec3& interior);

// Half the sum of the fan triangles' cross products: the unnormalised
// outward normal of a face, with length equal to its area. Uses only the
// vertex loop, not the stored normal.
Vec3 face_vector_area(const Polyhedron& p, int face);
double face_area(const Polyhedron& p, int face);
Vec3 face_centroid(const Polyhedron& p, int face);
double surface_area(const Polyhedron& p);
// ∫_face |x - c|² dA: bounds the rotational stiffness a face can carry.
double face_polar_moment(const Polyhedron& p, int face, const Vec3& c);
// Largest distance from c to a vertex.
double bounding_radius(const Polyhedron& p, const Vec3& c);
// Diagonal of the axis-aligned bounding box: the length scale that relative
// tolerances are measured against.
double bounding_box_diagonal(const std::vector<Vec3>& points);

}  // namespace polydem
