// The joint clipped again as it moves (`simulation.joint_sampling = "clip"`).
//
// A detection samples a joint: it clips the incident face by the reference
// face's side planes and puts a normal spring kn·A_i at each vertex of the
// polygon P it finds, with A_i the vertex's share of P by its corner's
// angle (corner_areas: A_i = |P|·θ_i/2π). Between samplings the polygon
// changes shape as the blocks slide and turn (a joint that shrinks as a
// stone slides off its bed), and the springs lag it until the next.
//
// Here the pair's face polygon is clipped again whenever its two blocks
// have moved relative to each other by the detection travel since its last
// clip (Simulation::clip_due; with a travel of 1e-12 m, at every step), at
// the blocks' current poses, and its springs are the polygon's vertices:
// each subcontact's point is its vertex (a corner of the incident face, the
// crossing of an incident edge with a side plane of the reference face, or
// a reference corner seen on the incident face) and its area the vertex's
// corner share of the polygon now. The joint's normal strain energy
//
//     E(q) = Σ_i ½·kn·A_i(q)·⟨u_i(q)⟩₊²,    u_i the overlap at vertex i,
//
// is then a function of the blocks' poses q alone, and the load a clip
// gives is its exact gradient there, −∂E/∂q, which is more than the
// springs' kn·A_i·u_i along the plane's normal at each vertex:
//   - a crossing slides along its incident edge e as the side plane s cuts
//     it elsewhere, so its overlap changes along the slide: the spring
//     pushes along n − ((n·e)/(s·e))·s, not along n;
//   - a reference corner presses on the incident face (normal m), whose
//     plane moves under it: it pushes along m/(m·n);
//   - the areas change with the polygon: ½·kn·u_i² per unit area, through
//     the polygon's area (each incident edge's line moved along its outward
//     normal, L·ν at the edge's middle) and through the corners' angles
//     (each incident edge's line turned, its two ends' ½·kn·u² a unit of
//     angle, times |P|/2π).
// The springs' part goes through the joint law with the subcontacts (so
// friction's cap and the dashpots see each vertex's normal force); the rest
// is one wrench per pair (`clip_pairs`), gathered by pair and held with
// the springs until the pair's next clip. The reference block takes the
// reaction: the energy depends on the two blocks' relative pose only.
//
// The shear springs carry their history: each keeps its elastic shear
// displacement F/(ks·A) as its area changes, so its force goes with its
// area. The shear energy F²/(2·ks·A) then goes with the area too: the part
// of the joint that slides off takes its strain with it. No force does that
// work; the ledger books it with the re-samplings' (dropped shear).
//
// A bonded joint (cohesion, tensile strength) is clipped the same way: its
// springs in tension take their force kn·A_i·u_i along n through the joint
// law at their vertices. The rest is taken over the compressed springs
// only, so a spring in tension (|u| at most σt/kn, micrometres) goes
// without its rest's terms (its point's slide, the areas' part), of the
// order of its own force times σt/kn over the polygon's size; its energy,
// ½·σt²/kn a unit of area at most. A vertex left without a spring (below)
// pushes and never pulls.
//
// The polygon's topology (which vertices it has) changes when a corner
// crosses a side plane: the corner becomes two crossings a hair apart, with
// the corner's angle, and so its area, shared between them (corner_areas),
// so E is continuous there. A pair whose clip no longer has its
// subcontacts' vertices, or whose faces a detection would now choose
// otherwise, is marked `stale`, and the step re-samples it at once, at the
// same pose, and clips it again (Simulation::clip_after_detection); should
// it still be stale, its points follow their definitions for that step as
// under "step" (contact/moving_points.hpp), with the areas they had, and it
// is clipped again at the next step.
#pragma once

#include "contact/contact_patch.hpp"
#include "contact/joint_law_kernels.hpp"
#include "contact/subcontacts.hpp"

#include <cstdint>
#include <vector>

namespace polydem {

struct JointLaws;

// Per-thread scratch (no allocation once warmed up).
struct ClipScratch {
  PatchScratch patch;
  std::vector<Vec3> ref_w, inc_w;  // world vertices: only the two faces' entries are set
  std::vector<Vec3> on_plane;
  std::vector<double> area, u;
  std::vector<std::uint8_t> taken;     // per vertex: a subcontact's
  std::vector<std::size_t> vertex_of;  // per subcontact: its vertex
};

// A vertex of the clipped polygon turning its boundary by less than this
// (rad) need not have a subcontact (clip_pairs).
inline constexpr double kClipCornerAngle = 1e-3;

// One face pair's normal layer at the blocks' current poses.
struct ClipLoad {
  double energy = 0;  // Σ ½·kn·A_i·⟨u_i⟩₊², J
  double area = 0;    // the clipped polygon's area, m² (0: none to speak of)
  // The gradient's part not carried by the springs along n, on the
  // incident block: force, and moment about its centroid.
  Vec3 rest_force = Vec3::Zero(), rest_moment = Vec3::Zero();
  // The whole load −∂E/∂q on the incident block (the springs' part
  // kn·A_i·⟨u_i⟩₊·n at each vertex plus the rest); the reference block takes
  // the reaction.
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
};

// Clips `inc_face` of `inc` by `ref_face` of `ref` at their poses (the clip
// of contact_patch.hpp) and evaluates the layer on the plane of world unit
// normal `n` (the reference face's, out of it) and offset `c` (n·x = c; the
// overlap at x is c − n·x). After it, `s.patch.poly` etc. hold the polygon,
// s.area the vertices' corner areas and s.u their overlaps. `face_area_min`:
// the smaller of the two faces' areas; a polygon of at most kClipNoArea of
// it has no area (contact_patch.hpp).
ClipLoad clip_normal_load(const PosedBlock& ref, int ref_face, const PosedBlock& inc, int inc_face, const Vec3& n,
                          double c, double kn, double face_area_min, ClipScratch& s);

// The step's stage before the joint law under "clip", pairs [begin, end):
// each face pair clipped at the current poses. Where the clip's vertices
// within `margin` of the plane are the pair's subcontacts (the same
// features in the same order), each subcontact's point and area are set to
// its vertex's and `rest[q]` gets the gradient's rest (force on the
// incident block, its moment, the reaction's moment about the reference
// block's centroid). Otherwise the points are moved as under "step",
// rest[q] is zero and stale[q] is set (the pair trigger re-samples it);
// likewise where a detection at this pose would choose other faces for
// the pair, find it beyond the margin, or judge it edge to edge (the face
// test deeper than the polygon's deepest vertex by a quarter of the
// margin). Edge-to-edge pairs are left alone. A subcontact whose area
// changes keeps its elastic shear displacement (its shear force scaled by
// the areas' ratio); `shear_dropped[q]` gets the shear energy that took
// away (J, < 0 where it added). `face_areas` (per block, per face;
// face_areas_of) saves the step computing them again; null: computed.
void clip_pairs(const std::vector<Polyhedron>& shapes, const BlockState& st, const JointLaws& laws,
                const std::vector<ContactPair>& pairs, double margin, Subcontacts& sub,
                std::vector<lanes::PairRest>& rest, std::vector<std::uint8_t>& stale,
                std::vector<double>& shear_dropped, std::size_t begin, std::size_t end, ClipScratch& s,
                const std::vector<std::vector<double>>* face_areas = nullptr);

// The same for the pairs `list[0 .. count)` alone; `check_faces` false
// leaves out the faces' questions (pairs a detection has just sampled at
// this pose).
void clip_listed_pairs(const std::vector<Polyhedron>& shapes, const BlockState& st, const JointLaws& laws,
                       const std::vector<ContactPair>& pairs, double margin, Subcontacts& sub,
                       std::vector<lanes::PairRest>& rest, std::vector<std::uint8_t>& stale,
                       std::vector<double>& shear_dropped, const int* list, std::size_t count, ClipScratch& s,
                       const std::vector<std::vector<double>>* face_areas, bool check_faces);

// Every face's area (face_area) of each of `shapes`, for clip_pairs.
std::vector<std::vector<double>> face_areas_of(const std::vector<Polyhedron>& shapes);

}  // namespace polydem
