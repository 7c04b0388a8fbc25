// The time loop: one explicit central-difference step, stage by stage
// (Simulation::step reads as the list below).
//
//   1. detection, only if some pair may have moved by the detection travel
//      (contact/detection.hpp; settled at the last step's end where the
//      threads' bound is clear, step_threads.hpp); pair by pair (the
//      default) the scene only at half the margin, and between, the pairs
//      whose own blocks moved by the travel re-sampled alone; under
//      joint_sampling = "clip" those pairs clipped again instead
//      (clip_joint.hpp), and re-sampled only where the clip finds their
//      polygon's vertices changed
//   2. joint law: one force slot per subcontact       (contact/joint_law.hpp)
//      or, under the overlap model, one wrench per pair (overlap_joint.hpp)
//   3. gather and central-difference update            (block_update.hpp)
//      with the split damping scheme, between them: the rest of the
//      dashpots from the predicted velocities          (dashpot_rest.hpp)
//   4. kinematic blocks and prescribed motions         (applied_loads.hpp)
//   5. every 256 steps, the guard                      (guard.hpp)
// Stages 2-3 run in one parallel region; each stage is timed into the
// StepProfile. The energy ledger (energy_ledger.hpp) is read, not stepped.
// No atomics, no reductions of doubles across threads: every array is
// written by one iteration, and 1 and 2 threads give the same bits.
#pragma once

#include "contact/clip_joint.hpp"
#include "contact/detection.hpp"
#include "contact/overlap_joint.hpp"
#include "contact/pair_gather.hpp"
#include "core/code_path.hpp"
#include "integrators/applied_loads.hpp"
#include "integrators/critical_time_step.hpp"
#include "integrators/dashpot_rest.hpp"
#include "integrators/energy_ledger.hpp"
#include "integrators/guard.hpp"
#include "integrators/static_stage.hpp"
#include "integrators/step_threads.hpp"

namespace polydem {

// Wall seconds in each stage of step(), summed over the steps this object
// has run (cf. Box2D's b2Profile); not checkpointed.
struct StepProfile {
  double detection = 0;      // the half-margin test, broad and narrow phase, subcontacts, gather lists
  double patch = 0;          // common plane and patch clipping (part of each detection)
  double joint_law = 0;      // joint forces, one slot per subcontact
  double gather_update = 0;  // gather, update, kinematic blocks, the threads' half-margin bound
  double guard = 0;          // check_health, every 256 steps
  long steps = 0;            // steps timed
  int threads_given = 1;     // threads OpenMP gave the run (Simulation::thread_governor: what it did with them)
};

struct StepLoads;  // block_update.hpp
struct BlockUpdate;

class Simulation {
 public:
  // dt: the step (checked against the critical one); adaptive: lower it when
  // a detection finds stiffer joints; laws: make_joint_laws, built at setup;
  // loads: point loads and prescribed motions (core/loads.hpp).
  Simulation(Blocks blocks, const SimulationSpec& sim, JointLaws laws, GroundMotion motion, double margin, double dt,
             bool adaptive_time_step = true, BlockLoads loads = {});

  void step();

  double time() const { return clock_.time; }
  double dt() const { return clock_.dt; }
  long steps() const { return clock_.steps; }
  // Times a detection lowered the step, and the estimate that last did.
  int time_step_reductions() const { return control_.reductions; }
  const CriticalStep& time_step_source() const { return control_.source; }
  double split_fraction() const { return rest_.fraction; }  // the split scheme's θ (0: explicit)
  // Subcontact s's whole joint force on the incident block at the last step
  // (zero under the overlap model, whose forces are the pairs').
  Vec3 subcontact_force(std::size_t s) const {
    return rest_.fraction > 0 ? Vec3(contacts_.sub.force[s] + rest_.force_sub[s]) : contacts_.sub.force[s];
  }
  const StepProfile& profile() const { return profile_; }

  const Blocks& blocks() const { return blocks_; }
  const ContactSet& contacts() const { return contacts_; }
  double detection_travel() const { return detector_.travel(); }
  long long pairs_resampled() const { return detector_.pairs_resampled(); }
  // joint_sampling = "clip": the pair clips so far (contact/clip_joint.hpp).
  long long pairs_clipped() const { return clip_count_; }
  const GroundMotion& ground_motion() const { return motion_; }
  const JointLaws& joint_laws() const { return laws_; }
  // The stiffest law that can act: its β sets the time step's damping.
  const JointLaw& step_law() const { return step_law_; }
  bool is_prescribed(int i) const { return !loads_.prescription_of.empty() && loads_.prescription_of[i] >= 0; }

  // Energies at the time of the last force evaluation (time() − dt()).
  EnergyLedger energies() const;
  // Block i's velocities and pose at that time.
  Vec3 velocity_at_force_time(int i) const { return ledger_.velocity_mid[i]; }
  Vec3 angular_velocity_at_force_time(int i) const { return ledger_.omega_mid[i]; }
  Vec3 position_at_force_time(int i) const { return ledger_.position_prev[i]; }
  Quat orientation_at_force_time(int i) const { return ledger_.orientation_prev[i]; }
  // Largest opening (m) among block i's subcontacts at the force time.
  double largest_opening(int i) const;

  // The guard (guard.hpp): its limits and the last good state.
  void set_energy_growth_limit(double fraction) { guard_.energy_growth_limit = fraction; }
  void set_penetration_limit(double fraction_of_size) { guard_.penetration_limit = fraction_of_size; }
  const BlockState& last_good_state() const { return guard_.last_good; }
  double last_good_time() const { return guard_.last_good_time; }
  long last_good_step() const { return guard_.last_good_step; }

  // Checkpoints: everything that decides the rest of the run, bit for bit,
  // loaded into a Simulation built from the same deck (StateFormatError).
  void save_state(ByteWriter& w) const;
  void load_state(ByteReader& r);

  // The static stage (static_stage.hpp), under `load` (default: gravity).
  // end_static_stage() starts the dynamic stage from the state reached:
  // time and step count 0, every block at rest and its initial pose set to
  // it, the ledger, the guard and the profile started afresh; the joints
  // keep their forces and shear history.
  void begin_static_stage(double local_damping);
  void begin_static_stage(double local_damping, const Vec3& load, bool density_scaling = false);
  void end_static_stage();

  // Tests and benchmarks: threads (step_threads.hpp), code path (core/code_path.hpp).
  void set_parallel_threshold(std::size_t subcontacts) { threads_.parallel_threshold = subcontacts; }
  void set_code_path(CodePath path) { code_path_ = path; }
  void set_thread_governor(ThreadGovernor settings);
  const ThreadGovernor& thread_governor() const { return threads_.governor; }
  bool large_enough_for_threads() const;

 private:
  // A scene-wide detection, or (`moved`) the re-sampling of those pairs.
  DetectionTimes detect_contacts(const std::vector<int>* moved = nullptr);
  void start_half_step_back();
  void joint_forces(double dt, std::size_t begin, std::size_t end, CodePath path, const SplitPart& part, int thread);
  StepLoads step_loads() const;
  BlockUpdate block_update(const StepLoads& loads);
  int integrate(int threads, const StepLoads& loads, double& law_seconds);
  void finish_step();
  void record_profile(double detection, double patch, double law, double rest, bool big);
  // joint_sampling = "clip" (contact/clip_joint.hpp).
  void clip_listed(const std::vector<int>& pairs, int threads, bool check_faces);
  void clip_due(int threads);
  void clip_after_detection(int threads, double& patch);
  void carry_clip_rest();

  struct StepControl {
    bool adaptive = true;
    int reductions = 0;
    CriticalStep source;
  };

  Blocks blocks_;
  SimulationSpec sim_;
  JointLaws laws_;
  JointLaw step_law_;  // the stiffest law that can act (the time step's)
  GroundMotion motion_;
  ContactDetector detector_;
  ContactSet contacts_;
  StepClock clock_;
  StepControl control_;
  bool bond_initial_;  // new joints start bonded at the first detection
  CodePath code_path_ = CodePath::automatic;
  StepThreads threads_;
  LedgerKinematics ledger_;
  Guard guard_;
  AppliedLoads loads_;
  StaticStage stage_;
  DashpotRest rest_;
  // The overlap joint model (contact/overlap_joint.hpp): per-thread scratch
  // and each block's pairs.
  bool overlap_joints_ = false;
  std::vector<OverlapScratch> overlap_scratch_;
  PairGather pair_gather_;
  // joint_sampling = "clip" (contact/clip_joint.hpp): per-thread scratch,
  // each pair's gradient rest (from its last clip) and each block's pairs;
  // per pair, whether its last clip found its polygon's vertices changed;
  // the pairs to clip at this step, and those to re-sample now; the pairs
  // still stale after the step's re-samplings (clipped again at the next
  // step whatever their travel).
  bool clip_ = false;
  std::vector<ClipScratch> clip_scratch_;
  std::vector<std::vector<double>> clip_face_areas_;  // per block, per face
  std::vector<lanes::PairRest> clip_rest_, clip_rest_next_;
  std::vector<std::uint8_t> clip_stale_;
  std::vector<double> clip_shear_dropped_;  // per pair: the shear energy its last clip took (clip_pairs)
  std::vector<int> clip_list_, clip_stale_list_, clip_fresh_, clip_retry_, clip_edges_;
  PairGather clip_gather_;
  long long clip_count_ = 0;
  std::vector<int> moved_pairs_;   // pair by pair: the pairs to re-sample (scratch)
  std::vector<int> moved_blocks_;  // and their blocks
  StepProfile profile_;
};

}  // namespace polydem
