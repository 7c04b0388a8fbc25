// Runs one scene from its deck: builds the blocks, chooses the time step,
// steps to the end time, records what the deck asks for, and evaluates the
// deck's verification checks. No files here: run_command writes them.
#pragma once

#include "apps/assessment.hpp"
#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"

#include <functional>
#include <string>
#include <vector>

namespace polydem {

struct CheckResult {
  std::string name;
  std::string unit;
  double measured = 0, expected = 0, tolerance = 0;
  bool passed = false;
  std::string note;
};

// A table of histories: one row per record time, columns named with units.
struct HistoryTable {
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::vector<double> rows;  // row-major
  std::size_t row_count() const { return columns.empty() ? 0 : rows.size() / columns.size(); }
};

struct RunReport {
  std::string status;  // "intact", "damaged" or "collapsed" (see assessment)
  bool settled = false;
  bool unstable = false;     // stopped by the guard (see Simulation::check_health)
  std::string instability;   // the guard's message
  double last_good_time = 0;  // s
  std::vector<Polyhedron> final_shapes;  // the last good state's blocks (unstable runs only)  // stopped early: every block at rest (simulation.settle_*)
  Assessment assessment;
  long steps = 0;
  double end_time = 0;
  double time_step = 0;          // s, at the end of the run
  double initial_time_step = 0;  // s, at the start
  int time_step_reductions = 0;
  CriticalStep critical;
  double margin = 0;
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
  EnergyLedger energy;
  double energy_balance_error = 0;  // max |balance − balance(0)| / reference energy
  double energy_reference = 0;      // J
  // Walking (output.walking): largest opening of bed joints (normal within
  // 45° of vertical) and of vertical joints, at the end and the largest seen.
  struct Walking {
    double bed_opening = 0, vertical_opening = 0;          // m, at the end
    double max_bed_opening = 0, max_vertical_opening = 0;  // m, during the run
    std::string bed_joint, vertical_joint;                 // "blockA|blockB" at the end
  };
  Walking walking;
  HistoryTable histories;
  HistoryTable energies;
  std::vector<CheckResult> checks;
  // Final state of every block (for restart-free comparisons and tests).
  std::vector<Vec3> final_position, final_velocity;
  std::vector<Quat> final_orientation;
  bool all_checks_passed() const;
};

struct RunControl {
  int threads = 0;  // 0: OpenMP default
  std::size_t parallel_threshold = 2048;  // see Simulation::set_parallel_threshold
  // Called every `progress_every` steps (for progress output); may be empty.
  std::function<void(const Simulation&)> progress;
  long progress_every = 1000;
  // Called at t = 0, every output.snapshot_interval and at the end (only
  // when the deck asks for snapshots).
  std::function<void(const Simulation&, double time)> snapshot;
  // Checkpoints (only when the deck sets output.checkpoint_interval): called
  // with the whole run state at each multiple of the interval; run_command
  // frames it and writes DIR/checkpoint.bin. `save_extra`/`load_extra` add
  // the caller's own state to it (run_command: the snapshot series).
  std::function<void(const std::string& state)> checkpoint;
  std::function<void(ByteWriter&)> save_extra;
  std::function<void(ByteReader&)> load_extra;
  // Continue from a checkpoint's state (as passed to `checkpoint`) instead of
  // starting at t = 0; the scene must come from the same deck. A state that
  // does not fit throws StateFormatError.
  const std::string* restart = nullptr;
  // Test hook (POLYDEM_KILL_AT_STEP): the process kills itself with SIGKILL
  // after this step, as a machine that dies would. -1: never.
  long kill_at_step = -1;
};

// Checkpoints hold the Simulation's state (Simulation::save_state), the
// assessment and check monitors, and the runner's own: histories recorded so
// far, next record/snapshot/checkpoint times, energy-balance tracking,
// settle tracking, subcontact updates. Taken between two steps after all of
// a step's bookkeeping, so a restart continues with the next step exactly as
// the uninterrupted run would.
//
// Throws DeckError-like std::runtime_error for input found bad only now
// (overlapping blocks, time step above the critical one). A run the guard
// stops returns with `unstable` set, the histories so far and the last good
// state as the final state.
RunReport run_scene(const SceneSpec& spec, const RunControl& control = {});

// Finds the line of `key` (e.g. "time_step") in the deck text; 0 if absent.
int deck_line_of(const std::string& deck_text, const std::string& key);

}  // namespace polydem
