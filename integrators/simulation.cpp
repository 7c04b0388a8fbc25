#include "integrators/simulation.hpp"

#include "contact/gather.hpp"
#include "core/loads.hpp"
#include "integrators/block_update.hpp"
#include "integrators/thread_split.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace polydem {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// The deck's detection travel, or the automatic one where subcontacts
// sample the joints (the overlap model samples nothing: half the margin).
double deck_detection_travel(const SimulationSpec& sim, const Blocks& blocks) {
  if (sim.detection_travel > 0) return sim.detection_travel;
  if (sim.joint_model == JointModel::overlap) return 0.0;
  return automatic_detection_travel(blocks, pair_by_pair(sim));
}

}  // namespace

Simulation::Simulation(Blocks blocks, const SimulationSpec& sim, JointLaws laws, GroundMotion motion, double margin,
                       double dt, bool adaptive_time_step, BlockLoads loads)
    : blocks_(std::move(blocks)),
      sim_(sim),
      laws_(std::move(laws)),
      step_law_(stiffest_law(laws_)),
      motion_(std::move(motion)),
      detector_(blocks_, margin, deck_detection_travel(sim, blocks_)),
      clock_{0.0, dt, dt, 0},
      control_{adaptive_time_step, 0, {}},
      bond_initial_(laws_.any_bonds()),
      threads_(make_step_threads(sim.adaptive_threads)),
      loads_(make_applied_loads(std::move(loads), blocks_)) {
  profile_.threads_given = omp_get_max_threads();
  overlap_joints_ = sim.joint_model == JointModel::overlap;
  if (overlap_joints_) overlap_scratch_.resize(static_cast<std::size_t>(std::max(1, omp_get_max_threads())));
  detector_.set_pair_joints(overlap_joints_);
  detector_.set_pair_trigger(pair_by_pair(sim));
  clip_ = joint_sampling_of(sim) == JointSampling::clip;
  if (clip_) {
    clip_scratch_.resize(static_cast<std::size_t>(std::max(1, omp_get_max_threads())));
    clip_face_areas_ = face_areas_of(blocks_.props.local_shape);
  }
  detector_.set_points_follow(joint_sampling_of(sim) == JointSampling::step || clip_);
  detector_.set_clipped(clip_);
  ledger_.start(blocks_.state);
  // The first detection on the governor's threads: one, when it governs
  // (beside a competitor the first region on two threads waits ~15 ms for
  // the second to be scheduled, longer than a small scene's whole setup).
  detector_.set_threads(threads_.governor.now);
  detect_contacts();
  // The first detection samples the joints; it re-samples nothing (its
  // counters would hold the strain of blocks built overlapping).
  contacts_.dropped_shear_energy = contacts_.resampled_normal_energy = 0;
  if (clip_) {
    double patch = 0;
    clip_after_detection(threads_.governor.now, patch);
  }
  clock_.dt_prev = clock_.dt;
  if (sim_.damping_scheme == DampingScheme::split)
    rest_.set_step(clock_.dt, step_law_.beta, sim_.safety_factor, blocks_.count);
  start_half_step_back();
  guard_.last_good = blocks_.state;
}

// The deck gives velocities at t = 0; leapfrog keeps them at t − dt/2. Step
// them back half a step with the forces at t = 0 (joint forces without a
// shear increment, gravity, the ground motion), so that free flight from a
// given velocity is the exact parabola and not half a step late.
void Simulation::start_half_step_back() {
  joint_forces(0.0, 0, contacts_.pairs.size(), CodePath::automatic, {}, 0);
  gather_all_blocks(block_update(step_loads()));
  if (!loads_.loaded.empty()) evaluate_point_loads(loads_, blocks_.state, 0.0);
  auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  const Vec3 a_ground = ground_body_acceleration(motion_, 0.0);
  const Vec3 gravity = gravity_at(sim_.gravity, sim_.gravity_rise_time, 0.0);
  const double dt = clock_.dt;
  for (int i : blocks_.free_blocks) {
    Vec3 force = external_force(pr, i, gravity, a_ground) + st.contact_force[i];
    Vec3 torque = st.contact_torque[i];
    if (loads_.on(i)) {
      force += loads_.force[i];
      torque += loads_.torque[i];
    }
    st.velocity[i] -= (0.5 * dt * pr.inv_mass[i]) * force;
    st.angular_momentum[i] -= 0.5 * dt * torque;
    const Mat3& R = st.rotation[i];
    st.angular_velocity[i] = R * pr.inv_principal_inertia[i].cwiseProduct(R.transpose() * st.angular_momentum[i]);
  }
  // The forces at t = 0 started the half step back, not a step of the run:
  // no dashpot work of theirs is owed to the ledger.
  contacts_.sub.damping_force.fill_zero();
  std::fill(contacts_.joints.damping.begin(), contacts_.joints.damping.end(), lanes::PairRest{});
}

// Stage 2 for pairs [begin, end) on thread `thread`: the joint law of the
// scene's model.
void Simulation::joint_forces(double dt, std::size_t begin, std::size_t end, CodePath path, const SplitPart& part,
                              int thread) {
  if (overlap_joints_) {
    overlap_joint_forces(laws_, blocks_.props.local_shape, blocks_.state, contacts_.pairs, contacts_.sub,
                         contacts_.joints, dt, begin, end, overlap_scratch_[static_cast<std::size_t>(thread)]);
    return;
  }
  // Under "clip" the joints were clipped before the detection (clip_due).
  if (contacts_.sub.moving.on && !clip_)
    move_points(blocks_.state, contacts_.pairs, contacts_.sub, begin, end);
  compute_pair_forces(laws_, blocks_.state, contacts_.pairs, contacts_.sub, dt, begin, end, path, part);
}

// Before a detection replaces the subcontacts, each books the second half of
// its last step's dashpot work (the velocities now are that step's
// t + dt/2), at the step it was computed with. After it, the step is checked
// against the joints just found (closed or within the margin): if they
// allow less, the step is lowered for the rest of the run. Leapfrog carries
// the change exactly (the velocity update spans the mean of the old and new
// steps).
DetectionTimes Simulation::detect_contacts(const std::vector<int>* moved) {
  const int detections = contacts_.detections;
  if (overlap_joints_) {
    settle_pair_damping(blocks_.state, contacts_.pairs, contacts_.joints, clock_.dt);
  } else if (moved) {  // pair by pair: the pairs taken over whole keep their dashpots' account
    moved_blocks_.clear();
    for (int q : *moved) {
      const ContactPair& p = contacts_.pairs[static_cast<std::size_t>(q)];
      settle_damping_work(blocks_.state, contacts_.sub, clock_.dt, p.first, p.first + p.count);
      moved_blocks_.push_back(p.a);
      moved_blocks_.push_back(p.b);
    }
    std::sort(moved_blocks_.begin(), moved_blocks_.end());
    moved_blocks_.erase(std::unique(moved_blocks_.begin(), moved_blocks_.end()), moved_blocks_.end());
  } else {
    settle_damping_work(blocks_.state, contacts_.sub, clock_.dt);
  }
  const DetectionTimes times =
      moved ? detector_.resample(blocks_, contacts_, *moved, laws_)
            : detector_.detect(blocks_, contacts_, bond_initial_ && contacts_.detections == 0, laws_);
  // A re-sampling pair by pair changed the joints of its pairs' blocks
  // alone (unless it became a scene-wide detection).
  const std::vector<int>* only = moved && contacts_.detections == detections ? &moved_blocks_ : nullptr;
  if (overlap_joints_) pair_gather_.build(contacts_.pairs, blocks_.count, &contacts_.joints.ref_block);
  if (clip_) carry_clip_rest();
  if (sim_.damping_scheme == DampingScheme::split) rest_.size_for(contacts_, blocks_.count);
  if (!control_.adaptive) return times;
  const CriticalStep c =
      critical_time_step_from_contacts(blocks_, contacts_, laws_, step_law_.beta, sim_.safety_factor, clock_.dt,
                                       detector_.threads(), sim_.time_step_bound, sim_.damping_scheme, only);
  if (c.chosen > 0 && c.chosen < clock_.dt) {
    clock_.dt = c.chosen;
    ++control_.reductions;
    control_.source = c;  // the estimate that set the step now
    if (sim_.damping_scheme == DampingScheme::split)
      rest_.set_step(clock_.dt, step_law_.beta, sim_.safety_factor, blocks_.count);
  }
  return times;
}

// Under "clip", after a detection: each pair taken over whole keeps the
// rest of its last clip (in the set's new order), the pairs sampled are
// listed in clip_fresh_ for clipping at this pose.
void Simulation::carry_clip_rest() {
  const std::size_t np = contacts_.pairs.size();
  const std::vector<int>& origin = detector_.pair_origin();
  const bool known = origin.size() == np;
  clip_rest_next_.assign(np, lanes::PairRest{});
  clip_fresh_.clear();
  for (std::size_t q = 0; q < np; ++q) {
    const int o = known ? origin[q] : -1;
    const auto u = static_cast<std::size_t>(o);
    if (o >= 0 && u < clip_rest_.size()) clip_rest_next_[q] = clip_rest_[u];
    // Sampled, or taken over whole while stale: clipped at this pose.
    if (o < 0 || u >= clip_rest_.size() || (u < clip_stale_.size() && clip_stale_[u]))
      clip_fresh_.push_back(static_cast<int>(q));
  }
  std::swap(clip_rest_, clip_rest_next_);
  clip_stale_.assign(np, 0);
  clip_shear_dropped_.assign(np, 0.0);
  clip_gather_.build(contacts_.pairs, blocks_.count);
}

// The pairs `pairs` (ascending) clipped at the blocks' poses now
// (contact/clip_joint.hpp), in parallel over them (each writes its own), on
// `threads` threads; `check_faces`: with the faces' questions. Those whose
// clip keeps their vertices count as sampled now (their travel starts
// afresh); the others go to clip_stale_list_, and the edge-to-edge pairs,
// which have no faces to clip, to clip_edges_ (re-sampled as the default's
// are, on their travel).
void Simulation::clip_listed(const std::vector<int>& pairs, int threads, bool check_faces) {
  clip_stale_list_.clear();
  clip_edges_.clear();
  if (pairs.empty()) return;
  if (clip_scratch_.size() < static_cast<std::size_t>(threads))
    clip_scratch_.resize(static_cast<std::size_t>(threads));
  const std::size_t n = pairs.size();
  const bool parallel = threads > 1 && n >= 64 && large_enough_for_threads();
#pragma omp parallel if (parallel) num_threads(threads)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const auto [kb, ke] = thread_range(n, static_cast<std::size_t>(nt), static_cast<std::size_t>(t));
    clip_listed_pairs(blocks_.props.local_shape, blocks_.state, laws_, contacts_.pairs, detector_.margin(),
                      contacts_.sub, clip_rest_, clip_stale_, clip_shear_dropped_, pairs.data() + kb, ke - kb,
                      clip_scratch_[static_cast<std::size_t>(t)], &clip_face_areas_, check_faces);
  }
  moved_pairs_.clear();  // here: the pairs clipped with their vertices kept
  for (int q : pairs) {
    const auto u = static_cast<std::size_t>(q);
    contacts_.dropped_shear_energy += clip_shear_dropped_[u];
    if (contacts_.pairs[u].ref_face < 0 || contacts_.pairs[u].count == 0)
      clip_edges_.push_back(q);
    else
      (clip_stale_[u] ? clip_stale_list_ : moved_pairs_).push_back(q);
  }
  clip_count_ += static_cast<long long>(moved_pairs_.size() + clip_stale_list_.size());
  detector_.restart_pair_travel(blocks_, contacts_, moved_pairs_);
}

// Under "clip", before the detection: the pairs whose blocks may have moved
// relative to each other by the detection travel since they were last
// clipped (counting the coming step), and those left stale at the last
// step, clipped again at this pose.
void Simulation::clip_due(int threads) {
  detector_.moved_pairs(blocks_, contacts_, clock_.dt, clip_list_, true);
  if (!clip_retry_.empty()) {
    clip_list_.insert(clip_list_.end(), clip_retry_.begin(), clip_retry_.end());
    std::sort(clip_list_.begin(), clip_list_.end());
    clip_list_.erase(std::unique(clip_list_.begin(), clip_list_.end()), clip_list_.end());
    clip_retry_.clear();
  }
  clip_listed(clip_list_, threads, true);
  // The edge-to-edge pairs that have moved by the travel re-sampled with
  // the stale ones.
  if (!clip_edges_.empty()) {
    clip_stale_list_.insert(clip_stale_list_.end(), clip_edges_.begin(), clip_edges_.end());
    std::sort(clip_stale_list_.begin(), clip_stale_list_.end());
  }
}

// Under "clip", after a detection: the pairs it sampled clipped at this
// pose, and those whose clip finds their vertices changed (a pair sampled
// on a polygon round-off decides) re-sampled and clipped again, twice at
// most; any still stale follow their points' definitions for this step
// (clip_pair) and are clipped again at the next. `patch` adds the
// re-samplings' patch time. The faces' questions are not asked again of
// pairs the detection has just sampled at this pose.
void Simulation::clip_after_detection(int threads, double& patch) {
  for (int pass = 0;; ++pass) {
    clip_list_ = clip_fresh_;
    clip_listed(clip_list_, threads, false);
    if (clip_stale_list_.empty()) return;
    if (pass == 2) break;
    moved_pairs_ = clip_stale_list_;
    patch += detect_contacts(&moved_pairs_).patch;  // carry_clip_rest lists the pairs sampled
  }
  clip_retry_ = clip_stale_list_;
}

bool Simulation::large_enough_for_threads() const {
  return polydem::large_enough_for_threads(threads_, contacts_.sub.size(), blocks_.free_blocks.size());
}

void Simulation::step() {
  const Clock::time_point t0 = Clock::now();
  const bool big = large_enough_for_threads();
  const int threads = threads_for_this_step(threads_, big);
  detector_.set_threads(threads);
  double patch = 0;  // 1. detection, where the half-margin test asks for it
  // Under "clip" the pairs that have moved by the travel are clipped again
  // first; a pair whose polygon's vertices have changed is re-sampled now,
  // at the same pose.
  if (clip_) clip_due(threads);
  bool detected = false;
  if (!detection_known_unneeded(threads_, clock_.dt) && detector_.needs_detection(blocks_, clock_.dt)) {
    patch = detect_contacts().patch;
    detected = true;
  } else if (clip_) {
    if (!clip_stale_list_.empty()) {
      moved_pairs_ = clip_stale_list_;
      patch = detect_contacts(&moved_pairs_).patch;
      detected = true;
    }
  } else if (detector_.pair_trigger() && detector_.moved_pairs(blocks_, contacts_, clock_.dt, moved_pairs_, true)) {
    patch = detect_contacts(&moved_pairs_).patch;  // pair by pair: the moved pairs alone
    detected = true;
  }
  if (clip_ && detected) clip_after_detection(threads, patch);
  const Clock::time_point t1 = Clock::now();
  const StepLoads loads = step_loads();  // the loads once, before the threads
  if (!loads_.loaded.empty() && !stage_.active) evaluate_point_loads(loads_, blocks_.state, clock_.time);
  double law_seconds = 0;
  const int region_threads = integrate(threads, loads, law_seconds);  // 2-3. law, gather and update
  move_kinematic_blocks(blocks_, loads_, motion_, clock_, stage_.active, ledger_);  // 4.
  if (rest_.fraction > 0)
    for (int i : blocks_.kinematic_blocks) rest_.book_work(i, blocks_.state, ledger_, clock_.dt);
  settle_travel_test(threads_, detector_, blocks_, region_threads, clock_.dt);
  finish_step();
  const Clock::time_point t3 = Clock::now();
  record_profile(seconds(t0, t1), patch, law_seconds, seconds(t1, t3), big);
  if (clock_.steps % 256 == 0) {  // 5. the guard
    check_health(guard_, blocks_, contacts_, detector_.margin(), energies(), sim_.gravity, clock_.steps, clock_.time,
                 clock_.dt);
    profile_.guard += seconds(t3, Clock::now());
  }
}

// The step's stages into the profile; the step's time without its
// detection to the thread governor, if the step could run in parallel
// after its detection too.
void Simulation::record_profile(double detection, double patch, double law, double rest, bool big) {
  profile_.detection += detection - patch;
  profile_.patch += patch;
  profile_.joint_law += law;
  profile_.gather_update += rest - law;
  ++profile_.steps;
  if (big && large_enough_for_threads()) record_step(threads_.governor, rest);
}

void Simulation::finish_step() {
  clock_.time += clock_.dt;
  clock_.dt_prev = clock_.dt;
  ++clock_.steps;
}

// The loads of this step, the same for every block.
StepLoads Simulation::step_loads() const {
  StepLoads loads;
  loads.a_ground = stage_.active ? Vec3(Vec3::Zero()) : ground_body_acceleration(motion_, clock_.time);
  loads.gravity = stage_.active ? stage_.load : gravity_at(sim_.gravity, sim_.gravity_rise_time, clock_.time);
  // m·(g(t) − g) is load work: gravity rising, or the static stage's load
  // tilted away from gravity.
  loads.rising = stage_.active ? stage_.load != sim_.gravity : clock_.time < sim_.gravity_rise_time;
  return loads;
}

BlockUpdate Simulation::block_update(const StepLoads& loads) {
  block_lanes::AdvanceFour advance_four = &block_lanes::advance_four_portable;
#ifdef POLYDEM_LANES_AVX2
  if (use_lanes(code_path_)) advance_four = &block_lanes::advance_four_avx2;
#endif
  BlockUpdate u{blocks_,  ledger_,     loads_, stage_, motion_, contacts_, sim_.gravity, loads, clock_,
                gather_kernels(code_path_), advance_four};
  if (overlap_joints_) {
    u.pair_gather = &pair_gather_;
    u.pair_wrench = &contacts_.joints.wrench;
  }
  if (clip_) {
    u.clip_gather = &clip_gather_;
    u.clip_rest = &clip_rest_;
  }
  return u;
}

// Stages 2 and 3 in one parallel region (small scenes on one thread). Each
// thread takes a contiguous range of pairs for the law, then gathers and
// moves the blocks whose pairs it has just computed (thread_split.hpp), and
// bounds their travels for the next step's half-margin test. Returns the
// region's threads; `law_seconds` receives the law's wall time.
int Simulation::integrate(int threads, const StepLoads& loads, double& law_seconds) {
  const Clock::time_point start = Clock::now();
  Clock::time_point law_end = start;
  const bool parallel = threads > 1 && large_enough_for_threads();
  BlockUpdate u = block_update(loads);
  const bool split = rest_.fraction > 0;
  SplitPart part;
  if (split) part = {1.0 - rest_.fraction, rest_.dashpot_state.data()};
  int region_threads = 1;
  if (overlap_joints_ && overlap_scratch_.size() < static_cast<std::size_t>(threads))
    overlap_scratch_.resize(static_cast<std::size_t>(threads));
#pragma omp parallel if (parallel) num_threads(threads)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const auto [pb, pe] = thread_range(contacts_.pairs.size(), static_cast<std::size_t>(nt), static_cast<std::size_t>(t));
    joint_forces(clock_.dt, pb, pe, code_path_, part, t);
#pragma omp barrier
#pragma omp master
    {
      law_end = Clock::now();
      region_threads = nt;
    }
    const int begin = block_split(contacts_.pairs, blocks_.count, nt, t);
    const int end = block_split(contacts_.pairs, blocks_.count, nt, t + 1);
    if (split) {  // the law's forces gathered, the velocities predicted, the rest of the dashpots pair by pair
      gather_and_predict(u, rest_, begin, end);
#pragma omp barrier
      apply_dashpot_rest(laws_, rest_.fraction, blocks_.state, rest_.velocity_next, rest_.omega_next, contacts_.pairs,
                         rest_.dashpot_state.data(), contacts_.sub, rest_.pair_rest, rest_.force_sub, pb, pe,
                         code_path_);
#pragma omp barrier
    }
    gather_and_advance(u, split ? &rest_ : nullptr, begin, end);
    if (split)
      for (int i = begin; i < end; ++i)
        if (blocks_.props.motion[i] == BlockMotion::free) rest_.book_work(i, blocks_.state, ledger_, clock_.dt);
    TravelBound& bound = threads_.travel_parts[static_cast<std::size_t>(t)].bound;
    bound = TravelBound{};
    detector_.add_travels(blocks_, begin, end, threads_.travel_ref, clock_.dt, bound);
  }
  law_seconds = seconds(start, law_end);
  return region_threads;
}

void Simulation::set_thread_governor(ThreadGovernor settings) {
  ThreadGovernor& g = threads_.governor;
  settings.most = g.most;
  settings.now = g.now;
  settings.probing = 0;
  g = settings;
}

void Simulation::begin_static_stage(double local_damping) { begin_static_stage(local_damping, sim_.gravity); }

void Simulation::begin_static_stage(double local_damping, const Vec3& load, bool density_scaling) {
  threads_.travel_clear = false;
  stage_ = start_static_stage(blocks_, contacts_, laws_, step_law_, sim_, clock_.dt, local_damping, load,
                              density_scaling);
}

void Simulation::end_static_stage() {
  stage_ = StaticStage{};
  threads_.travel_clear = false;
  auto& st = blocks_.state;
  for (int i : blocks_.free_blocks) {
    st.velocity[i].setZero();
    st.angular_momentum[i].setZero();
    st.angular_velocity[i].setZero();
  }
  ledger_.start(st);
  blocks_.initial_position = st.position;
  blocks_.initial_orientation = st.orientation;
  clock_.time = 0;
  clock_.steps = 0;
  clock_.dt_prev = clock_.dt;
  rest_.work.assign(rest_.work.size(), 0.0);
  rest_.pending.assign(rest_.pending.size(), 0.0);
  contacts_.retired_slip_energy = contacts_.retired_damping_energy = 0;
  contacts_.dropped_shear_energy = 0;
  contacts_.resampled_normal_energy = 0;
  std::fill(contacts_.sub.slip_energy.begin(), contacts_.sub.slip_energy.end(), 0.0);
  std::fill(contacts_.sub.damping_energy.begin(), contacts_.sub.damping_energy.end(), 0.0);
  contacts_.sub.damping_force.fill_zero();
  PairJoints& j = contacts_.joints;
  std::fill(j.slip_energy.begin(), j.slip_energy.end(), 0.0);
  std::fill(j.damping_energy.begin(), j.damping_energy.end(), 0.0);
  std::fill(j.damping.begin(), j.damping.end(), lanes::PairRest{});
  guard_.restart(st);
  // The profile counts the run's own steps; the threads it was given stay.
  profile_ = StepProfile{.threads_given = profile_.threads_given};
}

void Simulation::save_state(ByteWriter& w) const {
  w.put(static_cast<std::int32_t>(blocks_.count));
  w.put(clock_.time);
  w.put(clock_.steps);
  w.put(clock_.dt);
  w.put(clock_.dt_prev);
  w.put(static_cast<std::int32_t>(control_.reductions));
  save_block_state(w, blocks_.state);
  ledger_.save(w);
  guard_.save(w);
  contacts_.save(w);
  detector_.save(w);
  // Point loads and prescribed blocks (a scene with neither writes nothing more).
  loads_.save(w);
  if (sim_.damping_scheme == DampingScheme::split) {
    w.put(rest_.work);
    w.put(rest_.pending);
  }
  if (clip_) {  // each pair's rest from its last clip, and the pairs to clip again
    std::vector<double> rest;
    rest.reserve(9 * clip_rest_.size());
    for (const lanes::PairRest& r : clip_rest_) {
      rest.insert(rest.end(), r.force, r.force + 3);
      rest.insert(rest.end(), r.moment, r.moment + 3);
      rest.insert(rest.end(), r.moment_ref, r.moment_ref + 3);
    }
    w.put(rest);
    w.put(static_cast<std::int64_t>(clip_count_));
    w.put(static_cast<std::uint64_t>(clip_retry_.size()));
    for (int q : clip_retry_) w.put(static_cast<std::int32_t>(q));
  }
}

void Simulation::load_state(ByteReader& r) {
  threads_.travel_clear = false;  // the test runs in full at the first step after
  std::int32_t count = 0;
  r.get(count);
  if (count != blocks_.count)
    throw StateFormatError("the checkpoint has " + std::to_string(count) + " blocks, the scene " +
                           std::to_string(blocks_.count));
  const auto n = static_cast<std::size_t>(count);
  r.get(clock_.time);
  r.get(clock_.steps);
  r.get(clock_.dt);
  r.get(clock_.dt_prev);
  std::int32_t reductions = 0;
  r.get(reductions);
  control_.reductions = reductions;
  load_block_state(r, blocks_.state, n);
  ledger_.load(r, n);
  guard_.load(r, n);
  contacts_.load(r, count);
  if (overlap_joints_) {  // the derived lists a checkpoint does not hold
    pair_gather_.build(contacts_.pairs, blocks_.count, &contacts_.joints.ref_block);
    find_joint_cells(blocks_.props.local_shape, blocks_.state, contacts_.pairs, contacts_.sub, detector_.margin(),
                     contacts_.joints, overlap_scratch_[0]);
  }
  detector_.load(r, contacts_.pairs.size());
  loads_.load(r, n);
  if (sim_.damping_scheme == DampingScheme::split) {
    rest_.set_step(clock_.dt, step_law_.beta, sim_.safety_factor, blocks_.count);  // θ is the step's
    rest_.size_for(contacts_, blocks_.count);
    r.get_sized(rest_.work, n, "rest_work");
    r.get_sized(rest_.pending, n, "rest_pending");
  }
  if (clip_) {
    const std::size_t np = contacts_.pairs.size();
    std::vector<double> rest;
    r.get_sized(rest, 9 * np, "clip_rest");
    clip_rest_.assign(np, lanes::PairRest{});
    for (std::size_t q = 0; q < np; ++q) {
      std::copy_n(rest.data() + 9 * q, 3, clip_rest_[q].force);
      std::copy_n(rest.data() + 9 * q + 3, 3, clip_rest_[q].moment);
      std::copy_n(rest.data() + 9 * q + 6, 3, clip_rest_[q].moment_ref);
    }
    std::int64_t clipped = 0;
    r.get(clipped);
    clip_count_ = clipped;
    std::uint64_t retry = 0;
    r.get(retry);
    if (retry > np) throw StateFormatError("the checkpoint's clip_retry lists more pairs than it has");
    clip_retry_.assign(static_cast<std::size_t>(retry), 0);
    for (int& q : clip_retry_) {
      std::int32_t v = 0;
      r.get(v);
      if (v < 0 || static_cast<std::size_t>(v) >= np) throw StateFormatError("clip_retry: a pair out of range");
      q = v;
    }
    clip_stale_.assign(np, 0);
    clip_shear_dropped_.assign(np, 0.0);
    clip_gather_.build(contacts_.pairs, blocks_.count);
  }
}

double Simulation::largest_opening(int i) const {
  double open = -std::numeric_limits<double>::infinity();
  const auto& off = contacts_.gather_offset;
  for (int k = off[i]; k < off[i + 1]; ++k)
    open = std::max(open, -contacts_.sub.geometric_overlap(contacts_.gather_sub[k]));
  return open;
}

EnergyLedger Simulation::energies() const {
  return polydem::energies(blocks_, ledger_, laws_, contacts_, rest_.work, sim_.gravity);
}

}  // namespace polydem
