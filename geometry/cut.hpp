// Cutting convex blocks by planes: 3DEC's `block cut joint-set`.
//
// A joint set is a family of parallel planes given as a geologist gives
// them: dip (degrees below horizontal, 0..90) and dip direction (the azimuth
// the plane descends towards, degrees clockwise from north). With x east,
// y north and z up, the plane's upward unit normal is
//
//   n = (sin(dip)·sin(dip_direction), sin(dip)·cos(dip_direction), cos(dip))
//
// (dip 0: a horizontal bed joint, n = +z; dip 90, dip direction 90: a
// vertical joint facing east, n = +x). The planes are n·x = n·origin +
// k·spacing for k = 0 … count-1: the first passes through the origin, the
// others follow along +n.
//
// A plane splits a block into the part below it (n·x < d) and the part
// above. The points where the plane crosses the block's edges are computed
// once, in double precision, and both pieces are built from the same
// doubles: the two pieces share their cut face bit for bit, with neither a
// gap nor an overlap, and their volumes sum to the block's to round-off.
// Each piece is then the CGAL hull of its corners (exact predicates,
// geometry/convex_hull.cpp), so it is numbered canonically: a piece and the
// same corners listed as a [[block]] hull are the same block, bit for bit.
// On the cut face the crossing point is placed on the plane exactly in the
// coordinate along which the normal is largest (x = (d - n_y y - n_z z)/n_x
// for a joint facing east), so a plane parallel to a box's faces gives the
// corners one would write by hand.
//
// A corner within 1e-12 of the block's size from the plane is on it (it
// belongs to both pieces and no crossing is made next to it). A plane that
// passes closer than 1e-7 of the block's size to a corner without going
// through it would make needle-thin faces: that is an error (move the plane),
// not a silent change of the block. A plane that would cut off a piece
// thinner than `min_thickness` (its farthest corner from the plane nearer
// than that) leaves the block whole: slivers are not made.
#pragma once

#include <optional>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace polydem {

// Upward unit normal of a plane of the given dip and dip direction (degrees;
// the convention above). Multiples of 90° give exact 0s and 1s.
Vec3 joint_set_normal(double dip_degrees, double dip_direction_degrees);

// How far a block reaches below and above the plane n·x = d (both >= 0).
struct PlaneReach {
  double below = 0;  // max over corners of d - n·x
  double above = 0;  // max over corners of n·x - d
};
PlaneReach plane_reach(const Polyhedron& p, const Vec3& n, double d);

// The two pieces of a block split by the plane n·x = d (n unit): [0] below,
// [1] above. Throws GeometryError if the plane does not cross the block's
// interior or passes needle-close to a corner.
struct PlanePieces {
  Polyhedron below, above;
};
PlanePieces split_by_plane(const Polyhedron& p, const Vec3& n, double d);

struct JointSet {
  Vec3 normal = Vec3::UnitZ();  // unit
  Vec3 origin = Vec3::Zero();   // a point of the first plane
  double spacing = 0;           // m between planes along the normal (> 0 when count > 1)
  int count = 1;                // number of planes
  double min_thickness = 0;     // m: a piece thinner than this is not cut off
};

// The offset d of plane k (n·x = d).
double joint_plane_offset(const JointSet& set, int k);

// The block cut by every plane of the set in turn, pieces ordered along the
// normal (below first). A block no plane cuts comes back as the one piece.
std::vector<Polyhedron> cut_by_joint_set(const Polyhedron& p, const JointSet& set);

// Penetration of two convex blocks: the least distance one must move to
// separate them (the separating-axis test over both blocks' face normals and
// the cross products of their edges); 0 or less when they are apart or only
// touch. `axis` (if given) receives the direction of least penetration.
double penetration_depth(const Polyhedron& a, const Polyhedron& b, Vec3* axis = nullptr);

// The volume the two convex blocks share (a clipped by b's face planes), or
// nullopt when the clipping cannot be built (a sliver thinner than the
// corner tolerance); 0 when they do not overlap.
std::optional<double> overlap_volume(const Polyhedron& a, const Polyhedron& b);

}  // namespace polydem
