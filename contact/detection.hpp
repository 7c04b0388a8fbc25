// Contact detection: the stages that rebuild the contact set, in order.
//
//   detect():
//     1. broad phase: candidate pairs from the blocks' boxes   broad_phase.hpp
//     2. narrow phase: which candidates are within the margin  narrow_phase.hpp
//     3. patch: common plane, clipped joint polygon            contact_patch.hpp
//     4. subcontacts from the patches, history carried over    subcontacts.hpp
//        by position on the joint
//     5. per-block gather lists                                gather.hpp
//
// Detection runs only when some pair of blocks may have moved relative to
// each other by more than the detection travel since the last one (the two
// largest travels, translation measured from the blocks' common drift plus
// rotation times the bounding radius plus the coming step at the current
// speed, add up to it). The detection travel is at most half the margin. A
// pair farther apart than the margin at a detection (the broad phase grows
// every box by half the margin, the narrow phase looks a margin out) is
// thus still at least half the margin apart at the next one: contacts
// between fast blocks are found before they touch. In between, the
// subcontacts follow their blocks exactly but their sampling of the joint
// does not: the points stay where the detection put them in the incident
// block and push against the reference face's plane, also once the faces
// have slid so that a point has left the reference face (a stone whose
// support has moved away still stands on it). The detection travel bounds
// that lag; under the subcontact model it is by default 0.016 % of the
// smallest free block pair by pair and 0.25 % scene-wide, far below half
// the margin (docs/contact.md, "The detection travel"), under the overlap
// model (nothing sampled) half the margin.
//
// Triggered pair by pair (the subcontact model's default; "scene" below
// re-samples the whole scene at once), the lag
// is bounded for each pair by its own blocks' motion: a pair is re-sampled
// alone (resample()) once its two blocks have moved relative to each other
// by the detection travel since it was sampled, and the whole scene is
// searched again (detect()) only for new pairs, once any two blocks may
// have closed by half the margin; pairs that have not moved are then taken
// over whole. The travel can be made small at the cost of the pairs that
// move, not of the scene; its automatic value is a sixteenth of the
// scene-wide one (docs/contact.md, "Detection pair by pair"). A pair
// re-sampled with an unchanged layout is written in place
// (resample_in_place); otherwise the set is rebuilt around it.
//
// Steps 2 and 3 run in parallel, one slot per candidate; step 4's history carry and
// held normal strain run pair by pair in parallel (a pair writes only its
// own subcontacts), and its energy sums take their terms in subcontact
// order. Everything is assembled in candidate order (sorted by block pair),
// so the result does not depend on the number of threads
// (tests/integrators/spire_detection_test.cpp).
#pragma once

#include "contact/joint_law.hpp"
#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"

#include <limits>
#include <memory>
#include <vector>

namespace polydem {

// The detection travel a subcontact-model run takes when the deck sets none
// (simulation.detection_travel = 0): 0.25 % of the smallest free block's size
// (of any block when none is free), where the spire's answers lie within a
// bisection bracket of those at smaller travels (docs/contact.md, "The
// detection travel"). Pair by pair (`pair_trigger`, the default) a sixteenth of it: a
// pair is then re-sampled on its own blocks' motion, not at the cadence of
// the fastest pair in the scene, and its travel must be that much smaller
// for the same answers (docs/contact.md, "Detection pair by pair").
double automatic_detection_travel(const Blocks& blocks, bool pair_trigger = false);
// The smallest free block's size (of any block when none is free; 0 without
// blocks): what the automatic margin and detection travel scale with.
double smallest_block_size(const Blocks& blocks);

// Wall seconds spent in each stage of one detect() call.
struct DetectionTimes {
  double broad_phase = 0;
  double narrow_phase = 0;
  double patch = 0;
  double subcontacts = 0;  // assembly and history carry-over
  double gather = 0;
};

// The detection test's bound, gathered block by block where the step
// already holds each block (Simulation::step: each thread over the blocks
// it has just moved), instead of two serial passes over all the blocks at
// the next step's start. Travels are measured from a reference `ref` chosen
// before they are added (the last step's common drift, which moves little);
// clearly_no_detection() then bounds the test's own sum, taken from the
// drift c of this step's translations, by |d − c| ≤ |d − ref|₁ + |c − ref|₁
// for every travel (the fixed blocks' |c| likewise). When it answers true,
// needs_detection() answers false: the same decisions, the same runs.
struct TravelBound {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());  // translations since the detection
  Vec3 hi = -Vec3::Constant(std::numeric_limits<double>::infinity());
  double u1 = 0, u2 = 0;   // the two largest travel bounds from ref (1-norms)
  bool any_fixed = false;  // a fixed block: no translation, lo ≤ 0 ≤ hi
  bool finite = true;      // false: a bound was NaN or infinite
};
void merge_travels(TravelBound& into, const TravelBound& from);

class ContactDetector {
 public:
  // travel: the detection travel, at most half the margin (a larger one is
  // taken as half the margin); 0 = half the margin.
  ContactDetector(const Blocks& blocks, double margin, double travel = 0);
  ~ContactDetector();
  ContactDetector(const ContactDetector&) = delete;
  ContactDetector& operator=(const ContactDetector&) = delete;

  double margin() const { return margin_; }
  double travel() const { return travel_; }  // the detection travel, ≤ half the margin
  // Threads for detect()'s parallel loops (0: OpenMP's default); the step
  // passes its governor's choice (integrators/thread_governor.hpp).
  void set_threads(int threads) { threads_ = threads; }
  int threads() const { return threads_; }  // 0: not set (OpenMP's default)
  // Under the overlap joint model (contact/overlap_joint.hpp) a detection
  // hands each joint's state on by its pair, and the subcontacts only
  // sample the joint's opening.
  void set_pair_joints(bool on) { pair_joints_ = on; }
  // Pair by pair (see above): the scene's test then asks for half the
  // margin, and moved_pairs() for each pair's travel. Set before the first
  // detect().
  void set_pair_trigger(bool on) { pair_trigger_ = on; }
  // The joints' points follow the blocks between detections
  // (contact/moving_points.hpp): each point of a clipped polygon is kept
  // with what it is in the blocks' geometry. Set before the first detection.
  void set_points_follow(bool on) { points_follow_ = on; }
  // The joints clipped again at every step (contact/clip_joint.hpp): the
  // patches' polygons with coincident vertices merged and no nominal areas
  // (PatchPoints::clipped). Set with set_points_follow(true).
  void set_clipped(bool on) { clipped_ = on; }
  bool pair_trigger() const { return pair_trigger_; }
  // What the scene-wide test compares the two largest travels with: the
  // detection travel, or half the margin when pairs are re-sampled on their
  // own.
  double scene_threshold() const { return pair_trigger_ ? 0.5 * margin_ : travel_; }
  // True when some pair may have moved by more than the detection travel since
  // detect(), counting the coming step of length dt at the current speeds.
  // `bound_first`: a cheap bound settles the clear cases (the same answer;
  // false only for tests comparing the two).
  bool needs_detection(const Blocks& blocks, double dt = 0, bool bound_first = true) const;
  // The test's bound block by block (TravelBound above): blocks [begin, end)
  // but the kinematic ones, or the blocks of `list`, added into `t`, their
  // travels from `ref` with the coming step `dt`.
  void add_travels(const Blocks& blocks, int begin, int end, const Vec3& ref, double dt, TravelBound& t) const;
  void add_travels(const Blocks& blocks, const std::vector<int>& list, const Vec3& ref, double dt,
                   TravelBound& t) const;
  // True only when needs_detection(blocks, dt) would answer false, from the
  // bound `t` of every block taken from `ref`; `drift` gets this step's c.
  bool clearly_no_detection(const TravelBound& t, const Vec3& ref, Vec3& drift) const;
  // Rebuilds `contacts` for the current state, carrying history over by
  // position (carry_history). The joint law's stiffnesses price what the
  // re-sampling changes at the same pose: the shear it cannot carry
  // (`dropped_shear_energy`) and the normal strain it removes or adds
  // (`resampled_normal_energy`), so that a detection leaves the ledger's
  // balance as it was. New subcontacts start bonded when `bond_new` is set
  // (cohesion/tension at t = 0). Returns the time spent in each stage.
  // Pair by pair, detect() takes over whole (build_subcontacts) the pairs
  // whose blocks have moved relative to each other by less than the travel
  // since they were sampled.
  DetectionTimes detect(const Blocks& blocks, ContactSet& contacts, bool bond_new, const JointLaws& laws);
  // Pair by pair only: the pairs of `contacts` whose two blocks may have
  // moved relative to each other by more than the detection travel since
  // the pair was sampled, counting the coming step of length dt, into
  // `moved` (ascending). Returns whether there are any. `bound_first`: a
  // cheap bound settles the clear cases (the same answer; false only for
  // tests comparing the two).
  bool moved_pairs(const Blocks& blocks, const ContactSet& contacts, double dt, std::vector<int>& moved,
                   bool bound_first = true) const;
  // Re-samples the pairs `moved` of `contacts` (ascending), each as detect()
  // would, carrying its history by position, and takes the others over
  // whole. A moved pair no longer within the margin would leave the scene's
  // guarantee for new pairs behind (it could close again before the next
  // scene-wide search): then the whole scene is searched (detect()).
  DetectionTimes resample(const Blocks& blocks, ContactSet& contacts, const std::vector<int>& moved,
                          const JointLaws& laws);
  // Pair re-samplings so far (resample()'s pairs, and detect()'s pairs that
  // were not taken over whole).
  long long pairs_resampled() const { return pairs_resampled_; }
  // Pair by pair, after a detect() or resample(): per pair of the set, the
  // pair of the set before it was taken over whole from, or -1 for a pair
  // sampled (or new). Without the pair trigger every pair is sampled.
  const std::vector<int>& pair_origin() const;
  // Pair by pair: the pairs `pairs` of `contacts` count as sampled at the
  // blocks' poses now (their travel starts afresh): joint_sampling = "clip"
  // has clipped them again at this pose.
  void restart_pair_travel(const Blocks& blocks, const ContactSet& contacts, const std::vector<int>& pairs);

  // Checkpoints: the poses at the last detection (they decide when the next
  // one runs). Nothing else carries over: the contacts of the detection
  // before (`previous` inside) are only read during detect(), which swaps the
  // current set in as the history and rebuilds every array it hands back,
  // and the FCL tree is refitted to exact boxes at each detection and its
  // pairs are sorted, so a tree rebuilt after a restart finds the same ones.
  // Pair by pair, also each pair's poses when it was sampled (`pairs`: the
  // checkpoint's contact pairs, loaded before).
  void save(ByteWriter& w) const;
  void load(ByteReader& r, std::size_t pairs = 0);

 private:
  bool travels_clearly_below(const Blocks& blocks, const Vec3& drift, bool any_fixed, double dt,
                             double threshold) const;
  // Stages 2-3 for the candidates to sample (im.todo), against `current`'s
  // planes; stages 4-5 (sample) from them and the pairs taken over whole
  // (im.kept ≥ 0), the history carried from the previous set; pair by pair,
  // the pairs' poses, history and ledger (take_pair_poses, carry_and_hold)
  // and a re-sampling in place (resample_in_place).
  void narrow_phase_and_patches(const Blocks& blocks, const ContactSet& current, DetectionTimes& times);
  void sample(const Blocks& blocks, ContactSet& contacts, bool bond_new, const JointLaws& laws, bool scene,
              DetectionTimes& times);
  void take_pair_poses(const Blocks& blocks, const ContactSet& old);
  void carry_and_hold(const Blocks& blocks, const ContactSet& old, ContactSet& contacts, const JointLaws& laws,
                      int threads);
  void resample_in_place(const Blocks& blocks, ContactSet& contacts, const std::vector<int>& moved,
                         const JointLaws& laws, DetectionTimes& times);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  double margin_;
  double travel_;
  int threads_ = 0;
  bool pair_joints_ = false;
  bool pair_trigger_ = false;
  bool points_follow_ = false;
  bool clipped_ = false;
  long long pairs_resampled_ = 0;
};

}  // namespace polydem
