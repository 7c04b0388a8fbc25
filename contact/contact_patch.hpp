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

// What a vertex of the clipped polygon is in the two blocks' own geometry,
// so that it can follow them between detections (joint_sampling "step",
// contact/moving_points.hpp). Every vertex lies on the incident face:
//   incident_vertex   a corner of the incident face (v0, a vertex of the
//                     incident block);
//   incident_edge     where the incident edge v0–v1 crosses the side plane
//                     of the reference face's edge `side`;
//   reference_corner  where the line along the normal through the meeting
//                     point of the side planes of the reference face's edges
//                     `side` and `side2` (a corner of the reference face when
//                     they are neighbours) meets the incident face's plane;
//   fixed             the edge-to-edge crossing: not a vertex of the clip.
enum class PointKind : std::uint8_t { incident_vertex, incident_edge, reference_corner, fixed };

struct PointDefinition {
  PointKind kind = PointKind::fixed;
  int v0 = -1, v1 = -1;       // incident block's vertices (incident_vertex, incident_edge)
  int side = -1, side2 = -1;  // reference face's edges (incident_edge, reference_corner)
};

struct PatchPoint {
  Vec3 point;         // on the incident block, world
  double separation;  // along the normal, > 0 open, < 0 overlapping (m)
  double area;        // tributary area, m²
  std::uint32_t feature;
  PointDefinition def;  // what it is in the blocks' geometry
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
  // Per clipped vertex, what it is, and per polygon edge (from a vertex to
  // the next) the line it lies on: an incident edge (its two vertices, side
  // −1) or a side plane (side).
  struct EdgeLine {
    int v0 = -1, v1 = -1, side = -1;
  };
  std::vector<PointDefinition> poly_def, next_def;
  std::vector<EdgeLine> poly_edge, next_edge;
  std::vector<double> areas;
};

// How a patch's points take their areas, for points fixed in the incident
// block until the next detection (`detection`, the default: fan_areas) or
// for points that follow the blocks (`following`,
// contact/moving_points.hpp: corner_areas, which do not jump when the
// polygon gains or loses a vertex).
// `clipped` (joint_sampling "clip", contact/clip_joint.hpp): corner_areas
// over the polygon with its coincident vertices merged
// (merge_coincident_vertices), and a polygon without area has none.
enum class PatchPoints { detection, following, clipped };

// Under `clipped`, a polygon of at most this fraction of the smaller face's
// area has none: the two faces touch along a line (side-by-side stones), or
// a sliver a round-off wide whose vertices come and go from one step to the
// next. Its springs would have at most a millionth of a face contact's
// stiffness.
inline constexpr double kClipNoArea = 1e-6;

// The clipped polygon in `s` with each vertex at the same place as the one
// before it (within 1e-9 of the longest edge) removed, the edge on from
// the vertex kept taking the removed one's line, and each vertex where the
// boundary runs straight on (within 1e-9 rad) removed, the edge before it
// going on along its line. Masonry is full of faces whose corners lie
// exactly on a neighbour's side plane or edge line: whether the clip then
// gives the corner, a crossing or two at the same place, or a vertex
// mid-edge is round-off's choice, which would otherwise change the
// polygon's vertex count from one step to the next. The corners' areas do
// not change (corner_areas gives such a vertex nothing).
void merge_coincident_vertices(PatchScratch& s);

// The area a corner subcontact carries in a face contact between blocks of
// size l (cube root of volume): a face l × l over its four corners, l²/4.
// The nominal area of edge–edge contacts (docs/contact.md).
double corner_area_of_size(double size);

// Separation of the other block's world vertices from `self`'s face plane
// (> 0 apart, < 0 overlapping).
double face_separation(const PosedBlock& self, int face, const std::vector<Vec3>& other);

// The block's vertices in world coordinates: R·v + x.
void world_vertices(const PosedBlock& block, std::vector<Vec3>& world);

// Step 3's clip: the incident face `iface` (indices into `inc_w`, the
// incident block's world vertices) clipped by the side planes of the
// reference face `rface` (into `ref_w`) of outward normal `n`, by
// Sutherland–Hodgman. Into s.poly (points on the incident face, world),
// s.poly_id (the feature ids that name the subcontacts), s.poly_def (what
// each vertex is) and s.poly_edge (the line each edge lies on). Only the
// entries of the two faces' vertices are read.
void clip_incident_face(const std::vector<Vec3>& ref_w, const std::vector<int>& rface, const Vec3& n,
                        const std::vector<Vec3>& inc_w, const std::vector<int>& iface, PatchScratch& s);

// Steps 2-4 for a pair the narrow phase found within the margin (`hit`).
// Returns false if the pair is farther apart than `margin` after all.
// prev_ref_side / prev_ref_face: the previous detection's choice for this
// pair (-1 if none). `keep_without_points`: a pair that the face test puts
// within the margin is kept with its plane even when the incident face's
// clip leaves no point within it (a corner of another face may be the
// closest point: the overlap joint model integrates every face).
// `prev_inc_face` (PatchPoints::clipped only): the previous incident face,
// kept while the reference face is the previous one and it is within 1e-3
// (in the cosine) of the most opposed face, so that a block edge-on or
// corner-on, whose faces at the edge are equally opposed, is found again on
// the face it was found on.
bool build_patch(const PosedBlock& a, const PosedBlock& b, double margin, const NarrowPhaseHit& hit,
                 int prev_ref_side, int prev_ref_face, Patch& out, PatchScratch& scratch,
                 bool keep_without_points = false, PatchPoints points = PatchPoints::detection,
                 int prev_inc_face = -1);

// The tributary areas of a convex polygon's vertices on the plane of unit
// normal n: each takes half of the two fan triangles at it, the fan about
// the polygon's area centroid (`on_plane`: the vertices projected on the
// plane, in order). Returns the polygon's area (the sum of the areas
// written). A polygon whose area is at most `floor` has no area centroid:
// the fan is about the vertices' mean.
double fan_areas(const Vec3* on_plane, std::size_t count, const Vec3& n, double floor, double* area);

// The tributary areas of a convex polygon's vertices by their corners: each
// takes the polygon's area times its exterior angle over the full turn
// (2π), so a square's corners a quarter each, and a vertex where the
// boundary goes straight on nothing. A vertex that appears on an edge (the
// polygon cut by a plane through it) takes nothing at first, and a corner
// cut into two vertices a hair apart hands its angle, and its area, on to
// them: the areas are continuous in the polygon's shape whatever vertices
// it is given, which the fan's are not (a vertex appearing mid-edge takes
// half of two fan triangles at once). A vertex at the same place as the one
// before it takes nothing. Returns the polygon's area; at most `floor`: no
// area, and the areas written are zero.
double corner_areas(const Vec3* on_plane, std::size_t count, const Vec3& n, double floor, double* area);

// Step 2's choice of the common plane for blocks a and b (world vertices
// world_a, world_b): the face, of either block, with the largest
// separation of the other's vertices along its own normal (sep_a, sep_b:
// each block's best), the previous choice (prev_ref_side, prev_ref_face;
// -1: none) kept while it is within 0.05 x margin of the best.
struct CommonPlane {
  int ref_side = 0;  // 0: a face of a, 1: of b
  int ref_face = -1;
  double separation = 0;  // its separation (> 0 apart), m
};
CommonPlane choose_common_plane(const PosedBlock& a, const PosedBlock& b, const std::vector<Vec3>& world_a,
                                const std::vector<Vec3>& world_b, double margin, int prev_ref_side,
                                int prev_ref_face, double& sep_a, double& sep_b);
// Step 3's incident face: the face of `inc` most opposed to the world
// normal n, or `prev_inc_face` (-1: none) while it is within 1e-3 (in the
// cosine) of the most opposed.
int choose_incident_face(const PosedBlock& inc, const Vec3& n, int prev_inc_face);

// Narrow phase and patch in one call (steps 1-4).
bool find_patch(const PosedBlock& a, const PosedBlock& b, double margin, int prev_ref_side, int prev_ref_face,
                Patch& out, PatchScratch& scratch);

}  // namespace polydem
