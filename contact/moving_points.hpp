// Joint points that follow the blocks between detections
// (`simulation.joint_sampling = "step"`).
//
// A detection clips the incident face by the reference face's side planes
// (contact_patch.hpp) and makes each vertex of the clipped polygon a
// subcontact. By default each point is then fixed in the incident block
// until the next detection, with the tributary area the fan gave it. Only
// the incident face's corners are material points of the incident block,
// though. A crossing of an incident edge with a side plane of the reference
// face slides along that edge as the blocks move, fast where the two edges
// are nearly parallel (aligned masonry joints: a crossing moves by the
// blocks' relative motion over the sine of the angle between the edges),
// and a corner of the reference face belongs to the reference block. Held
// fixed in the incident block they drift from the polygon they sample, and
// the next detection, clipping again, puts them back: the force jumps
// (benchmarks/redetection_jump.cpp).
//
// Here each point keeps its definition instead of its position: a corner of
// the incident face, the crossing of an incident edge (fixed in the
// incident block) with a side plane (fixed in the reference block), or the
// line along the normal through a corner of the reference face meeting the
// incident face's plane. Before the joint law, every step, each point is
// put where its definition says at the blocks' current poses. A crossing
// is held within both its edges: where two nearly parallel edges cross
// (faces of equal stones one on the other), the crossing runs off the end
// of one of them after a small relative motion, and the polygon's vertex is
// then that end (the other face's corner), where the held crossing stays.
// A corner of the incident face past a side of the reference face (slid
// off its support's edge) is held on that side, moved along the incident
// face, and a reference corner past a side of the incident face likewise:
// the two sides nearest at the detection are watched.
// An edge within a thousandth of a radian of its side plane (an edge lying
// in the plane of the face below) has no crossing to speak of, and a corner
// line nearly parallel to the incident face no meeting point: those points
// stay fixed in the incident block, as the default's do.
//
// The areas stay the detection's until the next one: a spring whose area
// changed with the pose would no longer be the gradient of its strain
// energy ½·kn·A·u² (the change of area would make or take ½·kn·u² a unit
// of area, with no force doing that work). They are the points'
// shares of the polygon by their corners (corner_areas): when the next
// detection finds a vertex more or less (a corner of the incident face
// that has crossed a side plane since becomes two crossings; a crossing
// that reached the end of its edge becomes that end), the areas move by
// what the polygon's shape changed, not by the change of vertex count,
// which the fan's areas do not manage (a vertex appearing mid-edge takes
// half of two fan triangles at once).
#pragma once

#include "contact/contact_patch.hpp"
#include "core/blocks.hpp"
#include "geometry/vec3_array.hpp"

#include <cstdint>
#include <vector>

namespace polydem {

struct ContactPair;
struct Subcontacts;

// Per subcontact, what its point is (PointKind) in the blocks' body frames.
// Sized with the subcontacts only when the points follow the blocks (`on`).
struct MovingPoints {
  bool on = false;
  std::vector<std::uint8_t> kind;  // PointKind
  // incident_edge: the edge's ends (incident frame), the side plane's unit
  // normal (reference frame) and offset (m·y = c). reference_corner: a point
  // of the corner's line on the reference plane (reference frame, in `a`),
  // the incident face's unit normal (incident frame, in `m`) and offset.
  std::vector<Vec3> a, b, m;
  std::vector<double> c;
  // incident_edge: the reference face's edge whose side plane it crosses
  // (reference frame): the crossing is held within both edges.
  std::vector<Vec3> r0, r1;
  // incident_vertex: the vertex and the incident face's unit normal
  // (incident frame) in `a` and `b`, and the two side planes of the
  // reference face nearest to it (reference frame); reference_corner: the
  // two side planes of the incident face nearest to it (incident frame).
  // A point past one is held on it, moved along the incident face.
  std::vector<Vec3> h1, h2;
  std::vector<double> o1, o2;

  void resize(std::size_t n);
  // Calls f(array of this, array of `other`, name) for each array above,
  // always in this order (resizing, checkpoints, copies).
  template <class Self, class Other, class F>
  static void for_each_array(Self& self, Other& other, F&& f) {
    f(self.kind, other.kind, "kind"), f(self.a, other.a, "a"), f(self.b, other.b, "b"), f(self.m, other.m, "m");
    f(self.c, other.c, "c"), f(self.r0, other.r0, "r0"), f(self.r1, other.r1, "r1"), f(self.h1, other.h1, "h1");
    f(self.h2, other.h2, "h2"), f(self.o1, other.o1, "o1"), f(self.o2, other.o2, "o2");
  }
};

// Subcontact s's definition from the patch point that made it (the pair's
// reference face `ref_face` on `ref`, incident face `inc_face` on `inc`).
// `point_ref`, `point_inc`: the point in the reference and incident frames.
void define_moving_point(const Polyhedron& ref_shape, int ref_face, const Polyhedron& inc_shape, int inc_face,
                         const PatchPoint& pt, const Vec3& point_ref, const Vec3& point_inc, MovingPoints& mp,
                         std::size_t s);

// Pairs [begin, end)'s points put where their definitions say at the
// blocks' poses in `st` (written to inc_point_local). The step's stage
// before the joint law.
void move_points(const BlockState& st, const std::vector<ContactPair>& pairs, Subcontacts& sub, std::size_t begin,
                 std::size_t end);

}  // namespace polydem
