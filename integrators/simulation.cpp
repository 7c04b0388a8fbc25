#include "integrators/simulation.hpp"

#include "contact/gather.hpp"
#include "core/loads.hpp"
#include "integrators/split_damping.hpp"
#include "integrators/thread_split.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace polydem {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}


// Rotation by the rotation vector w (the exponential map). A step turns a
// block by far less than 1e-3 rad, where the fourth-order series is exact to
// round-off and avoids sin/cos; larger turns take the closed form.
// The large turn out of line: the series, taken at every step of every
// block, inlines into the update.
[[gnu::noinline]] Quat large_rotation_quaternion(const Vec3& w, double a2) {
  const double angle = std::sqrt(a2);
  return Quat(Eigen::AngleAxisd(angle, w / angle));
}

[[gnu::always_inline]] inline Quat rotation_quaternion(const Vec3& w) {
  const double a2 = w.squaredNorm();
  if (a2 < 1e-6) [[likely]] {
    const double c = 1.0 - a2 / 8.0 + a2 * a2 / 384.0;  // cos(a/2)
    const double h = 0.5 - a2 / 48.0 + a2 * a2 / 3840.0;  // sin(a/2)/a
    return Quat(c, h * w.x(), h * w.y(), h * w.z());
  }
  return large_rotation_quaternion(w, a2);
}

}  // namespace

Simulation::Simulation(Blocks blocks, const SimulationSpec& sim, JointLaws laws, GroundMotion motion, double margin,
                       double dt, bool adaptive_time_step, BlockLoads loads)
    : blocks_(std::move(blocks)),
      sim_(sim),
      laws_(std::move(laws)),
      step_law_(stiffest_law(laws_)),
      motion_(std::move(motion)),
      detector_(blocks_, margin),
      bond_initial_(laws_.any_bonds()),
      adaptive_dt_(adaptive_time_step),
      dt_(dt),
      dt_prev_(dt),
      loads_(std::move(loads)) {
  governor_ = make_thread_governor(omp_get_max_threads(), sim.adaptive_threads);
  // One part per thread a step can take: the governor's all or, switched off, OpenMP's (never more).
  travel_parts_.resize(static_cast<std::size_t>(std::max({1, governor_.most, governor_.now})));
  profile_.threads_given = omp_get_max_threads();
  const int n = blocks_.count;
  if (!loads_.loads.empty()) {
    loaded_.assign(n, 0);
    load_force_.assign(n, Vec3::Zero());
    load_torque_.assign(n, Vec3::Zero());
    load_force_prev_.assign(n, Vec3::Zero());
    load_torque_prev_.assign(n, Vec3::Zero());
    for (const PointLoad& l : loads_.loads) loaded_[l.block] = 1;
  }
  if (!loads_.prescribed.empty()) {
    prescription_of_.assign(n, -1);
    prescribed_history_.assign(loads_.prescribed.size(), PrescribedHistory{});
    for (std::size_t k = 0; k < loads_.prescribed.size(); ++k) {
      const Prescription& p = loads_.prescribed[k];
      if (blocks_.props.motion[p.block] != BlockMotion::kinematic)
        throw std::invalid_argument("a prescribed block must be kinematic: block '" + blocks_.props.name[p.block] +
                                    "' is not");
      prescription_of_[p.block] = static_cast<int>(k);
      blocks_.state.velocity[p.block] = p.displacement_table.empty() ? p.velocity_at(0.0) : Vec3(Vec3::Zero());
      blocks_.state.angular_velocity[p.block] = p.angular_velocity;
    }
  }
  velocity_mid_ = blocks_.state.velocity;
  omega_mid_ = blocks_.state.angular_velocity;
  position_prev_ = blocks_.state.position;
  orientation_prev_ = blocks_.state.orientation;
  load_work_.assign(n, 0.0);
  // The first detection on the governor's threads: one, when it governs
  // (beside a competitor the first region on two threads waits ~15 ms for
  // the second to be scheduled, longer than a small scene's whole setup).
  detector_.set_threads(governor_.now);
  detect_contacts();
  dt_prev_ = dt_;
  update_split_fraction();
  start_half_step_back();
  last_good_ = blocks_.state;
}

// The deck gives velocities at t = 0; leapfrog keeps them at t − dt/2. Step
// them back half a step with the forces at t = 0 (joint forces without a
// shear increment, gravity, the ground motion), so that free flight from a
// given velocity is the exact parabola and not half a step late.
void Simulation::start_half_step_back() {
  compute_pair_forces(laws_, blocks_.state, contacts_.pairs, contacts_.sub, 0.0, 0, contacts_.pairs.size());
  gather_block_forces();
  if (!loaded_.empty()) compute_point_loads(0.0);
  auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  const Vec3 a_ground = ground_body_acceleration(motion_, 0.0);
  const Vec3 gravity = gravity_at(sim_.gravity, sim_.gravity_rise_time, 0.0);
  for (int i : blocks_.free_blocks) {
    Vec3 force = external_force(pr, i, gravity, a_ground) + st.contact_force[i];
    Vec3 torque = st.contact_torque[i];
    if (!loaded_.empty() && loaded_[i]) {
      force += load_force_[i];
      torque += load_torque_[i];
    }
    st.velocity[i] -= (0.5 * dt_ * pr.inv_mass[i]) * force;
    st.angular_momentum[i] -= 0.5 * dt_ * torque;
    const Mat3& R = st.rotation[i];
    st.angular_velocity[i] = R * pr.inv_principal_inertia[i].cwiseProduct(R.transpose() * st.angular_momentum[i]);
  }
  // The forces at t = 0 started the half step back, not a step of the run:
  // no dashpot work of theirs is owed to the ledger.
  contacts_.sub.damping_force.fill_zero();
}

// Before a detection replaces the subcontacts, each books the second half of
// its last step's dashpot work (the velocities now are that step's
// t + dt/2), at the step it was computed with. After it, the step is checked
// against the joints just found (closed or within the margin): if they
// allow less, the step is lowered for the rest of the run. Leapfrog carries
// the change exactly (the velocity update spans the mean of the old and new
// steps).
DetectionTimes Simulation::detect_contacts() {
  settle_damping_work(blocks_.state, contacts_.sub, dt_);
  const DetectionTimes times =
      detector_.detect(blocks_, contacts_, bond_initial_ && contacts_.detections == 0, laws_);
  if (sim_.damping_scheme == DampingScheme::split) size_split_arrays();
  if (!adaptive_dt_) return times;
  const CriticalStep c =
      critical_time_step_from_contacts(blocks_, contacts_, laws_, step_law_.beta, sim_.safety_factor, dt_,
                                       detector_.threads(), sim_.time_step_bound, sim_.damping_scheme);
  if (c.chosen > 0 && c.chosen < dt_) {
    dt_ = c.chosen;
    ++dt_reductions_;
    step_source_ = c;  // the estimate that set the step now
    update_split_fraction();
  }
  return times;
}

void Simulation::update_split_fraction() {
  split_fraction_ = 0;
  if (sim_.damping_scheme != DampingScheme::split) return;
  const std::size_t n = static_cast<std::size_t>(blocks_.count);
  rest_work_.resize(n, 0.0);
  rest_pending_.resize(n, 0.0);
  if (!(step_law_.beta > 0)) return;  // nothing to split: the explicit step, one pass
  const double omega = highest_frequency_for_step(dt_, step_law_.beta, sim_.safety_factor, DampingScheme::split);
  split_fraction_ = split_damping(0.5 * step_law_.beta * omega).fraction;
  velocity_next_.resize(n, Vec3::Zero());
  omega_next_.resize(n, Vec3::Zero());
  rest_force_.resize(n, Vec3::Zero());
  rest_torque_.resize(n, Vec3::Zero());
}

bool Simulation::large_enough_for_threads() const {
  return contacts_.sub.size() >= parallel_threshold_ || 16 * blocks_.free_blocks.size() >= parallel_threshold_;
}

void Simulation::step() {
  const Clock::time_point t0 = Clock::now();
  // One parallel region per step (a region costs more than a barrier); small
  // scenes stay serial, where a parallel region costs more than it saves.
  // The governor picks all threads or one (a competing process on a core
  // makes the threads wait at every barrier); results are the same bits.
  // A small scene detects on one thread too: its detection gains little
  // from a second, and threads woken for it would spin beside a competitor.
  const bool big = large_enough_for_threads();
  const int threads = big ? threads_for_step(governor_, steps_) : 1;
  // Down from all threads to one (a drop, a probe's one-thread side, a scene
  // grown small): release the idle threads first. With libgomp's default
  // wait policy they spin for milliseconds after a region, taking the core
  // from a competitor and through it from this thread (measured ~4 ms per
  // drop on the 52-stone wall), and they would slow a probe's one-thread
  // side. The next region on all threads starts them again. Inside a
  // caller's parallel region this does nothing.
  if (threads == 1 && last_threads_ > 1) omp_pause_resource_all(omp_pause_soft);
  last_threads_ = threads;
  detector_.set_threads(threads);
  double patch = 0;
  // The half-margin test: settled at the last step's end where its bound
  // was clear (the same answer, block by block in the threads), else here.
  const bool known_clear = travel_clear_ && travel_dt_ == dt_;
  travel_clear_ = false;
  if (!known_clear && detector_.needs_detection(blocks_, dt_)) patch = detect_contacts().patch;
  const Clock::time_point t1 = Clock::now();
  Clock::time_point t2 = t1;  // the joint law's end, read by the master thread
  const bool parallel = threads > 1 && large_enough_for_threads();
  // The loads once, before the threads: a caller's extra ground
  // acceleration (GroundMotion::extra) is called once per step, on this thread.
  const StepLoads loads = step_loads();
  if (!loaded_.empty() && !static_stage_) compute_point_loads(time_);
  int region_threads = 1;
#pragma omp parallel if (parallel) num_threads(threads)
  {
    compute_joint_forces_parallel();
#pragma omp barrier
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp master
    {
      t2 = Clock::now();
      region_threads = nt;
    }
    const int begin = block_split(contacts_.pairs, blocks_.count, nt, t);  // thread_split.hpp
    const int end = block_split(contacts_.pairs, blocks_.count, nt, t + 1);
    if (split_fraction_ > 0) {
      // The split damping scheme (split_damping.hpp): the law's forces
      // gathered and each block's velocities predicted; the rest of the
      // dashpots from them, pair by pair; then the rest gathered onto the
      // blocks and the update.
      gather_and_predict(loads, begin, end);
#pragma omp barrier
      const auto [pb, pe] = thread_range(contacts_.pairs.size(), static_cast<std::size_t>(nt),
                                         static_cast<std::size_t>(t));
      apply_dashpot_rest(laws_, split_fraction_, blocks_.state, velocity_next_, omega_next_, contacts_.pairs,
                         dashpot_state_.data(), contacts_.sub, dashpot_rest_, rest_force_sub_, pb, pe, code_path_);
#pragma omp barrier
    }
    gather_and_advance(loads, begin, end, split_fraction_ > 0);
    if (split_fraction_ > 0)
      for (int i = begin; i < end; ++i)
        if (blocks_.props.motion[i] == BlockMotion::free) book_rest_work(i);
    // The next step's half-margin test, this thread's part: over the blocks
    // it has just moved, while it holds them (no second pass over every
    // block, on one thread, at the next step's start).
    TravelBound& part = travel_parts_[static_cast<std::size_t>(t)].bound;
    part = TravelBound{};
    detector_.add_travels(blocks_, begin, end, travel_ref_, dt_, part);
  }
  move_kinematic_blocks();
  if (split_fraction_ > 0)
    for (int i : blocks_.kinematic_blocks) book_rest_work(i);
  settle_travel_test(region_threads);
  time_ += dt_;
  dt_prev_ = dt_;
  ++steps_;
  const Clock::time_point t3 = Clock::now();
  profile_.detection += seconds(t0, t1) - patch;
  profile_.patch += patch;
  profile_.joint_law += seconds(t1, t2);
  profile_.gather_update += seconds(t2, t3);
  ++profile_.steps;
  // A sample only if the step could run in parallel after its detection too.
  if (big && large_enough_for_threads()) record_step(governor_, seconds(t1, t3), steps_);
  if (steps_ % 256 == 0) {
    check_health();
    profile_.guard += seconds(t3, Clock::now());
  }
}

// The threads' parts of the half-margin test in thread order, the
// kinematic blocks (moved after the threads) added; clear only when the
// test itself would answer no (ContactDetector::clearly_no_detection).
void Simulation::settle_travel_test(int threads) {
  TravelBound all = travel_parts_[0].bound;
  for (int t = 1; t < threads; ++t) merge_travels(all, travel_parts_[static_cast<std::size_t>(t)].bound);
  if (!blocks_.kinematic_blocks.empty())
    detector_.add_travels(blocks_, blocks_.kinematic_blocks, travel_ref_, dt_, all);
  Vec3 drift;
  travel_clear_ = detector_.clearly_no_detection(all, travel_ref_, drift);
  travel_ref_ = drift;
  travel_dt_ = dt_;
}

void Simulation::compute_joint_forces_parallel() {
  // Called inside the step's parallel region: each thread takes one
  // contiguous range of pairs (a static partition).
  const auto [begin, end] = thread_range(contacts_.pairs.size(), static_cast<std::size_t>(omp_get_num_threads()),
                                         static_cast<std::size_t>(omp_get_thread_num()));
  SplitPart split;
  if (split_fraction_ > 0) split = {1.0 - split_fraction_, dashpot_state_.data()};
  compute_pair_forces(laws_, blocks_.state, contacts_.pairs, contacts_.sub, dt_, begin, end, code_path_, split);
}

void Simulation::gather_block(int i) {
  auto& st = blocks_.state;
  gather_kernels(code_path_).block(gather_lane_arrays(contacts_, st.position, st.contact_force, st.contact_torque), i);
}

// Blocks i and i + 1 (when below end): two sums in flight
// (gather_lanes::gather_two, the same bits).
void Simulation::gather_two_blocks(int i, int end) {
  auto& st = blocks_.state;
  const gather_lanes::GatherKernels k = gather_kernels(code_path_);
  const gather_lanes::GatherArrays a = gather_lane_arrays(contacts_, st.position, st.contact_force, st.contact_torque);
  if (i + 1 < end)
    k.two(a, i, i + 1);
  else
    k.block(a, i);
}

// The split scheme's per-subcontact and per-pair scratch, and each block's
// pairs (in increasing order, each entry 2·pair + 1 where the block is the
// pair's reference): sized and listed after each detection.
void Simulation::size_split_arrays() {
  dashpot_state_.resize(contacts_.sub.size());
  rest_force_sub_.resize(contacts_.sub.size());
  dashpot_rest_.resize(contacts_.pairs.size());
  const int n = blocks_.count;
  rest_offset_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const ContactPair& cp : contacts_.pairs) {
    ++rest_offset_[static_cast<std::size_t>(cp.a) + 1];
    ++rest_offset_[static_cast<std::size_t>(cp.b) + 1];
  }
  for (int i = 0; i < n; ++i) rest_offset_[i + 1] += rest_offset_[i];
  rest_entry_.resize(static_cast<std::size_t>(rest_offset_[n]));
  std::vector<int> next(rest_offset_.begin(), rest_offset_.end() - 1);
  for (std::size_t q = 0; q < contacts_.pairs.size(); ++q) {
    const ContactPair& cp = contacts_.pairs[q];
    for (const int b : {cp.a, cp.b})
      rest_entry_[static_cast<std::size_t>(next[b]++)] = 2 * static_cast<int>(q) + (b == cp.ref_block ? 1 : 0);
  }
}

// The split scheme's rest of the dashpots onto block i's joint force and
// moment (the law's already there): its pairs' sums in a fixed order.
void Simulation::gather_rest(int i) {
  auto& st = blocks_.state;
  double f0 = 0, f1 = 0, f2 = 0, m0 = 0, m1 = 0, m2 = 0;
  for (int k = rest_offset_[i]; k < rest_offset_[i + 1]; ++k) {
    const int e = rest_entry_[k];
    const lanes::PairRest& p = dashpot_rest_[static_cast<std::size_t>(e >> 1)];
    if (e & 1) {  // the reference block: the reaction
      f0 -= p.force[0];
      f1 -= p.force[1];
      f2 -= p.force[2];
      m0 += p.moment_ref[0];
      m1 += p.moment_ref[1];
      m2 += p.moment_ref[2];
    } else {
      f0 += p.force[0];
      f1 += p.force[1];
      f2 += p.force[2];
      m0 += p.moment[0];
      m1 += p.moment[1];
      m2 += p.moment[2];
    }
  }
  rest_force_[i] = Vec3(f0, f1, f2);
  rest_torque_[i] = Vec3(m0, m1, m2);
  st.contact_force[i] += rest_force_[i];
  st.contact_torque[i] += rest_torque_[i];
}

// The work of the rest of the dashpots, block by block: its force and
// moment times the block's velocities (summed over a joint's two blocks, the
// rest force times the relative velocity at the point), at the centred
// velocity as the law's dashpot work (joint_law.hpp): half with the
// velocities before the update, booked now, and half with those after it,
// booked at the next step (rest_pending_), when the ledger's kinetic energy
// has taken that half of the impulse. Free blocks in the threads, kinematic
// ones after they have moved (fixed blocks never move: no work).
void Simulation::book_rest_work(int i) {
  const auto& st = blocks_.state;
  const double half = 0.5 * dt_;
  const Vec3& v = st.velocity[i];
  const Vec3& w = st.angular_velocity[i];
  const Vec3 v_before = 2.0 * velocity_mid_[i] - v, w_before = 2.0 * omega_mid_[i] - w;
  rest_work_[i] += rest_pending_[i] + half * (rest_force_[i].dot(v_before) + rest_torque_[i].dot(w_before));
  rest_pending_[i] = half * (rest_force_[i].dot(v) + rest_torque_[i].dot(w));
}

void Simulation::gather_and_predict(const StepLoads& loads, int begin, int end) {
  auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  const double dv_dt = 0.5 * (dt_prev_ + dt_);
  for (int i0 = begin; i0 < end; i0 += 2) {
    gather_two_blocks(i0, end);
    for (int i = i0; i < std::min(i0 + 2, end); ++i) {
      if (pr.motion[i] == BlockMotion::fixed) {  // never moves (whatever the ground does)
        velocity_next_[i] = st.velocity[i];
        omega_next_[i] = st.angular_velocity[i];
        continue;
      }
      if (pr.motion[i] == BlockMotion::kinematic) {
        kinematic_velocity_next(i, velocity_next_[i], omega_next_[i]);
        continue;
      }
      Vec3 force, torque;
      double inv_m;
      const Vec3* inv_I;
      if (local_damping_ > 0)
        block_load<true>(i, loads, force, torque, inv_m, inv_I);
      else
        block_load<false>(i, loads, force, torque, inv_m, inv_I);
      velocity_next_[i] = st.velocity[i] + (dv_dt * inv_m) * force;
      const Vec3 L = st.angular_momentum[i] + dv_dt * torque;
      const Mat3& R = st.rotation[i];
      omega_next_[i] = R * inv_I->cwiseProduct(R.transpose() * L);
    }
  }
}

void Simulation::gather_block_forces() {
  const int n = blocks_.count;
#pragma omp for schedule(static)
  for (int i = 0; i < n; ++i) gather_block(i);
}

// Central differences for one free block (see the file's header). With
// kLocalDamping (the static stage only) the force and the moment are first
// reduced by Cundall's local damping against the velocities at t − dt/2;
// without it the update is the plain one, at no cost.
template <bool kLocalDamping>
[[gnu::always_inline]] inline void Simulation::block_load(int i, const StepLoads& loads, Vec3& force, Vec3& torque,
                                                          double& inv_m, const Vec3*& inv_I) const {
  const auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  force = external_force(pr, i, loads.gravity, loads.a_ground) + st.contact_force[i];
  torque = st.contact_torque[i];
  const bool loaded = !loaded_.empty() && loaded_[i] && !static_stage_;
  if (loaded) {  // the point loads: the sum's last term
    force += load_force_[i];
    torque += load_torque_[i];
  }
  if constexpr (kLocalDamping) {
    force = locally_damped(force, st.velocity[i], local_damping_);
    torque = locally_damped(torque, st.angular_velocity[i], local_damping_);
  }
  inv_m = pr.inv_mass[i];
  inv_I = &pr.inv_principal_inertia[i];
  if constexpr (kLocalDamping) {
    if (!scaled_inv_mass_.empty()) {  // density scaling (the static stage)
      inv_m = scaled_inv_mass_[i];
      inv_I = &scaled_inv_inertia_[i];
    }
  }
}

template <bool kLocalDamping>
void Simulation::advance_block(int i, const StepLoads& loads) {
  auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  const double dt = dt_;
  const double dv_dt = 0.5 * (dt_prev_ + dt_);  // span of the velocity update
  const Vec3& a_ground = loads.a_ground;
  Vec3 force, torque;
  double inv_m;
  const Vec3* inv_I_p;
  block_load<kLocalDamping>(i, loads, force, torque, inv_m, inv_I_p);
  const bool loaded = !loaded_.empty() && loaded_[i] && !static_stage_;
  const Vec3& inv_I = *inv_I_p;
  const Vec3 v_old = st.velocity[i];
  const Vec3 v_new = v_old + (dv_dt * inv_m) * force;
  const Vec3 L_new = st.angular_momentum[i] + dv_dt * torque;
  // ω at the half step: predict the half-step orientation, then evaluate.
  const Mat3& R0 = st.rotation[i];
  const Vec3 w0 = R0 * inv_I.cwiseProduct(R0.transpose() * L_new);
  const Mat3 Rh = (rotation_quaternion(0.5 * dt * w0) * st.orientation[i]).toRotationMatrix();
  const Vec3 w = Rh * inv_I.cwiseProduct(Rh.transpose() * L_new);
  const Vec3 w_old = st.angular_velocity[i];

  velocity_mid_[i] = 0.5 * (v_old + v_new);
  omega_mid_[i] = 0.5 * (w_old + w);
  position_prev_[i] = st.position[i];
  orientation_prev_[i] = st.orientation[i];
  // Gravity's work is the ledger's potential energy: only the ground's counts.
  load_work_[i] += load_work(dt, ground_inertial_force(pr.mass[i], a_ground), velocity_mid_[i]);
  // Under a rising gravity the ledger's potential counts m·g: the rest of
  // the applied weight, m·(g(t) − g), is a load.
  if (loads.rising) load_work_[i] += load_work(dt, pr.mass[i] * (loads.gravity - sim_.gravity), velocity_mid_[i]);
  // The point loads' work over the step that ends at the force time, by the
  // trapezoid: ½(F(t) + F(t − dt))·(x(t) − x(t − dt)), and the same for the
  // torque and the turn. It is the leapfrog's own: with the ledger's
  // kinetic energy ½·m·v₋·v₊, ½m·v₋(t)·(v₊(t) − v₋(t − dt)) is exactly
  // that, so a load of any history keeps the balance to round-off (the
  // mid-step dt·F·v(t) runs half a step ahead of the kinetic energy).
  if (loaded) {
    if (steps_ > 0)
      load_work_[i] += 0.5 * (load_force_[i] + load_force_prev_[i]).dot(dt_prev_ * v_old) +
                       0.5 * (load_torque_[i] + load_torque_prev_[i]).dot(dt_prev_ * st.angular_velocity[i]);
    load_force_prev_[i] = load_force_[i];
    load_torque_prev_[i] = load_torque_[i];
  }

  st.velocity[i] = v_new;
  st.angular_momentum[i] = L_new;
  st.angular_velocity[i] = w;
  st.position[i] += dt * v_new;
  st.orientation[i] = (rotation_quaternion(dt * w) * st.orientation[i]).normalized();
  st.rotation[i] = st.orientation[i].toRotationMatrix();
}

// The loads of this step, the same for every block.
Simulation::StepLoads Simulation::step_loads() const {
  StepLoads loads;
  loads.a_ground = static_stage_ ? Vec3(Vec3::Zero()) : ground_body_acceleration(motion_, time_);
  loads.gravity = static_stage_ ? static_load_ : gravity_at(sim_.gravity, sim_.gravity_rise_time, time_);
  // m·(g(t) − g) is load work: gravity rising, or the static stage's load
  // tilted away from gravity.
  loads.rising = static_stage_ ? static_load_ != sim_.gravity : time_ < sim_.gravity_rise_time;
  return loads;
}

// Gather and update fused in one loop over the blocks [begin, end) of the
// calling thread: a block's update needs only its own gathered force, so
// one barrier less per step (the region's end is the barrier).
void Simulation::gather_and_advance(const StepLoads& loads, int begin, int end, bool rest) {
  const auto& motion = blocks_.props.motion;
  // The blocks two by two, their forces gathered: the law's, or under the
  // split scheme the rest of the dashpots onto the law's.
  auto gather = [&](int i0) {
    if (!rest) {
      gather_two_blocks(i0, end);
      return;
    }
    gather_rest(i0);
    if (i0 + 1 < end) gather_rest(i0 + 1);
  };
  // The blocks two by two: both gathered, then each updated.
  if (local_damping_ > 0) {
    for (int i0 = begin; i0 < end; i0 += 2) {
      gather(i0);
      for (int i = i0; i < std::min(i0 + 2, end); ++i)
        if (motion[i] == BlockMotion::free) advance_block<true>(i, loads);
    }
    return;
  }
  // The free blocks four at a time (block_update_lanes.hpp), each block
  // once its own force is gathered; blocks with point loads, and every block
  // while gravity rises (a load term more), by advance_block.
  if (loads.rising) {
    for (int i0 = begin; i0 < end; i0 += 2) {
      gather(i0);
      for (int i = i0; i < std::min(i0 + 2, end); ++i)
        if (motion[i] == BlockMotion::free) advance_block<false>(i, loads);
    }
    return;
  }
  block_lanes::AdvanceFour advance_four = &block_lanes::advance_four_portable;
#ifdef POLYDEM_LANES_AVX2
  if (use_lanes(code_path_)) advance_four = &block_lanes::advance_four_avx2;
#endif
  const block_lanes::BlockArrays arrays = block_lane_arrays();
  block_lanes::StepConstants k;
  for (int c = 0; c < 3; ++c) {
    k.gravity[c] = loads.gravity[c];
    k.ground_acceleration[c] = loads.a_ground[c];
  }
  k.dt = dt_;
  k.dv_dt = 0.5 * (dt_prev_ + dt_);
  const bool any_loaded = !loaded_.empty() && !static_stage_;
  int four[4];
  int waiting = 0;
  for (int i0 = begin; i0 < end; i0 += 2) {
    gather(i0);
    for (int i = i0; i < std::min(i0 + 2, end); ++i) {
      if (motion[i] != BlockMotion::free) continue;
      if (any_loaded && loaded_[i]) {
        advance_block<false>(i, loads);
        continue;
      }
      four[waiting++] = i;
      if (waiting < 4) continue;
      waiting = 0;
      advance_four(arrays, k, four);
    }
  }
  if (waiting > 0) {
    for (int w = waiting; w < 4; ++w) four[w] = four[waiting - 1];
    advance_four(arrays, k, four);
  }
}

block_lanes::BlockArrays Simulation::block_lane_arrays() {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double) &&
                    sizeof(Mat3) == 9 * sizeof(double),
                "the block arrays are read as plain doubles");
  // The records as doubles (no element is touched: an empty array is fine).
  auto& st = blocks_.state;
  const auto& pr = blocks_.props;
  block_lanes::BlockArrays a;
  a.position = reinterpret_cast<double*>(st.position.data());
  a.velocity = reinterpret_cast<double*>(st.velocity.data());
  a.angular_momentum = reinterpret_cast<double*>(st.angular_momentum.data());
  a.angular_velocity = reinterpret_cast<double*>(st.angular_velocity.data());
  a.orientation = reinterpret_cast<double*>(st.orientation.data());
  a.rotation = reinterpret_cast<double*>(st.rotation.data());
  a.contact_force = reinterpret_cast<double*>(st.contact_force.data());
  a.contact_torque = reinterpret_cast<double*>(st.contact_torque.data());
  a.mass = pr.mass.data();
  a.inv_mass = pr.inv_mass.data();
  a.inv_inertia = reinterpret_cast<const double*>(pr.inv_principal_inertia.data());
  a.velocity_mid = reinterpret_cast<double*>(velocity_mid_.data());
  a.omega_mid = reinterpret_cast<double*>(omega_mid_.data());
  a.position_prev = reinterpret_cast<double*>(position_prev_.data());
  a.orientation_prev = reinterpret_cast<double*>(orientation_prev_.data());
  a.load_work = load_work_.data();
  return a;
}

void Simulation::begin_static_stage(double local_damping) { begin_static_stage(local_damping, sim_.gravity); }

void Simulation::begin_static_stage(double local_damping, const Vec3& load, bool density_scaling) {
  static_stage_ = true;
  travel_clear_ = false;
  local_damping_ = local_damping;
  static_load_ = load;
  scaled_inv_mass_.clear();
  scaled_inv_inertia_.clear();
  if (!density_scaling) return;
  // Each block's highest frequency, on all its faces or on the joints it
  // has now, whichever is higher; the step was chosen for the highest of all.
  std::vector<double> w = block_frequencies(blocks_, step_law_);
  const std::vector<double> wc = block_frequencies_from_contacts(blocks_, contacts_, laws_);
  double top = 0;
  for (int i : blocks_.free_blocks) {
    w[i] = std::max(w[i], wc[i]);
    top = std::max(top, w[i]);
  }
  // Under the joint bound the step may allow less than √2·top (each joint
  // counted once beside a fixed block or a stiffer stone), but blocks scaled
  // to one frequency count every joint twice: scale them to ω/√2 of the
  // highest ω the step allows (blocks above it become heavier).
  if (sim_.time_step_bound == StepBound::joint)
    top = std::min(top, highest_frequency_for_step(dt_, step_law_.beta, sim_.safety_factor, sim_.damping_scheme) /
                            std::sqrt(2.0));
  scaled_inv_mass_ = blocks_.props.inv_mass;
  scaled_inv_inertia_ = blocks_.props.inv_principal_inertia;
  if (!(top > 0)) return;
  for (int i : blocks_.free_blocks) {
    if (!(w[i] > 0)) continue;
    const double f = (top / w[i]) * (top / w[i]);  // 1 / the mass factor, ≥ 1
    scaled_inv_mass_[i] *= f;
    scaled_inv_inertia_[i] *= f;
  }
}

void Simulation::end_static_stage() {
  static_stage_ = false;
  travel_clear_ = false;
  local_damping_ = 0;
  scaled_inv_mass_.clear();
  scaled_inv_inertia_.clear();
  auto& st = blocks_.state;
  for (int i : blocks_.free_blocks) {
    st.velocity[i].setZero();
    st.angular_momentum[i].setZero();
    st.angular_velocity[i].setZero();
  }
  for (int i = 0; i < blocks_.count; ++i) {
    velocity_mid_[i] = st.velocity[i];
    omega_mid_[i] = st.angular_velocity[i];
  }
  position_prev_ = st.position;
  orientation_prev_ = st.orientation;
  blocks_.initial_position = st.position;
  blocks_.initial_orientation = st.orientation;
  time_ = 0;
  steps_ = 0;
  dt_prev_ = dt_;
  load_work_.assign(load_work_.size(), 0.0);
  rest_work_.assign(rest_work_.size(), 0.0);
  rest_pending_.assign(rest_pending_.size(), 0.0);
  contacts_.retired_slip_energy = contacts_.retired_damping_energy = 0;
  contacts_.dropped_shear_energy = 0;
  contacts_.resampled_normal_energy = 0;
  std::fill(contacts_.sub.slip_energy.begin(), contacts_.sub.slip_energy.end(), 0.0);
  std::fill(contacts_.sub.damping_energy.begin(), contacts_.sub.damping_energy.end(), 0.0);
  contacts_.sub.damping_force.fill_zero();
  energy_reference_ = mechanical0_ = 0;
  energy_started_ = false;
  last_good_ = st;
  last_good_time_ = 0;
  last_good_step_ = 0;
  // The profile counts the run's own steps; the threads it was given stay.
  profile_ = StepProfile{.threads_given = profile_.threads_given};
}

void Simulation::kinematic_velocity_next(int i, Vec3& v, Vec3& w) const {
  const auto& st = blocks_.state;
  const int k = prescription_of_.empty() ? -1 : prescription_of_[i];
  if (k >= 0) {
    const Prescription& p = loads_.prescribed[static_cast<std::size_t>(k)];
    v = Vec3::Zero();
    if (!static_stage_) {
      v = !p.displacement_table.empty() ? Vec3((table_value(p.displacement_table, time_ + dt_) -
                                                table_value(p.displacement_table, time_)) / dt_)
                                        : p.velocity_at(time_ + 0.5 * dt_);
    }
    w = static_stage_ ? Vec3(Vec3::Zero()) : p.angular_velocity;
    return;
  }
  const bool moving =
      !static_stage_ && motion_.any_active() && motion_.applied_as == GroundMotionApplication::kinematic;
  v = moving ? motion_.velocity_vector(time_ + 0.5 * dt_) : st.velocity[i];
  w = st.angular_velocity[i];
}

void Simulation::move_kinematic_blocks() {
  if (blocks_.kinematic_blocks.empty()) return;
  auto& st = blocks_.state;
  for (int i : blocks_.kinematic_blocks) {
    const int k = prescription_of_.empty() ? -1 : prescription_of_[i];
    if (k >= 0) {
      move_prescribed_block(i, loads_.prescribed[static_cast<std::size_t>(k)]);
      continue;
    }
    const Vec3 v_old = st.velocity[i];
    Vec3 v_new, w_unused;
    kinematic_velocity_next(i, v_new, w_unused);
    velocity_mid_[i] = 0.5 * (v_old + v_new);
    position_prev_[i] = st.position[i];
    // The base does work on the blocks through the joints: −F_joint·v.
    load_work_[i] += load_work(-dt_, st.contact_force[i], velocity_mid_[i]);
    st.velocity[i] = v_new;
    st.position[i] += dt_ * v_new;
  }
}

// A prescribed block (core/loads.hpp): its velocity at t + dt/2 from its
// history, its turn by ω·dt about its centroid; it does the work
// −dt·(F_joint·v + T_joint·ω) on the blocks it pushes. Held still in the
// static stage.
void Simulation::move_prescribed_block(int i, const Prescription& p) {
  auto& st = blocks_.state;
  const Vec3 v_old = st.velocity[i], w_old = st.angular_velocity[i];
  const bool by_displacement = !p.displacement_table.empty();
  Vec3 v_new, w_new;
  kinematic_velocity_next(i, v_new, w_new);
  velocity_mid_[i] = 0.5 * (v_old + v_new);
  omega_mid_[i] = 0.5 * (w_old + w_new);
  position_prev_[i] = st.position[i];
  orientation_prev_[i] = st.orientation[i];
  // The work it does through its joints over the step that ends now, by
  // the trapezoid (as the point loads: exact against the leapfrog's ledger).
  PrescribedHistory& h = prescribed_history_[static_cast<std::size_t>(prescription_of_[i])];
  if (steps_ > 0)
    load_work_[i] -= 0.5 * (st.contact_force[i] + h.force).dot(dt_prev_ * v_old) +
                     0.5 * (st.contact_torque[i] + h.torque).dot(dt_prev_ * w_old);
  h.force = st.contact_force[i];
  h.torque = st.contact_torque[i];
  st.velocity[i] = v_new;
  st.angular_velocity[i] = w_new;
  if (by_displacement && !static_stage_)
    st.position[i] = p.start + table_value(p.displacement_table, time_ + dt_);  // exactly, no drift
  else
    st.position[i] += dt_ * v_new;
  if (!w_new.isZero(0.0)) {
    st.orientation[i] = (rotation_quaternion(dt_ * w_new) * st.orientation[i]).normalized();
    st.rotation[i] = st.orientation[i].toRotationMatrix();
  }
}

// The point loads at time t on the blocks they act on (serial, in load order:
// several loads on one block sum in the deck's order).
void Simulation::compute_point_loads(double t) {
  const auto& st = blocks_.state;
  for (const PointLoad& l : loads_.loads) {
    load_force_[l.block] = Vec3::Zero();
    load_torque_[l.block] = Vec3::Zero();
  }
  for (const PointLoad& l : loads_.loads) {
    const double f = table_value(l.factor, t).x();
    const Vec3 force = f * l.force;
    Vec3 torque = f * l.moment;
    if (l.at_point) torque += (st.rotation[l.block] * l.arm_local).cross(force);
    load_force_[l.block] += force;
    load_torque_[l.block] += torque;
  }
}

void Simulation::check_health() {
  const auto& st = blocks_.state;
  auto stop = [&](const std::string& cause) {
    std::ostringstream msg;
    msg << "numerical instability at step " << steps_ << " (t = " << time_ << " s, time step " << dt_
        << " s): " << cause << "; the last good state is from step " << last_good_step_ << " (t = "
        << last_good_time_ << " s)";
    throw InstabilityError(msg.str());
  };
  for (int i : blocks_.free_blocks) {
    if (st.position[i].allFinite() && st.velocity[i].allFinite() && st.angular_momentum[i].allFinite()) continue;
    stop("block '" + blocks_.props.name[i] + "' has a non-finite position or velocity");
  }
  // Penetration: a joint overlapping by a fair fraction of the smaller
  // block's size is no longer a contact but blocks passing through each
  // other. A hard impact sinks a joint by about v·sqrt(m/(kn·A)), a few mm for
  // a stone falling metres onto a corner: more than the margin, which is
  // therefore not the limit (only its floor).
  const auto& sub = contacts_.sub;
  const auto& size = blocks_.props.size;
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const double smaller = std::min(size[sub.ref_block[s]], size[sub.inc_block[s]]);
    const double limit = std::max(detector_.margin(), penetration_limit_ * smaller);
    const double overlap = sub.geometric_overlap(s);
    if (overlap <= limit) continue;
    std::ostringstream what;
    what << "blocks '" << blocks_.props.name[sub.ref_block[s]] << "' and '" << blocks_.props.name[sub.inc_block[s]]
         << "' overlap by " << overlap << " m, beyond the penetration limit " << limit << " m ("
         << 100 * penetration_limit_ << " % of the smaller block's size, at least the contact margin)";
    stop(what.str());
  }
  const EnergyLedger e = energies();
  const double mechanical = e.kinetic + e.gravitational + e.strain - e.load_work;
  if (!energy_started_) {
    mechanical0_ = mechanical;
    energy_started_ = true;
  }
  energy_reference_ = std::max(energy_reference_, energy_in_play(e));
  // A floor so that a scene at rest (all energies ~0) is not judged on noise.
  double floor = 0;
  for (int i : blocks_.free_blocks) floor += blocks_.props.mass[i] * sim_.gravity.norm() * 1e-6;
  const double growth = mechanical - mechanical0_;
  if (growth > energy_growth_limit_ * std::max(energy_reference_, floor) && growth > floor) {
    std::ostringstream what;
    what << "the mechanical energy grew by " << growth << " J beyond the work of the loads (" << 100 * growth /
                                                                                                 energy_reference_
         << " % of the energy in play)";
    stop(what.str());
  }
  last_good_ = st;
  last_good_time_ = time_;
  last_good_step_ = steps_;
}

namespace {

void save_block_state(ByteWriter& w, const BlockState& s) {
  w.put(s.position);
  w.put(s.orientation);
  w.put(s.rotation);
  w.put(s.velocity);
  w.put(s.angular_momentum);
  w.put(s.angular_velocity);
  w.put(s.contact_force);
  w.put(s.contact_torque);
}

void load_block_state(ByteReader& r, BlockState& s, std::size_t n) {
  r.get_sized(s.position, n, "block state position");
  r.get_sized(s.orientation, n, "block state orientation");
  r.get_sized(s.rotation, n, "block state rotation");
  r.get_sized(s.velocity, n, "block state velocity");
  r.get_sized(s.angular_momentum, n, "block state angular_momentum");
  r.get_sized(s.angular_velocity, n, "block state angular_velocity");
  r.get_sized(s.contact_force, n, "block state contact_force");
  r.get_sized(s.contact_torque, n, "block state contact_torque");
}

}  // namespace

void Simulation::save_state(ByteWriter& w) const {
  w.put(static_cast<std::int32_t>(blocks_.count));
  w.put(time_);
  w.put(steps_);
  w.put(dt_);
  w.put(dt_prev_);
  w.put(static_cast<std::int32_t>(dt_reductions_));
  save_block_state(w, blocks_.state);
  w.put(velocity_mid_);
  w.put(omega_mid_);
  w.put(position_prev_);
  w.put(orientation_prev_);
  w.put(load_work_);
  w.put(energy_reference_);
  w.put(mechanical0_);
  w.put(energy_started_);
  save_block_state(w, last_good_);
  w.put(last_good_time_);
  w.put(last_good_step_);
  contacts_.save(w);
  detector_.save(w);
  // Point loads and prescribed blocks (a scene with neither writes nothing
  // more: its checkpoints are those it always wrote).
  if (!loaded_.empty()) {
    w.put(load_force_prev_);
    w.put(load_torque_prev_);
  }
  for (const PrescribedHistory& h : prescribed_history_) {
    w.put(h.force);
    w.put(h.torque);
  }
  if (sim_.damping_scheme == DampingScheme::split) {  // the explicit scheme's files as before
    w.put(rest_work_);
    w.put(rest_pending_);
  }
}

void Simulation::load_state(ByteReader& r) {
  travel_clear_ = false;  // the test runs in full at the first step after
  std::int32_t count = 0;
  r.get(count);
  if (count != blocks_.count)
    throw StateFormatError("the checkpoint has " + std::to_string(count) + " blocks, the scene " +
                           std::to_string(blocks_.count));
  const auto n = static_cast<std::size_t>(count);
  r.get(time_);
  r.get(steps_);
  r.get(dt_);
  r.get(dt_prev_);
  std::int32_t reductions = 0;
  r.get(reductions);
  dt_reductions_ = reductions;
  load_block_state(r, blocks_.state, n);
  r.get_sized(velocity_mid_, n, "velocity_mid");
  r.get_sized(omega_mid_, n, "omega_mid");
  r.get_sized(position_prev_, n, "position_prev");
  r.get_sized(orientation_prev_, n, "orientation_prev");
  r.get_sized(load_work_, n, "load_work");
  r.get(energy_reference_);
  r.get(mechanical0_);
  r.get(energy_started_);
  load_block_state(r, last_good_, n);
  r.get(last_good_time_);
  r.get(last_good_step_);
  contacts_.load(r, count);
  detector_.load(r);
  if (!loaded_.empty()) {
    r.get_sized(load_force_prev_, n, "load_force_prev");
    r.get_sized(load_torque_prev_, n, "load_torque_prev");
  }
  for (PrescribedHistory& h : prescribed_history_) {
    r.get(h.force);
    r.get(h.torque);
  }
  update_split_fraction();  // θ is the step's (dt_ restored above)
  if (sim_.damping_scheme == DampingScheme::split) {
    size_split_arrays();
    r.get_sized(rest_work_, n, "rest_work");
    r.get_sized(rest_pending_, n, "rest_pending");
  }
}

double Simulation::largest_opening(int i) const {
  double open = -std::numeric_limits<double>::infinity();
  const auto& off = contacts_.gather_offset;
  for (int k = off[i]; k < off[i + 1]; ++k) open = std::max(open, -contacts_.sub.geometric_overlap(contacts_.gather_sub[k]));
  return open;
}

// The kinetic energy at the force time t is the leapfrog's own:
// ½·m·v(t − dt/2)·v(t + dt/2), the product of the two half steps around t
// (and ½·ω₋ᵀ·I·ω₊ in rotation, I in the body frame cached at t + dt: a
// second-order difference). With the joint law's dashpot work at the centred
// velocity (contact/joint_law.hpp), this is what makes the ledger an exact
// invariant of the update for linear springs and dashpots: per step,
// m·(v₊ − v₋)·v(t) = dt·F·v(t) books the work of every force at the centred
// velocity, and ½·m·v₋·v₊ + ½·k·x² + mg·x + dissipation is then constant. The
// square of the centred velocity, ½·m·v(t)², used before, exceeds it by
// m·(dt·a)²/8: nothing in a slow motion, but 1.1 % of the energy in play in
// the first steps of an overdamped impact, and for a block set down under a
// sudden gravity the whole balance error (1.35e-5 before, 1.03 % with the
// centred dashpot work and the squared velocity, 1e-10 with both changes).
EnergyLedger Simulation::energies() const {
  EnergyLedger e;
  const auto& pr = blocks_.props;
  const auto& st = blocks_.state;
  for (int i : blocks_.free_blocks) {
    const double m = pr.mass[i];
    // velocity_mid_ is the mean of the two half steps; the state holds v₊.
    const Vec3 v_before = 2.0 * velocity_mid_[i] - st.velocity[i];
    e.kinetic += 0.5 * m * v_before.dot(st.velocity[i]);
    const Vec3 wb0 = st.rotation[i].transpose() * (2.0 * omega_mid_[i] - st.angular_velocity[i]);
    const Vec3 wb1 = st.rotation[i].transpose() * st.angular_velocity[i];
    e.kinetic += 0.5 * wb0.dot(pr.principal_inertia[i].cwiseProduct(wb1));
    e.gravitational += -m * sim_.gravity.dot(position_prev_[i] - blocks_.initial_position[i]);
  }
  e.strain = joint_strain_energy(laws_, contacts_.sub);
  e.slip = contacts_.retired_slip_energy;
  e.damping = contacts_.retired_damping_energy;
  for (std::size_t s = 0; s < contacts_.sub.size(); ++s) {
    e.slip += contacts_.sub.slip_energy[s];
    e.damping += contacts_.sub.damping_energy[s];
  }
  for (double w : rest_work_) e.damping -= w;  // the split scheme's rest of the dashpots
  e.dropped_shear = contacts_.dropped_shear_energy;
  e.resampled_normal = contacts_.resampled_normal_energy;
  for (double w : load_work_) e.load_work += w;
  e.balance =
      e.kinetic + e.gravitational + e.strain + e.slip + e.damping + e.dropped_shear + e.resampled_normal - e.load_work;
  return e;
}

}  // namespace polydem
