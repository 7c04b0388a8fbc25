// Narrow phase and contact patch for one pair of convex blocks.
//
// 1. The narrow phase (narrow_phase.hpp: libccd's MPR on the blocks
//    inflated by half the margin) rejects pairs farther apart than the margin
//    and gives a penetration depth and direction.
// 2. Common plane: the face, of either block, with the largest separation
//    along its own outward normal (the separating-axis test over face
//    normals). For blocks meeting face to face, or a block rocking on an edge
//    over a face, that face's plane is the joint plane. The previous choice is
//    kept while it is within a small tolerance of the best, so that the
//    subcontacts (and their shear history) do not flip between the two
//    parallel faces of a closed joint.
// 3. Patch: the incident face (the other block's face most opposed to the
//    common-plane normal) is clipped by the side planes of the reference face
//    (Sutherland–Hodgman). The clipped polygon projected on the common plane is
//    the joint's patch; its vertices within the margin become subcontacts
//    with tributary areas from a fan about the polygon's centre. Vertices
//    farther than the margin are dropped with their areas: the patch's area
//    is the sum of the areas kept. A polygon without area (faces touching
//    along their boundary only) shares a nominal 1 % of the smaller face.
// 4. Fallback: when the face test says the blocks overlap much more than MPR
//    does (edge-to-edge contact, no face aligned), the MPR direction is the
//    normal and a single subcontact carries it, with the area of one corner
//    of a face contact between the same blocks: corner_area_of_size of the
//    smaller block's size. docs/contact.md gives the reasoning.
#pragma once

#include "contact/narrow_phase.hpp"
#include "geometry/polyhedron.hpp"

#include <cstdint>
#include <vector>

namespace polydem {

struct PosedBlock {
  const Polyhedron* shape;  // body frame
  Mat3 R;
  Vec3 x;
  double size = 0;  // cube root of the volume (m); 0: computed when needed
};

struct PatchPoint {
  Vec3 point;         // on the incident block, world
  double separation;  // along the normal, > 0 open, < 0 overlapping (m)
  double area;        // tributary area, m²
  std::uint32_t feature;
};

struct Patch {
  int ref_side = 0;  // 0: reference face on the first block, 1: on the second
  int ref_face = -1, inc_face = -1;
  Vec3 normal = Vec3::Zero();  // world, outward from the reference face
  double offset = 0;           // plane normal·x = offset, world
  double area = 0;  // sum of the points' areas (the part within the margin), m²
  std::vector<PatchPoint> points;
};

// Scratch buffers reused across calls (one per thread) so that detection does
// not allocate once warmed up.
struct PatchScratch {
  std::vector<Vec3> world_a, world_b;
  std::vector<Vec3> poly, next;
  std::vector<std::uint32_t> poly_id, next_id;
};

// The area a corner subcontact carries in a face contact between blocks of
// size l (cube root of volume): a face l × l over its four corners, l²/4.
// The nominal area of edge–edge contacts (docs/contact.md).
double corner_area_of_size(double size);

// Separation of the other block's world vertices from `self`'s face plane
// (> 0 apart, < 0 overlapping).
double face_separation(const PosedBlock& self, int face, const std::vector<Vec3>& other);

// The block's vertices in world coordinates: R·v + x.
void world_vertices(const PosedBlock& block, std::vector<Vec3>& world);

// Steps 2-4 for a pair the narrow phase found within the margin (`hit`).
// Returns false if the pair is farther apart than `margin` after all.
// prev_ref_side / prev_ref_face: the previous detection's choice for this
// pair (-1 if none). `keep_without_points`: a pair that the face test puts
// within the margin is kept with its plane even when the incident face's
// clip leaves no point within it (a corner of another face may be the
// closest point: the overlap joint model integrates every face).
bool build_patch(const PosedBlock& a, const PosedBlock& b, double margin, const NarrowPhaseHit& hit,
                 int prev_ref_side, int prev_ref_face, Patch& out, PatchScratch& scratch,
                 bool keep_without_points = false);

// Narrow phase and patch in one call (steps 1-4).
bool find_patch(const PosedBlock& a, const PosedBlock& b, double margin, int prev_ref_side, int prev_ref_face,
                Patch& out, PatchScratch& scratch);

}  // namespace polydem
