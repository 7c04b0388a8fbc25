// One run of a scene, as a library that knows no file: setup (run/setup.hpp),
// the time loop, the end. The deck reader (io/) makes the SceneSpec; the
// command line (apps/) and the Python module (python/) write what comes back.
//
// run_scene() is SceneRun driven to the end in one call; a caller that looks
// at the state between steps (the Python module's callbacks, a coupling to
// another code) drives a SceneRun itself, through the same loop body, so
// both give the same bits:
//
//   SceneRun run(spec, control);        // 1. and 2.
//   while (!run.over()) {
//     run.advance(1000);                // 3., at most 1000 steps
//     ... run.simulation() ...          // read the state
//   }
//   RunReport report = run.finish();    // 4.
//
//   run_scene(spec):
//     1. setup        blocks, margin, time step, ground motion, first
//                     detection, overlap check               (run/setup.hpp)
//        equilibrium  the static stage, when the deck has [equilibrium]
//                     (run/equilibrium.hpp): the dynamic stage starts at
//                     t = 0 from the equilibrium state, at rest
//     2. monitors     the assessment, the deck's [[check]]s, the recorder
//     3. the loop     step; observe; record, snapshot, checkpoint when due
//                     (run/schedule.hpp); stop on collapse, on settling, or
//                     when the guard finds the run unstable
//     4. the end      the final record, the walking openings, the
//                     assessment and the checks, the profile
//
// Errors: SceneError (run/scene_error.hpp) for input found bad only now
// (overlapping blocks, a time step above the critical one, a check that does
// not fit the scene), naming the deck key; StateFormatError for a restart
// state that does not fit. A run the guard stops returns with `unstable` set,
// the histories so far and the last good state as the final state.
#pragma once

#include "run/assessment.hpp"
#include "run/checks.hpp"
#include "run/equilibrium.hpp"
#include "run/recorder.hpp"
#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace polydem {

// Where a run's wall time went, stage by stage (as Box2D's b2Profile): the
// stages of the step (integrators/simulation.hpp) and the run's own output
// (histories, monitors, snapshots, checkpoints, progress). Seconds summed
// over the run; `total` is the whole run including setup.
struct RunProfile {
  double setup = 0, equilibrium = 0, detection = 0, patch = 0, joint_law = 0, gather_update = 0, guard = 0, output = 0, total = 0;
  long steps = 0;
  // The thread governor (integrators/thread_governor.hpp).
  int threads_given = 1;
  long thread_probes = 0, thread_switches = 0, steps_on_one_thread = 0, thread_stall_drops = 0;
};

struct RunReport {
  std::string status;  // "intact", "damaged", "collapsed" or "undetermined" (see assessment), "unstable"
  bool settled = false;      // stopped early: every block at rest (simulation.settle_*)
  bool unstable = false;     // stopped by the guard (see Simulation::check_health)
  std::string instability;   // the guard's message
  double last_good_time = 0;  // s
  std::vector<Polyhedron> final_shapes;  // the last good state's blocks (unstable runs only)
  Assessment assessment;
  long steps = 0;
  double end_time = 0;
  double time_step = 0;          // s, at the end of the run
  double initial_time_step = 0;  // s, at the start
  int time_step_reductions = 0;
  // The split damping scheme's θ at the end (0: the explicit scheme).
  double damping_split_fraction = 0;
  // The estimate that set the step: the all-faces bound before the first
  // detection, or the joints' estimate that last lowered it (frequency,
  // damping ratio ξ at that frequency, governing block); with the deck's own
  // step, the bound that step had to respect.
  CriticalStep critical;
  std::string time_step_set_by;  // "deck" | "all-faces bound" | "joints at a detection"
  std::string time_step_block;   // the governing block's name ("" if none)
  double margin = 0;
  double detection_travel = 0;  // m, the contacts' re-sampling travel (contact/detection.hpp)
  long long pairs_resampled = 0;  // pair by pair: the pairs re-sampled (scene-wide detections' too)
  long long pairs_clipped = 0;    // joint_sampling = "clip": the pair clips
  double wall_seconds = 0;
  long subcontact_updates = 0;  // Σ over steps of the number of subcontacts
  // Checkpoints written (output.checkpoint_interval), over the whole run
  // including before a restart; the size of the last one's state and the
  // wall time spent in them (serialising, framing, writing, fsync).
  int checkpoints = 0;
  long checkpoint_bytes = 0;
  double checkpoint_wall_seconds = 0;
  int detections = 0;
  int blocks = 0, free_blocks = 0;
  EquilibriumReport equilibrium;  // the static stage (ran = false without one)
  EnergyLedger energy;              // at the end
  EnergyLedger energy_start;        // at the first record (the dynamic stage's start)
  double energy_balance_error = 0;  // max |numerical| over the energy put in (integrators/energy_ledger.hpp)
  double energy_reference = 0;      // the energy put in, J
  // The numerical line at the end (J) and as a fraction of the energy
  // dissipated since the start (slip plus damping; 0 when none was).
  double numerical_energy() const { return polydem::numerical_energy(energy, energy_start); }
  double numerical_fraction_of_dissipation() const;
  // The part of the numerical line the detections account for (J): the
  // shear strain they could not hand on and the normal strain their
  // re-sampling of the joints removed or added, signed as the line (the
  // rest is the time integration's). Zero under the overlap model.
  double numerical_at_detections = 0;
  Walking walking;
  HistoryTable histories;
  HistoryTable energies;
  std::vector<CheckResult> checks;
  RunProfile profile;
  // Final state of every block (for restart-free comparisons and tests).
  std::vector<Vec3> final_position, final_velocity;
  std::vector<Quat> final_orientation;
  bool all_checks_passed() const;
};

struct RunControl {
  int threads = 0;  // 0: the deck's simulation.threads (0 there: OpenMP's default)
  std::size_t parallel_threshold = 2048;  // see Simulation::set_parallel_threshold
  CodePath code_path = CodePath::automatic;  // see Simulation::set_code_path
  // Called every `progress_every` steps (for progress output); may be empty.
  std::function<void(const Simulation&)> progress;
  long progress_every = 1000;
  // Called at t = 0, every output.snapshot_interval and at the end (only
  // when the deck asks for snapshots).
  std::function<void(const Simulation&, double time)> snapshot;
  // Checkpoints (only when the deck sets output.checkpoint_interval): called
  // with the whole run state at each multiple of the interval; the caller
  // frames it and writes it (io/checkpoint.hpp). `save_extra`/`load_extra`
  // add the caller's own state to it (the command line: the snapshot series).
  std::function<void(const std::string& state)> checkpoint;
  std::function<void(ByteWriter&)> save_extra;
  std::function<void(ByteReader&)> load_extra;
  // Continue from a checkpoint's state (as passed to `checkpoint`) instead of
  // starting at t = 0; the scene must come from the same deck. A state that
  // does not fit throws StateFormatError.
  const std::string* restart = nullptr;
  // Called after every step, once that step's records, snapshot and
  // checkpoint are written; may be empty. (The restart test installs one
  // that kills the process, as a machine that dies would.)
  std::function<void(const Simulation&)> after_step;
  // The caller's own ground acceleration, added to the deck's as a body
  // force (core/ground_motion.hpp ExtraGroundAcceleration); empty: none.
  // Not part of a checkpoint: a restart must be given the same one.
  ExtraGroundAcceleration ground_acceleration;
  // The time from which `ground_acceleration` stays as it is (a table's
  // last sample); a run does not count as settled before it. Infinite for a
  // function of time, which may change at any moment.
  double ground_acceleration_final_time = std::numeric_limits<double>::infinity();
};

// One run, step by step. The constructor sets the run up (1. and 2.:
// setup, the static stage, the monitors, the restart or the first
// snapshot); advance() runs the loop (3.); finish() is the end (4.).
// Errors: as run_scene() (SceneError, StateFormatError from the
// constructor); an instability ends the run (over(), report().unstable)
// instead of throwing. Not copyable; `spec` is copied.
class SceneRun {
 public:
  explicit SceneRun(const SceneSpec& spec, const RunControl& control = {});
  ~SceneRun();
  SceneRun(const SceneRun&) = delete;
  SceneRun& operator=(const SceneRun&) = delete;

  // Steps until `max_steps` more steps were taken, the time reached `until`
  // (s; the loop's own test: stop when time ≥ until − dt/2) or the run is
  // over. Returns the steps taken. Does nothing once over() or finished.
  long advance(long max_steps, double until = std::numeric_limits<double>::infinity());
  // The run has reached its end time, collapsed for certain (assessment.stop_on_collapse),
  // settled, or been stopped by the guard.
  bool over() const;
  bool finished() const { return finished_; }

  const SceneSpec& spec() const { return spec_; }
  const Simulation& simulation() const { return *sim_; }
  // The report so far: setup figures, `unstable` and `instability`, `settled`;
  // complete after finish().
  const RunReport& report() const { return report_; }

  // The end (4.): the final ledger row and snapshot, walking, assessment,
  // checks, final (or last good) state, profile. Once; later calls return
  // the same report. A run finished before its end time reports the state
  // where it stopped.
  const RunReport& finish();

 private:
  struct Loop;
  void write_checkpoint();

  SceneSpec spec_;
  RunControl control_;
  int threads_ = 0;  // the run's threads (scoped_threads.hpp run_threads; 0: OpenMP's default)
  RunReport report_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<Loop> loop_;
  bool over_ = false, finished_ = false;
};

// The run state a checkpoint holds, in this order: the Simulation's state
// (Simulation::save_state), the assessment, the check monitors, the run's
// own (histories and energies recorded so far, walking maxima, subcontact
// updates, checkpoints written, next record/snapshot/checkpoint times,
// energy-balance tracking, settle tracking, wall time), then the caller's
// extra section. Taken between two steps after all of a step's bookkeeping,
// so a restart continues with the next step exactly as the uninterrupted run
// would.
RunReport run_scene(const SceneSpec& spec, const RunControl& control = {});

}  // namespace polydem
