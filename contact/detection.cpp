#include "contact/detection.hpp"

#include "contact/overlap_joint.hpp"

#include "contact/broad_phase.hpp"
#include "contact/contact_patch.hpp"
#include "contact/gather.hpp"
#include "contact/narrow_phase.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace polydem {

struct ContactDetector::Impl {
  explicit Impl(int n) : blocks(n), broad(n) {}
  int blocks;
  BroadPhase broad;
  std::vector<std::pair<int, int>> candidates;
  std::vector<NarrowPhaseHit> hits;
  std::vector<Patch> patches;
  std::vector<char> found;
  std::vector<PatchScratch> scratch;
  std::vector<Vec3> detected_position;
  std::vector<Quat> detected_orientation;
  ContactSet previous;
  std::vector<int> count;
  CarryScratch carry;
  OverlapScratch overlap;
};

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

double l1(const Vec3& v) { return std::abs(v.x()) + std::abs(v.y()) + std::abs(v.z()); }

void keep_two_largest(double u, double& u1, double& u2) {
  if (u > u1) {
    u2 = u1;
    u1 = u;
  } else if (u > u2) {
    u2 = u;
  }
}

// A 1-norm bound of block i's travel since the detection (at p0, q0),
// measured from `from`, with the coming step dt (why it bounds the travel:
// travels_clearly_below).
double travel_l1(const Blocks& b, const Vec3& p0, const Quat& q0, int i, const Vec3& from, double dt) {
  const Quat& q = b.state.orientation[i];
  const double minus = std::abs(q.x() - q0.x()) + std::abs(q.y() - q0.y()) + std::abs(q.z() - q0.z()) +
                       std::abs(q.w() - q0.w());
  const double plus = std::abs(q.x() + q0.x()) + std::abs(q.y() + q0.y()) + std::abs(q.z() + q0.z()) +
                      std::abs(q.w() + q0.w());
  const double radius = b.props.radius[i];
  return l1(b.state.position[i] - p0 - from) + 2.0 * std::min(minus, plus) * radius +
         dt * (l1(b.state.velocity[i]) + l1(b.state.angular_velocity[i]) * radius);
}

// The chord block i's rotation since the detection (q0) swept at its
// bounding radius, 2·|sin(θ/2)|·r: the farthest any of its points has moved
// by turning. |vec(q·q0*)| = |sin(θ/2)|.
double turn_chord(const Blocks& b, const Quat& q0, int i) {
  const Quat dq = b.state.orientation[i] * q0.conjugate();
  return 2.0 * dq.vec().norm() * b.props.radius[i];
}

PosedBlock posed(const Blocks& b, int i) {
  return {&b.props.local_shape[i], b.state.rotation[i], b.state.position[i], b.props.size[i]};
}

}  // namespace

double smallest_block_size(const Blocks& b) {
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < b.count; ++i)
    if (b.props.motion[i] != BlockMotion::fixed) smallest = std::min(smallest, b.props.size[i]);
  if (!std::isfinite(smallest))
    for (int i = 0; i < b.count; ++i) smallest = std::min(smallest, b.props.size[i]);
  return std::isfinite(smallest) ? smallest : 0.0;
}

double automatic_detection_travel(const Blocks& b) { return 0.0025 * smallest_block_size(b); }

ContactDetector::ContactDetector(const Blocks& blocks, double margin, double travel)
    : impl_(std::make_unique<Impl>(blocks.count)),
      margin_(margin),
      travel_(travel > 0 ? std::min(travel, 0.5 * margin) : 0.5 * margin) {
  auto& im = *impl_;
  im.scratch.resize(std::max(1, omp_get_max_threads()));
  im.detected_position = blocks.state.position;
  im.detected_orientation = blocks.state.orientation;
}

ContactDetector::~ContactDetector() = default;

// A bound on how much any pair can have closed since the last detection
// (see the header): each block's travel is measured from a common reference
// c (the centre of the box of all translations), so that a pair's closure
// |d_i − d_j| + turn_i + turn_j is at most R_i + R_j with
// R_i = |d_i − c| + turn_i + (the step about to be taken, |v|·dt + |ω|·r·dt).
// The two largest R decide. Two serial passes over the blocks; bitwise the
// same on any thread count (max and min only).
bool ContactDetector::needs_detection(const Blocks& b, double dt, bool bound_first) const {
  const auto& im = *impl_;
  const int n = b.count;
  const auto& motion = b.props.motion;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  bool any_fixed = false;
  for (int i = 0; i < n; ++i) {
    if (motion[i] == BlockMotion::fixed) {
      any_fixed = true;  // no translation
      lo = lo.cwiseMin(Vec3::Zero());
      hi = hi.cwiseMax(Vec3::Zero());
      continue;
    }
    const Vec3 d = b.state.position[i] - im.detected_position[i];
    lo = lo.cwiseMin(d);
    hi = hi.cwiseMax(d);
  }
  if (n == 0) return false;
  const Vec3 c = 0.5 * (lo + hi);
  const double threshold = travel_;
  if (bound_first && travels_clearly_below(b, c, any_fixed, dt, threshold)) return false;
  double r1 = any_fixed ? c.norm() : 0.0, r2 = 0;  // a fixed block's travel from c
  for (int i = 0; i < n; ++i) {
    if (motion[i] == BlockMotion::fixed) continue;
    const double turn = turn_chord(b, im.detected_orientation[i], i);
    const double ahead =
        dt * (b.state.velocity[i].norm() + b.state.angular_velocity[i].norm() * b.props.radius[i]);
    const double r = (b.state.position[i] - im.detected_position[i] - c).norm() + turn + ahead;
    keep_two_largest(r, r1, r2);
  }
  return r1 + r2 > threshold;
}

// Most steps no pair is near half the margin, and a bound settles it without
// the travels' square roots and quaternion products. Each travel is bounded
// by the same sum with 1-norms (|x| ≤ |x|₁) and the turn's |vec(q·q₀*)| =
// sin(θ/2) by min(|q − q₀|₁, |q + q₀|₁) (for unit quaternions with
// c = q·q₀: 1 − c² ≤ 2(1 ∓ c) = |q ∓ q₀|²). If the two largest bounds add up
// to less than the threshold by a relative 1e-6 — far beyond the round-off of
// either sum — the exact test (needs_detection) answers no as well, so the
// answer, and every result, is the same; otherwise the exact test runs.
bool ContactDetector::travels_clearly_below(const Blocks& b, const Vec3& c, bool any_fixed, double dt,
                                            double threshold) const {
  const auto& im = *impl_;
  const auto& motion = b.props.motion;
  double u1 = any_fixed ? l1(c) : 0.0, u2 = 0;
  for (int i = 0; i < b.count; ++i) {
    if (motion[i] == BlockMotion::fixed) continue;
    const double u = travel_l1(b, im.detected_position[i], im.detected_orientation[i], i, c, dt);
    if (!(u <= std::numeric_limits<double>::max())) return false;  // NaN or infinite: the exact test decides
    keep_two_largest(u, u1, u2);
  }
  return u1 + u2 < threshold * (1.0 - 1e-6);
}

namespace {

// Block i's part of the bound (a block that is not fixed): its translation
// since the detection into the box, and its travel's bound from `ref`.
inline void add_travel(const Blocks& b, const Vec3& p0, const Quat& q0, int i, const Vec3& ref, double dt,
                       TravelBound& t) {
  const Vec3 d = b.state.position[i] - p0;
  t.lo = t.lo.cwiseMin(d);
  t.hi = t.hi.cwiseMax(d);
  const double u = travel_l1(b, p0, q0, i, ref, dt);
  if (!(u <= std::numeric_limits<double>::max())) t.finite = false;  // NaN or infinite
  keep_two_largest(u, t.u1, t.u2);
}

}  // namespace

void merge_travels(TravelBound& into, const TravelBound& from) {
  into.lo = into.lo.cwiseMin(from.lo);
  into.hi = into.hi.cwiseMax(from.hi);
  keep_two_largest(from.u1, into.u1, into.u2);
  keep_two_largest(from.u2, into.u1, into.u2);
  into.any_fixed = into.any_fixed || from.any_fixed;
  into.finite = into.finite && from.finite;
}

void ContactDetector::add_travels(const Blocks& b, int begin, int end, const Vec3& ref, double dt,
                                  TravelBound& t) const {
  const auto& im = *impl_;
  const auto& motion = b.props.motion;
  for (int i = begin; i < end; ++i) {
    if (motion[i] == BlockMotion::fixed) {
      t.any_fixed = true;
      continue;
    }
    if (motion[i] == BlockMotion::kinematic) continue;  // moved after the step's threads: add_travels(list)
    add_travel(b, im.detected_position[i], im.detected_orientation[i], i, ref, dt, t);
  }
}

void ContactDetector::add_travels(const Blocks& b, const std::vector<int>& list, const Vec3& ref, double dt,
                                  TravelBound& t) const {
  const auto& im = *impl_;
  for (int i : list) add_travel(b, im.detected_position[i], im.detected_orientation[i], i, ref, dt, t);
}

// The test's sum is r₁ + r₂ over r_i = |d_i − c| + turn_i + ahead_i (and |c|
// for the fixed blocks); each is at most the bound from ref plus
// δ = |c − ref|₁, so r₁ + r₂ ≤ u₁ + u₂ + 2δ. The relative 1e-6 is the
// round-off margin of travels_clearly_below.
bool ContactDetector::clearly_no_detection(const TravelBound& t, const Vec3& ref, Vec3& drift) const {
  drift = ref;
  if (!t.finite) return false;
  Vec3 lo = t.lo, hi = t.hi;
  if (t.any_fixed) {
    lo = lo.cwiseMin(Vec3::Zero());
    hi = hi.cwiseMax(Vec3::Zero());
  }
  if (!(lo.x() <= hi.x())) return true;  // no block: nothing can close (needs_detection: false)
  const Vec3 c = 0.5 * (lo + hi);
  const double delta = l1(c - ref);
  if (!(delta <= std::numeric_limits<double>::max())) return false;
  drift = c;
  double u1 = t.u1, u2 = t.u2;
  if (t.any_fixed) keep_two_largest(l1(ref), u1, u2);
  return u1 + u2 + 2.0 * delta < travel_ * (1.0 - 1e-6);
}

DetectionTimes ContactDetector::detect(const Blocks& b, ContactSet& contacts, bool bond_new, const JointLaws& laws) {
  auto& im = *impl_;
  DetectionTimes times;
  const Clock::time_point t0 = Clock::now();

  // 1. Broad phase.
  im.broad.find_pairs(b, 0.5 * margin_, im.candidates);
  const Clock::time_point t1 = Clock::now();

  // The previous contacts become the history to carry over.
  std::swap(im.previous, contacts);
  const ContactSet& old = im.previous;

  // 2. Narrow phase, in parallel, one slot per candidate.
  const int nc = static_cast<int>(im.candidates.size());
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
  im.hits.resize(nc);
  im.patches.resize(nc);
  im.found.assign(nc, 0);
#pragma omp parallel for schedule(dynamic, 16) if (nc >= 64) num_threads(threads)
  for (int k = 0; k < nc; ++k) {
    const auto [i, j] = im.candidates[k];
    const PosedBlock pa = posed(b, i), pb = posed(b, j);
    PatchScratch& s = im.scratch[omp_get_thread_num()];
    world_vertices(pa, s.world_a);
    world_vertices(pb, s.world_b);
    im.found[k] = narrow_phase(s.world_a, pa.x, s.world_b, pb.x, margin_, im.hits[k]);
  }
  const Clock::time_point t2 = Clock::now();

  // 3. Patches for the pairs within the margin, in parallel, keeping each
  // pair's previous common plane while it is still nearly the best.
#pragma omp parallel for schedule(dynamic, 16) if (nc >= 64) num_threads(threads)
  for (int k = 0; k < nc; ++k) {
    if (!im.found[k]) continue;
    const auto [i, j] = im.candidates[k];
    int prev_side = -1, prev_face = -1;
    if (const ContactPair* op = find_pair(old, i, j)) {
      prev_side = op->ref_block == i ? 0 : 1;
      prev_face = op->ref_face;
    }
    im.found[k] = build_patch(posed(b, i), posed(b, j), margin_, im.hits[k], prev_side, prev_face, im.patches[k],
                              im.scratch[omp_get_thread_num()], pair_joints_);
  }
  const Clock::time_point t3 = Clock::now();

  // 4. Subcontacts in candidate order (sorted by block pair), with the
  // history of the detection before, carried by position on the joint.
  build_subcontacts(b, im.candidates, im.patches, im.found, bond_new, contacts);
  if (bond_new) {  // only the joints whose law has a strength start bonded
    for (std::size_t s = 0; s < contacts.sub.size(); ++s)
      if (!laws.between(contacts.sub.ref_block[s], contacts.sub.inc_block[s]).bonds()) contacts.sub.bonded[s] = 0;
  }
  if (pair_joints_) {  // the overlap model: each joint's history goes with its pair
    carry_pair_joints(old, contacts);
    rechoose_joint_planes(b.props.local_shape, b.state, contacts.pairs, contacts.joints, im.overlap);
    find_joint_cells(b.props.local_shape, b.state, contacts.pairs, contacts.sub, margin_, contacts.joints,
                     im.overlap);
  } else {
    // How far each block has moved since the previous detection: the
    // reach of a pair's history (carry_history).
    im.carry.moved.resize(static_cast<std::size_t>(b.count));
    im.carry.turned.resize(static_cast<std::size_t>(b.count));
    for (int i = 0; i < b.count; ++i) {
      im.carry.moved[i] = b.state.position[i] - im.detected_position[i];
      im.carry.turned[i] = turn_chord(b, im.detected_orientation[i], i);
    }
    carry_history(b, old, contacts, laws, im.carry, threads);
    // Re-sampling may lower a pair's normal strain at this pose but not
    // raise it (joint_law.hpp); what it changes is the re-sampling's, not
    // motion's, and goes to the ledger.
    hold_normal_strain(laws, b.state, old, contacts, threads);
    contacts.resampled_normal_energy += normal_strain_energy_now(laws, b.state, old.sub, threads) -
                                        normal_strain_energy_now(laws, b.state, contacts.sub, threads);
  }
  contacts.detections = old.detections + 1;
  const Clock::time_point t4 = Clock::now();

  // 5. Gather lists: per block, its subcontacts in subcontact order.
  build_gather_lists(b.count, contacts, im.count);

  im.detected_position = b.state.position;
  im.detected_orientation = b.state.orientation;
  const Clock::time_point t5 = Clock::now();
  times.broad_phase = seconds(t0, t1);
  times.narrow_phase = seconds(t1, t2);
  times.patch = seconds(t2, t3);
  times.subcontacts = seconds(t3, t4);
  times.gather = seconds(t4, t5);
  return times;
}

void ContactDetector::save(ByteWriter& w) const {
  w.put(impl_->detected_position);
  w.put(impl_->detected_orientation);
}

void ContactDetector::load(ByteReader& r) {
  const auto n = static_cast<std::size_t>(impl_->blocks);
  r.get_sized(impl_->detected_position, n, "detector.detected_position");
  r.get_sized(impl_->detected_orientation, n, "detector.detected_orientation");
}

}  // namespace polydem
