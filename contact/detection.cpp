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

// The poses of a pair's two blocks (a, b as the pair's) when it was sampled.
struct PairPose {
  Vec3 pa, pb;
  Quat qa, qb;
};

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
  // Pair by pair only. Per candidate: the previous set's pair taken over
  // whole, or −1; the candidates to sample.
  std::vector<int> kept;
  std::vector<int> todo;
  // Per pair of the current set: its blocks' poses when it was sampled,
  // and the same being built for the next set.
  std::vector<PairPose> pose, next_pose;
  // Per pair of the current set: the previous set's pair it was taken over
  // whole from, or -1 (pair_origin()).
  std::vector<int> origin;
  // moved_pairs() on several threads: each thread's moved pairs.
  std::vector<std::vector<int>> moved_parts;
  // Per pair of the current set, under "clip": a pair resample() was asked
  // to sample (its clip found it stale), which a scene-wide detect()
  // standing in for it must not take over whole (empty: none).
  std::vector<char> must_sample;
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

// A bound of the chord block i's rotation since q0 swept at its bounding
// radius (turn_chord below): 2·min(|q − q0|₁, |q + q0|₁)·r, without a
// quaternion product (why it bounds it: travels_clearly_below).
double turn_bound(const Blocks& b, const Quat& q0, int i) {
  const Quat& q = b.state.orientation[i];
  const double minus = std::abs(q.x() - q0.x()) + std::abs(q.y() - q0.y()) + std::abs(q.z() - q0.z()) +
                       std::abs(q.w() - q0.w());
  const double plus = std::abs(q.x() + q0.x()) + std::abs(q.y() + q0.y()) + std::abs(q.z() + q0.z()) +
                      std::abs(q.w() + q0.w());
  return 2.0 * std::min(minus, plus) * b.props.radius[i];
}

// A 1-norm bound of block i's travel since the detection (at p0, q0),
// measured from `from`, with the coming step dt (why it bounds the travel:
// travels_clearly_below).
double travel_l1(const Blocks& b, const Vec3& p0, const Quat& q0, int i, const Vec3& from, double dt) {
  const double radius = b.props.radius[i];
  return l1(b.state.position[i] - p0 - from) + turn_bound(b, q0, i) +
         dt * (l1(b.state.velocity[i]) + l1(b.state.angular_velocity[i]) * radius);
}

// The chord block i's rotation since the detection (q0) swept at its
// bounding radius, 2·|sin(θ/2)|·r: the farthest any of its points has moved
// by turning. |vec(q·q0*)| = |sin(θ/2)|.
double turn_chord(const Blocks& b, const Quat& q0, int i) {
  const Quat dq = b.state.orientation[i] * q0.conjugate();
  return 2.0 * dq.vec().norm() * b.props.radius[i];
}

// How far any point of block a may have moved relative to any point of
// block b since the poses (pa, qa), (pb, qb), counting the coming step dt:
// the relative translation, the chords of both rotations at their bounding
// radii, and the step at the current speeds.
double pair_travel(const Blocks& b, int a, int c, const PairPose& p, double dt) {
  const auto& st = b.state;
  const double ra = b.props.radius[a], rc = b.props.radius[c];
  double u = ((st.position[a] - p.pa) - (st.position[c] - p.pb)).norm() + turn_chord(b, p.qa, a) +
             turn_chord(b, p.qb, c);
  if (dt > 0)
    u += dt * ((st.velocity[a] - st.velocity[c]).norm() + st.angular_velocity[a].norm() * ra +
               st.angular_velocity[c].norm() * rc);
  return u;
}

// A 1-norm bound of pair_travel, without its square roots and quaternion
// products (each 2-norm below its 1-norm, the turns' |sin(θ/2)| below
// min(|q − q₀|₁, |q + q₀|₁) as in travels_clearly_below).
double pair_travel_bound(const Blocks& b, int a, int c, const PairPose& p, double dt) {
  const auto& st = b.state;
  double u = l1((st.position[a] - p.pa) - (st.position[c] - p.pb)) + turn_bound(b, p.qa, a) + turn_bound(b, p.qb, c);
  if (dt > 0)
    u += dt * (l1(st.velocity[a] - st.velocity[c]) + l1(st.angular_velocity[a]) * b.props.radius[a] +
               l1(st.angular_velocity[c]) * b.props.radius[c]);
  return u;
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

double automatic_detection_travel(const Blocks& b, bool pair_trigger) {
  return (pair_trigger ? 0.0025 / 16 : 0.0025) * smallest_block_size(b);
}

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
  const double threshold = scene_threshold();
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
  return u1 + u2 + 2.0 * delta < scene_threshold() * (1.0 - 1e-6);
}

DetectionTimes ContactDetector::detect(const Blocks& b, ContactSet& contacts, bool bond_new, const JointLaws& laws) {
  auto& im = *impl_;
  DetectionTimes times;
  const Clock::time_point t0 = Clock::now();

  // 1. Broad phase.
  im.broad.find_pairs(b, 0.5 * margin_, im.candidates);
  const Clock::time_point t1 = Clock::now();
  times.broad_phase = seconds(t0, t1);

  // Pair by pair, the pairs whose blocks have not moved by the travel since
  // they were sampled are taken over whole; the rest are sampled.
  const int nc = static_cast<int>(im.candidates.size());
  im.todo.clear();
  if (pair_trigger_ && im.pose.size() == contacts.pairs.size()) {
    im.kept.assign(static_cast<std::size_t>(nc), -1);
    for (int k = 0; k < nc; ++k) {
      const auto [i, j] = im.candidates[k];
      if (const ContactPair* op = find_pair(contacts, i, j)) {
        const std::size_t o = static_cast<std::size_t>(op - contacts.pairs.data());
        if (pair_travel(b, i, j, im.pose[o], 0.0) <= travel_ &&
            !(static_cast<std::size_t>(o) < im.must_sample.size() && im.must_sample[static_cast<std::size_t>(o)])) {
          im.kept[static_cast<std::size_t>(k)] = static_cast<int>(o);
          continue;
        }
      }
      im.todo.push_back(k);
    }
  } else {
    im.kept.assign(pair_trigger_ ? static_cast<std::size_t>(nc) : 0, -1);
    im.todo.resize(static_cast<std::size_t>(nc));
    for (int k = 0; k < nc; ++k) im.todo[static_cast<std::size_t>(k)] = k;
  }

  // 2-3. Narrow phase and patches, against the current set's planes.
  narrow_phase_and_patches(b, contacts, times);

  // The previous contacts become the history to carry over.
  std::swap(im.previous, contacts);
  sample(b, contacts, bond_new, laws, true, times);
  return times;
}

bool ContactDetector::moved_pairs(const Blocks& b, const ContactSet& contacts, double dt, std::vector<int>& moved,
                                  bool bound_first) const {
  auto& im = *impl_;
  moved.clear();
  const std::size_t np = contacts.pairs.size();
  if (im.pose.size() != np) {  // a set this detector did not build: all of it
    for (std::size_t q = 0; q < np; ++q) moved.push_back(static_cast<int>(q));
    return np > 0;
  }
  // Most pairs are settled by the bound (below the travel by a relative
  // 1e-6, far beyond either sum's round-off: the exact test answers the
  // same); the rest by the exact test.
  const double clear = travel_ * (1.0 - 1e-6);
  auto test = [&](std::size_t begin, std::size_t end, std::vector<int>& out) {
    for (std::size_t q = begin; q < end; ++q) {
      const ContactPair& p = contacts.pairs[q];
      if (bound_first && pair_travel_bound(b, p.a, p.b, im.pose[q], dt) < clear) continue;
      if (!(pair_travel(b, p.a, p.b, im.pose[q], dt) <= travel_))
        out.push_back(static_cast<int>(q));  // NaN too: sampled again, the guard judges the state
    }
  };
  // On the step's threads, each a contiguous run of pairs, their lists
  // joined in thread order: ascending, as one thread would give them.
  const int threads = threads_ > 1 ? threads_ : 1;  // the step's choice (set_threads)
  if (threads == 1) {
    test(0, np, moved);
    return !moved.empty();
  }
  if (im.moved_parts.size() < static_cast<std::size_t>(threads))
    im.moved_parts.resize(static_cast<std::size_t>(threads));
  int ran = 1;
#pragma omp parallel num_threads(threads)
  {
    const auto nt = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<int>& out = im.moved_parts[t];
    out.clear();
    test(np * t / nt, np * (t + 1) / nt, out);
#pragma omp master
    ran = static_cast<int>(nt);
  }
  for (int t = 0; t < ran; ++t) {
    const std::vector<int>& part = im.moved_parts[static_cast<std::size_t>(t)];
    moved.insert(moved.end(), part.begin(), part.end());
  }
  return !moved.empty();
}

DetectionTimes ContactDetector::resample(const Blocks& b, ContactSet& contacts, const std::vector<int>& moved,
                                         const JointLaws& laws) {
  auto& im = *impl_;
  DetectionTimes times;
  const std::size_t np = contacts.pairs.size();
  im.candidates.resize(np);
  im.kept.resize(np);
  for (std::size_t q = 0; q < np; ++q) {
    im.candidates[q] = {contacts.pairs[q].a, contacts.pairs[q].b};
    im.kept[q] = static_cast<int>(q);
  }
  im.todo = moved;
  for (int q : moved) im.kept[static_cast<std::size_t>(q)] = -1;
  narrow_phase_and_patches(b, contacts, times);
  bool in_place = true;
  for (int k : im.todo) {
    const auto q = static_cast<std::size_t>(k);
    if (!im.found[q]) {  // a pair has left: the scene searched (under "clip", the pairs asked for sampled)
      im.must_sample.assign(clipped_ ? np : 0, 0);
      if (clipped_)
        for (int m : moved) im.must_sample[static_cast<std::size_t>(m)] = 1;
      const DetectionTimes t = detect(b, contacts, false, laws);
      im.must_sample.clear();
      return t;
    }
    const ContactPair& cp = contacts.pairs[q];
    const Patch& patch = im.patches[q];
    in_place = in_place && static_cast<int>(patch.points.size()) == cp.count &&
               (patch.ref_side == 0 ? cp.a : cp.b) == cp.ref_block;
  }
  if (in_place) {
    resample_in_place(b, contacts, moved, laws, times);
    return times;
  }
  std::swap(im.previous, contacts);
  sample(b, contacts, false, laws, false, times);
  return times;
}

// Every moved pair sampled again with as many subcontacts as it had and
// the same reference block: their new subcontacts go where the old ones
// were, so the set's layout and gather lists stay as they are and nothing
// else is copied. The old subcontacts of the moved pairs, kept aside as a
// small set, are the history carried, as sample() would carry it.
void ContactDetector::resample_in_place(const Blocks& b, ContactSet& contacts, const std::vector<int>& moved,
                                        const JointLaws& laws, DetectionTimes& times) {
  auto& im = *impl_;
  const Clock::time_point t3 = Clock::now();
  ContactSet& old = im.previous;
  old.pairs.clear();
  old.sub.resize(0);
  for (int q : moved) append_pairs(contacts, q, q + 1, old);
  old.retired_slip_energy = contacts.retired_slip_energy;
  old.retired_damping_energy = contacts.retired_damping_energy;
  old.dropped_shear_energy = contacts.dropped_shear_energy;
  old.resampled_normal_energy = contacts.resampled_normal_energy;
  old.detections = contacts.detections;
  im.carry.by_pair = true;
  im.carry.sampled = moved;
  im.carry.old_kept.clear();
  im.carry.reach.resize(contacts.pairs.size());
  const auto& st = b.state;
  for (std::size_t m = 0; m < moved.size(); ++m) {
    const auto q = static_cast<std::size_t>(moved[m]);
    ContactPair& cp = contacts.pairs[q];
    const int a = cp.a, c = cp.b;
    im.carry.reach[q] = pair_travel(b, a, c, im.pose[q], 0.0);
    ContactPair fresh;
    sample_pair(b, a, c, im.patches[q], false, static_cast<int>(q), cp.first, fresh, contacts.sub);
    cp = fresh;
    im.pose[q] = {st.position[a], st.position[c], st.orientation[a], st.orientation[c]};
  }
  pairs_resampled_ += static_cast<long long>(moved.size());
  im.origin.resize(contacts.pairs.size());
  for (std::size_t q = 0; q < im.origin.size(); ++q) im.origin[q] = static_cast<int>(q);
  for (int q : moved) im.origin[static_cast<std::size_t>(q)] = -1;
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
  carry_and_hold(b, old, contacts, laws, threads);
  times.subcontacts = seconds(t3, Clock::now());
}

// Stages 2 and 3 for the candidates im.todo, in parallel, one slot per
// candidate; `current` is the set in use (each pair keeps its common plane
// while it is still nearly the best).
void ContactDetector::narrow_phase_and_patches(const Blocks& b, const ContactSet& current, DetectionTimes& times) {
  auto& im = *impl_;
  const Clock::time_point t1 = Clock::now();
  const std::size_t nc = im.candidates.size();
  const int nt = static_cast<int>(im.todo.size());
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
  im.hits.resize(nc);
  im.patches.resize(nc);
  im.found.assign(nc, 0);
#pragma omp parallel for schedule(dynamic, 16) if (nt >= 64) num_threads(threads)
  for (int t = 0; t < nt; ++t) {
    const int k = im.todo[static_cast<std::size_t>(t)];
    const auto [i, j] = im.candidates[k];
    const PosedBlock pa = posed(b, i), pb = posed(b, j);
    PatchScratch& s = im.scratch[omp_get_thread_num()];
    world_vertices(pa, s.world_a);
    world_vertices(pb, s.world_b);
    im.found[k] = narrow_phase(s.world_a, pa.x, s.world_b, pb.x, margin_, im.hits[k]);
  }
  const Clock::time_point t2 = Clock::now();

#pragma omp parallel for schedule(dynamic, 16) if (nt >= 64) num_threads(threads)
  for (int t = 0; t < nt; ++t) {
    const int k = im.todo[static_cast<std::size_t>(t)];
    if (!im.found[k]) continue;
    const auto [i, j] = im.candidates[k];
    int prev_side = -1, prev_face = -1, prev_inc = -1;
    if (const ContactPair* op = find_pair(current, i, j)) {
      prev_side = op->ref_block == i ? 0 : 1;
      prev_face = op->ref_face;
      prev_inc = op->inc_face;
    }
    im.found[k] = build_patch(posed(b, i), posed(b, j), margin_, im.hits[k], prev_side, prev_face, im.patches[k],
                              im.scratch[omp_get_thread_num()], pair_joints_,
                              clipped_         ? PatchPoints::clipped
                              : points_follow_ ? PatchPoints::following
                                               : PatchPoints::detection,
                              prev_inc);
  }
  const Clock::time_point t3 = Clock::now();
  times.narrow_phase = seconds(t1, t2);
  times.patch = seconds(t2, t3);
}

// Stages 4 and 5: the new set from the candidates' patches (and, pair by
// pair, the pairs taken over whole), the history carried from im.previous.
// `scene`: a scene-wide detection (it counts, and the scene's test measures
// travels from here on).
void ContactDetector::sample(const Blocks& b, ContactSet& contacts, bool bond_new, const JointLaws& laws, bool scene,
                             DetectionTimes& times) {
  auto& im = *impl_;
  const Clock::time_point t3 = Clock::now();
  const ContactSet& old = im.previous;
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();

  // 4. Subcontacts in candidate order (sorted by block pair), with the
  // history of the detection before, carried by position on the joint.
  contacts.sub.moving.on = points_follow_;
  build_subcontacts(b, im.candidates, im.patches, im.found, bond_new, contacts, &old,
                    pair_trigger_ ? &im.kept : nullptr);
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
    if (pair_trigger_) {
      // Each pair's reach is its own blocks' motion since it was sampled.
      take_pair_poses(b, old);
    } else {
      // How far each block has moved since the previous detection: the
      // reach of a pair's history (carry_history).
      im.carry.moved.resize(static_cast<std::size_t>(b.count));
      im.carry.turned.resize(static_cast<std::size_t>(b.count));
      for (int i = 0; i < b.count; ++i) {
        im.carry.moved[i] = b.state.position[i] - im.detected_position[i];
        im.carry.turned[i] = turn_chord(b, im.detected_orientation[i], i);
      }
    }
    carry_and_hold(b, old, contacts, laws, threads);
  }
  if (!pair_trigger_ || pair_joints_) im.origin.assign(contacts.pairs.size(), -1);
  contacts.detections = old.detections + (scene ? 1 : 0);
  const Clock::time_point t4 = Clock::now();

  // 5. Gather lists: per block, its subcontacts in subcontact order.
  build_gather_lists(b.count, contacts, im.count);

  if (scene) {
    im.detected_position = b.state.position;
    im.detected_orientation = b.state.orientation;
  }
  const Clock::time_point t5 = Clock::now();
  times.subcontacts = seconds(t3, t4);
  times.gather = seconds(t4, t5);
}

// The history of `old` carried into `contacts` by position, the normal
// strain held, and what the re-sampling changed booked: for every pair, or
// pair by pair for the pairs sampled (im.carry) and the pairs gone.
void ContactDetector::carry_and_hold(const Blocks& b, const ContactSet& old, ContactSet& contacts,
                                     const JointLaws& laws, int threads) {
  auto& im = *impl_;
  carry_history(b, old, contacts, laws, im.carry, threads);
  // Re-sampling may lower a pair's normal strain at this pose but not
  // raise it (joint_law.hpp); what it changes is the re-sampling's, not
  // motion's, and goes to the ledger.
  hold_normal_strain(laws, b.state, old, contacts, threads, pair_trigger_ ? &im.carry.sampled : nullptr);
  if (!pair_trigger_) {
    contacts.resampled_normal_energy += normal_strain_energy_now(laws, b.state, old.sub, threads) -
                                        normal_strain_energy_now(laws, b.state, contacts.sub, threads);
    return;
  }
  double change = 0;  // the same difference over the pairs sampled and the pairs gone (the rest cancel)
  for (int q : im.carry.sampled) {
    const ContactPair& cp = contacts.pairs[static_cast<std::size_t>(q)];
    change -= normal_strain_energy_now(laws, b.state, contacts.sub, cp.first, cp.first + cp.count);
  }
  const bool some_kept = !im.carry.old_kept.empty();
  for (std::size_t o = 0; o < old.pairs.size(); ++o) {
    if (some_kept && im.carry.old_kept[o]) continue;
    const ContactPair& op = old.pairs[o];
    change += normal_strain_energy_now(laws, b.state, old.sub, op.first, op.first + op.count);
  }
  contacts.resampled_normal_energy += change;
}

// Pair by pair: per pair of the new set (built in candidate order from the
// kept and the found candidates), whether it was taken over whole, its
// reach since it was sampled, and the poses it was sampled at (the kept
// pairs' own, the others' now).
void ContactDetector::take_pair_poses(const Blocks& b, const ContactSet& old) {
  auto& im = *impl_;
  const auto& st = b.state;
  const std::size_t nc = im.candidates.size();
  im.carry.by_pair = true;
  im.carry.sampled.clear();
  im.carry.reach.clear();
  im.carry.old_kept.assign(old.pairs.size(), 0);
  im.next_pose.clear();
  im.origin.clear();
  for (std::size_t k = 0; k < nc; ++k) {
    const int o = im.kept[k];
    if (o < 0 && !im.found[k]) continue;
    const auto [i, j] = im.candidates[k];
    im.origin.push_back(o);
    if (o >= 0) {
      const auto u = static_cast<std::size_t>(o);
      im.carry.old_kept[u] = 1;
      im.carry.reach.push_back(0.0);
      im.next_pose.push_back(im.pose[u]);
      continue;
    }
    double reach = 0;
    if (const ContactPair* op = find_pair(old, i, j)) {
      const auto u = static_cast<std::size_t>(op - old.pairs.data());
      reach = pair_travel(b, i, j, im.pose[u], 0.0);
    }
    im.carry.sampled.push_back(static_cast<int>(im.carry.reach.size()));
    im.carry.reach.push_back(reach);
    im.next_pose.push_back({st.position[i], st.position[j], st.orientation[i], st.orientation[j]});
    ++pairs_resampled_;
  }
  std::swap(im.pose, im.next_pose);
}

const std::vector<int>& ContactDetector::pair_origin() const { return impl_->origin; }

void ContactDetector::restart_pair_travel(const Blocks& b, const ContactSet& contacts,
                                          const std::vector<int>& pairs) {
  auto& im = *impl_;
  if (im.pose.size() != contacts.pairs.size()) return;  // not pair by pair
  const auto& st = b.state;
  for (int q : pairs) {
    const ContactPair& p = contacts.pairs[static_cast<std::size_t>(q)];
    im.pose[static_cast<std::size_t>(q)] = {st.position[p.a], st.position[p.b], st.orientation[p.a],
                                            st.orientation[p.b]};
  }
}

void ContactDetector::save(ByteWriter& w) const {
  const auto& im = *impl_;
  w.put(im.detected_position);
  w.put(im.detected_orientation);
  if (!pair_trigger_) return;
  // Each field as an array of its own (the checkpoint's format).
  std::vector<Vec3> pa, pb;
  std::vector<Quat> qa, qb;
  for (const PairPose& p : im.pose) {
    pa.push_back(p.pa);
    pb.push_back(p.pb);
    qa.push_back(p.qa);
    qb.push_back(p.qb);
  }
  w.put(pa);
  w.put(pb);
  w.put(qa);
  w.put(qb);
  w.put(static_cast<std::int64_t>(pairs_resampled_));
}

void ContactDetector::load(ByteReader& r, std::size_t pairs) {
  auto& im = *impl_;
  const auto n = static_cast<std::size_t>(im.blocks);
  r.get_sized(im.detected_position, n, "detector.detected_position");
  r.get_sized(im.detected_orientation, n, "detector.detected_orientation");
  if (!pair_trigger_) return;
  std::vector<Vec3> pa, pb;
  std::vector<Quat> qa, qb;
  r.get_sized(pa, pairs, "detector.pair_pose_a");
  r.get_sized(pb, pairs, "detector.pair_pose_b");
  r.get_sized(qa, pairs, "detector.pair_orientation_a");
  r.get_sized(qb, pairs, "detector.pair_orientation_b");
  im.pose.resize(pairs);
  for (std::size_t q = 0; q < pairs; ++q) im.pose[q] = {pa[q], pb[q], qa[q], qb[q]};
  std::int64_t resampled = 0;
  r.get(resampled);
  pairs_resampled_ = resampled;
}

}  // namespace polydem
