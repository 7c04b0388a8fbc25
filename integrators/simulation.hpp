// The time loop: one explicit central-difference step, stage by stage.
//
//   step():
//     1. detect contacts, only if some pair may have closed half the margin
//        (settled at the last step's end where the threads' bound is clear)
//     2. joint law: one force slot per subcontact          (parallel)
//     3. gather: each block sums its slots in fixed order   (parallel)
//     4. central differences for free blocks                (parallel)
//        and each thread's part of the next step's test     (parallel)
//     With simulation.damping_scheme = "split" (split_damping.hpp) the law
//     applies 1 − θ of each dashpot and stage 3 also predicts each block's
//     velocities after the step; then
//     3a. the rest θ of the dashpots from them, pair by pair  (parallel)
//     3b. each block gathers the rest onto its force          (parallel)
//     before stage 4 (two barriers more, one pass over the subcontacts).
//     5. kinematic base blocks follow the ground velocity; the test's
//        parts merged (contact/detection.hpp TravelBound)
//     6. every 256 steps, the guard checks the state
// Each stage is timed into the StepProfile (a few clock reads per step).
//
// Leapfrog: x, q at t; v, L (angular momentum) at t − dt/2.
//   v(t+dt/2) = v(t−dt/2) + dt·F(t)/m,  x(t+dt) = x(t) + dt·v(t+dt/2)
//   L(t+dt/2) = L(t−dt/2) + dt·T(t),    q(t+dt) = exp(ω(t+dt/2)·dt)·q(t)
// with ω = R I⁻¹ Rᵀ L evaluated at the half-step orientation (one predictor
// pass), so rotation is second-order accurate with the full inertia tensor.
//
// Determinism: no atomics, no reductions of doubles across threads in the
// physics; every array is written by exactly one iteration. 1 and 2 threads
// give the same bits (guarded by a test).
#pragma once

#include "contact/detection.hpp"
#include "contact/joint_law.hpp"
#include "core/blocks.hpp"
#include "core/ground_motion.hpp"
#include "core/loads.hpp"
#include "integrators/block_update_lanes.hpp"
#include "integrators/critical_time_step.hpp"
#include "integrators/thread_governor.hpp"

#include <cmath>
#include <stdexcept>

namespace polydem {

// The run cannot go on (non-finite state): the message names the step,
// the time and the block.
struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct EnergyLedger {
  double kinetic = 0;        // J, ½·m·v₋·v₊ (the half steps around the force time) and its rotational part
  double gravitational = 0;  // J, −Σ m g·x relative to t = 0
  double strain = 0;         // J, stored in the joints
  double slip = 0;           // J, dissipated by Coulomb slip
  double damping = 0;        // J, dissipated by joint damping
  double dropped_shear = 0;  // J, elastic shear energy detections could not carry over (ContactSet)
  double resampled_normal = 0;  // J, normal strain detections removed (> 0) or added (< 0) at the same pose
  double load_work = 0;      // J, work of the ground motion (body force or base)
  double balance = 0;  // kinetic + gravitational + strain + slip + damping + dropped_shear + resampled_normal − load_work
};

// The energy in play, what a balance error is measured against: every term
// of the ledger, the potential and the load work by magnitude.
inline double energy_in_play(const EnergyLedger& e) {
  return e.kinetic + e.strain + std::abs(e.gravitational) + e.slip + e.damping + e.dropped_shear +
         std::abs(e.resampled_normal) + std::abs(e.load_work);
}

// Wall seconds spent in each stage of Simulation::step(), summed over the
// steps this object has run (std::chrono::steady_clock; cf. Box2D's
// b2Profile). Kept apart from the state: it is not checkpointed, so a run
// resumed from a checkpoint counts only the steps it ran itself, and the
// constructor's first detection is not in it.
struct StepProfile {
  double detection = 0;      // the half-margin test where the threads' bound did not settle it, broad
                             // and narrow phase, subcontacts with their history, gather lists, and
                             // the step check after a detection
  double patch = 0;          // common plane and patch clipping (part of each detection)
  double joint_law = 0;      // joint forces, one slot per subcontact
  double gather_update = 0;  // gather, central-difference update, kinematic blocks, the threads'
                             // bound for the next step's half-margin test
  double guard = 0;          // check_health, every 256 steps
  long steps = 0;            // steps timed
  // Threads OpenMP gave the run (what the thread governor did with them:
  // Simulation::thread_governor()).
  int threads_given = 1;
};

class Simulation {
 public:
  // dt: the step to use (already checked against the critical step).
  // adaptive_time_step: lower the step when a detection finds stiffer joints
  // (always on in runs; tests switch it off to drive a run unstable on
  // purpose and see the guard act).
  // laws: the joints' laws (make_joint_laws, built once at setup); loads:
  // point loads and prescribed motions (core/loads.hpp resolve_loads; the
  // prescribed blocks must be kinematic).
  Simulation(Blocks blocks, const SimulationSpec& sim, JointLaws laws, GroundMotion motion, double margin, double dt,
             bool adaptive_time_step = true, BlockLoads loads = {});

  // Steps with fewer subcontacts (and fewer free blocks than a sixteenth of
  // this) run on one thread, detections included. On a quiet machine two
  // threads pay from a few hundred subcontacts (polydem_throughput
  // --threshold-sweep: 1.66× at 346, 1.84× from 1399), and the thread
  // governor now keeps short steps beside a competitor within a few per
  // cent of one thread. But on this VM two threads start erratically (the
  // first 10-20 ms on two threads ran 2-3 times slower than one thread in 3
  // of 5 quiet runs of the 52-stone wall), so a governed small scene often
  // stays on one thread for its first seconds anyway (docs/benchmarks.md).
  // The threshold stays at 2048.
  void set_parallel_threshold(std::size_t subcontacts) { parallel_threshold_ = subcontacts; }
  // The code path of the joint law and of the blocks' update
  // (core/code_path.hpp): automatic by default; tests run both and compare
  // the bits.
  void set_code_path(CodePath path) { code_path_ = path; }
  // The thread governor's settings (tests probe every few steps): taken
  // from `settings`, its state started afresh with the threads given.
  void set_thread_governor(ThreadGovernor settings) {
    settings.most = governor_.most;
    settings.now = governor_.now;
    settings.probing = 0;
    settings.next_probe = settings.first_probe;
    settings.interval = settings.shortest_interval;
    governor_ = settings;
  }
  const ThreadGovernor& thread_governor() const { return governor_; }

  void step();
  // The scene is large enough for the step to run on more than one thread
  // (set_parallel_threshold).
  bool large_enough_for_threads() const;
  double time() const { return time_; }
  double dt() const { return dt_; }
  // Times the step was lowered because a detection found joints stiffer
  // than the step allowed (see critical_time_step_from_contacts).
  int time_step_reductions() const { return dt_reductions_; }
  // The estimate from the joints that last lowered the step (frequency,
  // damping ratio, governing block); governing_block < 0 if none did.
  const CriticalStep& time_step_source() const { return step_source_; }
  // The split damping scheme's θ for the current step (0: explicit).
  double split_fraction() const { return split_fraction_; }
  // Subcontact s's whole joint force on the incident block at the last step:
  // the law's slot, plus under the split scheme the rest of its dashpots.
  Vec3 subcontact_force(std::size_t s) const {
    return split_fraction_ > 0 ? Vec3(contacts_.sub.force[s] + rest_force_sub_[s]) : contacts_.sub.force[s];
  }
  long steps() const { return steps_; }
  const StepProfile& profile() const { return profile_; }

  const Blocks& blocks() const { return blocks_; }
  const ContactSet& contacts() const { return contacts_; }
  const GroundMotion& ground_motion() const { return motion_; }
  const JointLaws& joint_laws() const { return laws_; }
  // The stiffest law that can act: its β sets the time step's damping.
  const JointLaw& step_law() const { return step_law_; }
  // Block i moves as a [[prescribe]] says (not with the ground motion).
  bool is_prescribed(int i) const { return !prescription_of_.empty() && prescription_of_[i] >= 0; }

  // Energies at the time of the last force evaluation (time() − dt()); the
  // kinetic term is ½·m·v(t − dt/2)·v(t + dt/2) (see energies() in the .cpp).
  EnergyLedger energies() const;
  // Velocity and angular velocity of block i at that time.
  Vec3 velocity_at_force_time(int i) const { return velocity_mid_[i]; }
  Vec3 angular_velocity_at_force_time(int i) const { return omega_mid_[i]; }
  Vec3 position_at_force_time(int i) const { return position_prev_[i]; }
  Quat orientation_at_force_time(int i) const { return orientation_prev_[i]; }
  // Largest opening (m) among block i's subcontacts at the force time.
  double largest_opening(int i) const;

  // The guard. Every 256 steps the state is checked: a non-finite value,
  // a joint overlapping more than the penetration limit (a fraction, 10 % by
  // default, of the smaller block's size, and at least the contact margin:
  // blocks passing through each other, not a hard impact, which sinks a
  // joint by millimetres), or a mechanical energy that has grown by more
  // than energy_growth_limit of the energy in play beyond the work of the
  // loads (energy appearing from nowhere: the step is too large) throws
  // InstabilityError naming the cause, the step and the time. The state of
  // the last passed check is kept.
  void set_energy_growth_limit(double fraction) { energy_growth_limit_ = fraction; }
  void set_penetration_limit(double fraction_of_size) { penetration_limit_ = fraction_of_size; }
  const BlockState& last_good_state() const { return last_good_; }
  double last_good_time() const { return last_good_time_; }
  long last_good_step() const { return last_good_step_; }

  // Checkpoints: everything that decides the rest of the run, bit for bit:
  // time, step count, the step and the one before, the block state, the
  // mid-step kinematics and load work of the ledger, the guard, the contacts
  // with their shear history, and the detector's last poses. The scene
  // itself (shapes, masses, joint law, ground motion, settings) is not
  // saved: load_state() is called on a Simulation built from the same deck,
  // and checks that the block and subcontact counts fit. Throws
  // StateFormatError (core/byte_stream.hpp) on a payload that does not.
  void save_state(ByteWriter& w) const;
  void load_state(ByteReader& r);

  // The static stage (run/equilibrium.hpp), as 3DEC's `model solve`. Between
  // begin and end the step applies gravity in full (no rise time) and no
  // ground motion (no body force, kinematic blocks stay), and reduces each
  // free block's force and moment by Cundall's local damping α
  // (core/loads.hpp locally_damped). The joints keep their law, damping
  // included. end_static_stage() starts the dynamic stage from the state
  // reached: time and step count 0, every block at rest, the blocks'
  // initial positions and orientations (what displacements, rotations and
  // the ledger's potential are measured from) set to it, the ledger's load
  // work and dissipation, the guard and the profile started afresh. The
  // joints keep their forces and shear history: they carry the weight.
  // `load` replaces gravity as the stage's body acceleration (default: the
  // scene's gravity); the static collapse search tilts it by λ·g
  // horizontally (studies/collapse_search.hpp).
  //
  // Density scaling (`density_scaling`, 3DEC's for static solutions): in the
  // stage the inertia is fictitious, only the equilibrium counts, so each
  // free block's mass and inertia are lowered by the factor (ω_b / ω_top)²
  // (ω_b its highest frequency on all its faces, ω_top the stiffest block's,
  // the one that set the step; integrators/critical_time_step.hpp
  // block_frequencies). Every block then vibrates at the step's own
  // frequency and local damping takes the same few steps per cycle out of a
  // heavy stone as out of the lightest one; the step stays stable (no block
  // is above the frequency the step was chosen for). Weights stay the real
  // m·g: only the inertia in the update changes, so the equilibrium is the
  // same. The dynamic stage uses the real inertia.
  void begin_static_stage(double local_damping);
  void begin_static_stage(double local_damping, const Vec3& load, bool density_scaling = false);
  void end_static_stage();

 private:
  DetectionTimes detect_contacts();
  void start_half_step_back();
  void compute_joint_forces_parallel();
  void gather_block_forces();
  void gather_block(int i);
  void gather_two_blocks(int i, int end);
  // The loads of this step, the same for every block.
  struct StepLoads {
    Vec3 gravity;       // g(t) (core/loads.hpp gravity_at)
    Vec3 a_ground;      // the ground's body acceleration
    bool rising;        // g(t) ≠ g: count m·(g(t) − g) as load work
  };
  StepLoads step_loads() const;
  // `rest`: the blocks' joint forces are already gathered (the split scheme's
  // first pass); gather the rest of the dashpots onto them before the update.
  void gather_and_advance(const StepLoads& loads, int begin, int end, bool rest = false);
  // The split damping scheme (split_damping.hpp), blocks [begin, end):
  // gather the joint law's forces and predict each block's velocities after
  // the step (velocity_next_, omega_next_); kinematic blocks their own.
  void gather_and_predict(const StepLoads& loads, int begin, int end);
  void gather_rest(int i);
  void size_split_arrays();
  void book_rest_work(int i);
  // Block i's force and moment at the step's time, and the inverse mass and
  // principal inertia its update uses (the static stage's local damping and
  // density scaling included).
  template <bool kLocalDamping>
  void block_load(int i, const StepLoads& loads, Vec3& force, Vec3& torque, double& inv_m, const Vec3*& inv_I) const;
  // A kinematic block's velocity and angular velocity over the step ahead
  // (t to t + dt): the ground's, its prescription's, or held.
  void kinematic_velocity_next(int i, Vec3& v, Vec3& w) const;
  // θ for the step dt_ (0 with the explicit scheme or without damping).
  void update_split_fraction();
  void settle_travel_test(int threads);
  block_lanes::BlockArrays block_lane_arrays();
  template <bool kLocalDamping>
  void advance_block(int i, const StepLoads& loads);
  void move_kinematic_blocks();
  void compute_point_loads(double t);
  void move_prescribed_block(int i, const Prescription& p);  // load_force_, load_torque_ at time t
  void check_health();

  Blocks blocks_;
  SimulationSpec sim_;
  JointLaws laws_;
  JointLaw step_law_;  // the stiffest law that can act (the time step's)
  GroundMotion motion_;
  ContactDetector detector_;
  ContactSet contacts_;
  bool bond_initial_;
  bool adaptive_dt_;
  std::size_t parallel_threshold_ = 2048;
  CodePath code_path_ = CodePath::automatic;
  ThreadGovernor governor_;
  int last_threads_ = 0;  // threads of the last step (0: none yet)
  // The half-margin test gathered by the step's threads (contact/
  // detection.hpp TravelBound): each thread's part in its own cache line;
  // travel_clear_ when the last step's end settled the next step's test
  // (for a step of travel_dt_), travel_ref_ the drift travels are taken from.
  struct alignas(64) TravelPart {
    TravelBound bound;
  };
  std::vector<TravelPart> travel_parts_;
  Vec3 travel_ref_ = Vec3::Zero();
  bool travel_clear_ = false;
  double travel_dt_ = 0;
  double dt_;
  double dt_prev_;  // the step before: leapfrog with a changing step
  int dt_reductions_ = 0;
  CriticalStep step_source_;
  // The split damping scheme: θ (0: the explicit scheme, and none of the
  // arrays below is sized or touched), each subcontact's DashpotState and
  // rest per pair, each block's predicted velocities and gathered rest.
  double split_fraction_ = 0;
  std::vector<std::uint8_t> dashpot_state_;
  std::vector<lanes::PairRest> dashpot_rest_;    // per pair
  Vec3Array rest_force_sub_;                      // per subcontact (subcontact_force)
  std::vector<int> rest_offset_, rest_entry_;     // each block's pairs (size_split_arrays)
  std::vector<Vec3> velocity_next_, omega_next_, rest_force_, rest_torque_;
  std::vector<double> rest_work_;     // per block, J (the ledger's: −Σ is dissipation)
  std::vector<double> rest_pending_;  // per block, J: the last step's second half, booked at the next
  double time_ = 0;
  long steps_ = 0;
  // Per-block ledger terms and mid-step kinematics (for the energy ledger).
  std::vector<Vec3> velocity_mid_, omega_mid_, position_prev_;
  std::vector<Quat> orientation_prev_;
  // Guard.
  double energy_growth_limit_ = 0.1;
  double penetration_limit_ = 0.1;  // of the smaller block's size
  double energy_reference_ = 0, mechanical0_ = 0;
  bool energy_started_ = false;
  BlockState last_good_;
  double last_good_time_ = 0;
  long last_good_step_ = 0;
  std::vector<double> load_work_;
  // Point loads and prescribed motions (empty for most scenes: then no
  // array below is touched by the step).
  BlockLoads loads_;
  std::vector<char> loaded_;                  // per block: some point load acts on it
  std::vector<Vec3> load_force_, load_torque_;  // per block, at the step's time
  std::vector<Vec3> load_force_prev_, load_torque_prev_;  // per block, at the step before (the ledger's trapezoid)
  std::vector<int> prescription_of_;          // per block: index into loads_.prescribed, -1 if none
  struct PrescribedHistory {
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();  // its joints' force and torque at the step before
  };
  std::vector<PrescribedHistory> prescribed_history_;  // per prescription
  StepProfile profile_;
  // The static stage (begin_static_stage): not checkpointed, a checkpoint is
  // never taken during it.
  bool static_stage_ = false;
  double local_damping_ = 0;
  // Density scaling: the stage's inverse mass and principal inertia per
  // block (empty without it).
  std::vector<double> scaled_inv_mass_;
  std::vector<Vec3> scaled_inv_inertia_;
  Vec3 static_load_ = Vec3::Zero();
};

}  // namespace polydem
