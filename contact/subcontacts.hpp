// Contacts between blocks: pairs, and the subcontacts that carry the joint.
//
// A joint between two blocks is a contact *patch*: the overlap of a reference
// face of one block with the incident face of the other, projected on the
// common plane (the reference face's plane). Its vertices are the
// subcontacts (3DEC style), each with a tributary area; the areas add up to
// the patch area. A block resting face to face thus has springs at the
// corners of its footprint and can rock about an edge, which a single deepest
// point per pair cannot do.
//
// Each subcontact is body-fixed between detections: the reference plane in
// the reference block's body frame, the incident point in the incident
// block's body frame. So the normal gap and the shear displacement follow
// the blocks exactly until the next detection, which only rebuilds the patch
// when some blocks have moved relative to each other by the detection travel
// (contact/detection.hpp).
//
// The history a joint carries (elastic shear, bond, dissipation so far)
// belongs to a place on the joint, not to a vertex of the clipped polygon:
// a detection hands it to the new subcontacts by position (carry_history),
// and books the elastic shear energy it cannot hand on.
//
// Storage is a struct of arrays indexed by subcontact; one force slot per
// subcontact is written in parallel and gathered per block in a fixed order
// (see gather.hpp), so results do not depend on the number of threads. The
// vectors the joint law reads and writes four subcontacts at a time (the
// incident point, the shear and dashpot forces) are themselves split into
// x, y, z arrays (Vec3Array); those the gather reads one subcontact at a
// time (force, point) stay Vec3.
#pragma once

#include "contact/contact_patch.hpp"
#include "contact/moving_points.hpp"
#include "contact/pair_joints.hpp"
#include "core/blocks.hpp"
#include "core/byte_stream.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/vec3_array.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace polydem {

struct JointLaws;  // contact/joint_law.hpp

struct ContactPair {
  int a = 0, b = 0;        // block indices, a < b
  int ref_block = 0;       // a or b: the block whose face is the common plane
  int ref_face = 0;        // face of ref_block
  int inc_face = 0;        // face of the other block
  int first = 0, count = 0;  // range in Subcontacts
  double patch_area = 0;   // m²
  // The common plane this detection found, in ref_block's frame: unit
  // normal and offset (normal·x = offset).
  Vec3 normal_local = Vec3::UnitZ();
  double offset_local = 0;
};

struct Subcontacts {
  // Identity.
  std::vector<int> pair;
  std::vector<int> ref_block, inc_block;
  std::vector<std::uint64_t> key;  // the clipped feature that makes it (pair-local; not used to carry history)
  // Body-fixed geometry.
  std::vector<Vec3> ref_normal_local;   // reference face normal, ref body frame
  std::vector<double> ref_offset_local;  // plane n·x = offset, ref body frame
  Vec3Array inc_point_local;             // incident point, inc body frame
  std::vector<double> area;              // tributary area, m²
  // How far the detection moved the spring's zero into the joint so that its
  // re-sampling made no normal strain (hold_normal_strain, joint_law.hpp):
  // the blocks' geometric overlap is overlap + crush. Zero but after a hard
  // impact or a contact found already overlapping. Folded into
  // ref_offset_local, so the step never reads it. m, ≥ 0.
  std::vector<double> crush;
  // History carried across detections.
  Vec3Array shear_force;           // elastic shear force on the incident block, world, N
  std::vector<std::uint8_t> bonded;  // still has cohesion / tensile strength
  // Per-step results (one slot each).
  std::vector<Vec3> force;          // total joint force on the incident block, N
  std::vector<Vec3> point;          // world point where it acts
  std::vector<double> overlap;      // the spring's normal overlap u_n (> 0 closed), m
  std::vector<double> normal_force;  // total normal force incl. damping, N
  std::vector<double> slip_energy;     // cumulative slip dissipation, J
  std::vector<double> damping_energy;  // cumulative damping dissipation, J
  // The dashpot force of the last step (world, on the incident block, N):
  // half of its work is booked with the next step's velocity (joint_law.hpp).
  Vec3Array damping_force;
  // What each point is in the blocks' geometry, when the points follow the
  // blocks between detections (contact/moving_points.hpp); empty otherwise.
  MovingPoints moving;

  std::size_t size() const { return key.size(); }
  // The blocks' overlap at s (the spring's plus its crush), m: what
  // penetration and openings are judged on.
  double geometric_overlap(std::size_t s) const { return overlap[s] + crush[s]; }
  void clear();
  void resize(std::size_t n);
};

struct ContactSet {
  std::vector<ContactPair> pairs;
  Subcontacts sub;
  // Per pair, under the overlap joint model only (contact/overlap_joint.hpp).
  PairJoints joints;
  // CSR list of the subcontacts acting on each block, in a fixed order:
  // gather_offset[i] .. gather_offset[i+1] index gather_sub/gather_sign.
  std::vector<int> gather_offset, gather_sub;
  std::vector<double> gather_sign;  // +1 incident, −1 reference
  // Dissipation of subcontacts that no longer exist (kept for the ledger).
  double retired_slip_energy = 0, retired_damping_energy = 0;
  // Elastic shear energy F²/(2·ks·A) that detections could not hand on to a
  // new subcontact (a patch that shrank, a subcontact or a pair that is
  // gone), J, cumulative since the dynamic stage began.
  double dropped_shear_energy = 0;
  // Normal strain energy Σ ½·kn·A·u_n² that detections removed (> 0) or
  // added (< 0) by re-sampling the joints at the same pose: the patches'
  // points and tributary areas change while the blocks have not moved, J,
  // cumulative since the dynamic stage began.
  double resampled_normal_energy = 0;
  // Both as the part of the ledger's numerical line the detections account
  // for (signed as that line: energy removed is < 0).
  double numerical_at_detections() const { return -(dropped_shear_energy + resampled_normal_energy); }
  int detections = 0;
  // True under the overlap joint model once it has pairs: the joints'
  // forces and energies are the pairs' (`joints`), not the subcontacts'.
  bool pair_joints_in_use() const { return !pairs.empty() && joints.size() == pairs.size(); }

  // Checkpoints: every array above, bit for bit (see core/byte_stream.hpp).
  // load() checks that the arrays agree in length and that every block and
  // subcontact index is in range for `blocks` blocks; throws StateFormatError.
  void save(ByteWriter& w) const;
  void load(ByteReader& r, int blocks);
};

// The pair (a, b), a < b, of `set` (whose pairs are sorted by (a, b)), or
// nullptr. A binary search: no hash map, so no iteration order to leak.
const ContactPair* find_pair(const ContactSet& set, int a, int b);

// The key of a subcontact within its pair: which block holds the reference
// face (ref_side 0: the pair's a), the reference and incident faces, and the
// clipped feature of contact_patch.cpp (incident vertex, or the crossing of a
// reference side plane with an incident edge). It names the subcontact
// (tests, debugging); history goes by position (carry_history), since the
// clip's topology changes when a corner crosses an edge or the reference
// face changes sides while the joint itself has hardly moved.
std::uint64_t subcontact_key(int ref_side, int ref_face, int inc_face, std::uint32_t feature);

// Rebuilds `out.pairs` and `out.sub` from the patches found for the
// candidate pairs (candidates[k] = (i, j), i < j, sorted; patches[k] valid
// where found[k]), in candidate order. Each subcontact is made body-fixed
// (reference plane in the reference block's frame, incident point in the
// incident block's frame) at the current state and starts without history:
// no shear force, no dissipation, bonded if `bond_new`. The gather lists,
// the retired dissipation and the detection count are left alone.
// `kept_from` (with `previous`): per candidate, the index of a pair of
// `previous` taken over whole instead of its patch (its subcontacts, their
// body-fixed geometry and history, bit for bit), or −1 to build from the
// patch: a pair that has not moved since it was sampled is not re-sampled.
void build_subcontacts(const Blocks& blocks, const std::vector<std::pair<int, int>>& candidates,
                       const std::vector<Patch>& patches, const std::vector<char>& found, bool bond_new,
                       ContactSet& out, const ContactSet* previous = nullptr,
                       const std::vector<int>* kept_from = nullptr);

// The subcontacts of `patch` (found for the pair (i, j), i < j) written
// as pair `index` of a set, from subcontact `first` on (sc already sized):
// body-fixed at the current state, without history (bonded if
// `bond_new`); `cp` gets the pair.
void sample_pair(const Blocks& blocks, int i, int j, const Patch& patch, bool bond_new, int index, int first,
                 ContactPair& cp, Subcontacts& sc);

// Pairs [first_pair, last_pair) of `from` appended whole to `to` (pairs,
// subcontacts with their history); the gather lists and totals left alone.
void append_pairs(const ContactSet& from, int first_pair, int last_pair, ContactSet& to);

// Scratch for carry_history, reused across detections (no allocation once
// warmed up).
struct CarryScratch {
  std::vector<Vec3> old_point;          // previous subcontacts' incident points at the current pose
  std::vector<Vec3> old_stress;         // previous subcontacts' elastic shear stress F/A, Pa
  std::vector<char> dissipation_taken;  // per previous subcontact: its dissipation went to an inheritor
  // Per block, set by the caller: how far it has moved since the previous
  // detection, its translation and the chord its rotation swept at its
  // bounding radius (2·|sin(θ/2)|·r). Empty: no block has moved.
  std::vector<Vec3> moved;
  std::vector<double> turned;
  // Pair by pair (`by_pair`, contact/detection.hpp): only the new set's
  // pairs `sampled` (ascending) are carried, each with its own reach
  // (`reach`, per pair of the new set, in place of the one from `moved`
  // and `turned`: its blocks' relative motion since it was sampled); the
  // previous pairs `old_kept` (per previous pair; empty: none) were copied
  // into the new set whole and neither retire nor drop anything. The
  // ledger's terms are taken over the pairs sampled and the pairs gone
  // only (the rest cancel); `old_taken` gets, per previous pair, whether a
  // sampled pair took it on.
  bool by_pair = false;
  std::vector<int> sampled;
  std::vector<double> reach;
  std::vector<char> old_kept;
  std::vector<char> old_taken;
};

// History carry-over from one detection to the next, by position on the
// joint (see subcontacts.cpp for the reasoning). For each block pair found
// again, the previous subcontacts' incident points are evaluated at the
// current pose of `blocks` (they are fixed in their block): they span the
// previous patch, and their elastic shear stresses F/A sample the joint's
// shear field. Each new subcontact (built at the current pose) lying on the
// previous patch — inside it, or outside by at most the pair's reach in the
// joint plane, |d_a − d_b| + turned_a + turned_b from scratch.moved and
// scratch.turned (the farthest any point of one block has moved relative to
// the other since the previous detection, so the farthest the patch's edge
// can have moved) — takes
//   - the shear stress interpolated linearly at its point (a fan of
//     triangles about the previous points' centroid, whose value is their
//     mean, so a uniform shear and a twist are reproduced exactly; along
//     the nearest edge outside it), times its own area: the elastic shear
//     displacement carries, the force goes with the area; turned onto the
//     new incident block if the reference face changed sides, and
//     projected onto the new plane;
//   - the bond of the nearest previous subcontact (ties: the first);
//   - the cumulative slip and damping dissipation of that nearest one, if
//     no subcontact before it in `current` took them (never counted twice);
//     a previous subcontact no one takes retires its dissipation into the
//     totals.
// No strain energy is created: if a pair's new shear energy exceeds its
// previous one, the pair's new forces are scaled down to it. The elastic
// shear energy Σ F²/(2·ks·A) of `previous` minus that of `current` (≥ 0: a
// patch that shrank, a coarser sampling, pairs that are gone) is added to
// `dropped_shear_energy`; the totals are taken over from `previous`. So the
// ledger's balance is unchanged by a detection. Pair by pair
// (scratch.by_pair) the same for the pairs sampled alone.
// `threads` > 1: the pairs in parallel (the same bits).
void carry_history(const Blocks& blocks, const ContactSet& previous, ContactSet& current, const JointLaws& laws,
                   CarryScratch& scratch, int threads = 1);

}  // namespace polydem
