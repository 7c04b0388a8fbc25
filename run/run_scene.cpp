#include "run/run_scene.hpp"

#include "run/schedule.hpp"
#include "run/scoped_threads.hpp"
#include "run/setup.hpp"


#include <algorithm>
#include <limits>
#include <chrono>
#include <cmath>

namespace polydem {

double RunReport::numerical_fraction_of_dissipation() const {
  const double dissipated = (energy.slip - energy_start.slip) + (energy.damping - energy_start.damping);
  return dissipated > 0 ? numerical_energy() / dissipated : 0.0;
}

bool RunReport::all_checks_passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; });
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

constexpr std::uint32_t kRunnerTag = 0x52554e52;  // "RUNR"

// What the loop keeps besides the Simulation, the monitors and the recorder.
struct LoopState {
  Periodic records, snapshots, checkpoints;
  double quiet_since = -1;  // s, since when every free block has been slower than settle_velocity
  double wall_before = 0;   // s, spent before a restart
};

// The run's own section of a checkpoint (see run_scene.hpp for the order).
void save_loop(ByteWriter& w, const RunReport& rep, const Recorder& rec, const LoopState& s, double wall_now) {
  w.put(kRunnerTag);
  w.put(rec.histories.rows);
  w.put(rec.energies.rows);
  w.put(rec.walk.max_bed_opening);
  w.put(rec.walk.max_vertical_opening);
  w.put(static_cast<std::uint64_t>(rec.walk.courses.size()));
  for (const CourseWalking& c : rec.walk.courses) {
    w.put(c.peak_bed);
    w.put(c.peak_vertical);
  }
  w.put(rep.subcontact_updates);
  w.put(static_cast<std::int32_t>(rep.checkpoints + 1));  // counting the one being written
  w.put(rep.checkpoint_wall_seconds);
  const EnergyLedger& e0 = rec.start;
  for (double x : {s.records.next, e0.kinetic, e0.gravitational, e0.strain, e0.slip, e0.damping, e0.load_work,
                   e0.balance, rec.reference, rec.worst, s.snapshots.next, s.quiet_since, s.checkpoints.next})
    w.put(x);
  w.put(rec.first_energy);
  w.put(s.wall_before + wall_now);
}

void load_loop(ByteReader& r, RunReport& rep, Recorder& rec, LoopState& s, std::size_t state_bytes) {
  std::uint32_t tag = 0;
  r.get(tag);
  if (tag != kRunnerTag) throw StateFormatError("runner section missing");
  r.get(rec.histories.rows);
  r.get(rec.energies.rows);
  if (rec.histories.rows.size() % std::max<std::size_t>(1, rec.histories.columns.size()) != 0 ||
      (!rec.energies.columns.empty() && rec.energies.rows.size() % rec.energies.columns.size() != 0))
    throw StateFormatError("history rows do not fit the deck's columns");
  r.get(rec.walk.max_bed_opening);
  r.get(rec.walk.max_vertical_opening);
  std::uint64_t courses = 0;
  r.get(courses);
  if (courses != rec.walk.courses.size())
    throw StateFormatError("the checkpoint has walking on " + std::to_string(courses) + " courses, the deck " +
                           std::to_string(rec.walk.courses.size()));
  for (CourseWalking& c : rec.walk.courses) {
    r.get(c.peak_bed);
    r.get(c.peak_vertical);
  }
  r.get(rep.subcontact_updates);
  std::int32_t written = 0;
  r.get(written);
  rep.checkpoints = written;
  rep.checkpoint_bytes = static_cast<long>(state_bytes);  // the last one written
  r.get(rep.checkpoint_wall_seconds);
  EnergyLedger& e0 = rec.start;
  for (double* x : {&s.records.next, &e0.kinetic, &e0.gravitational, &e0.strain, &e0.slip, &e0.damping,
                    &e0.load_work, &e0.balance, &rec.reference, &rec.worst, &s.snapshots.next, &s.quiet_since,
                    &s.checkpoints.next})
    r.get(*x);
  r.get(rec.first_energy);
  r.get(s.wall_before);
}

// The time from which the loads stay as they are: gravity risen, the
// constant acceleration risen, the pulse over, the record played. Before it
// blocks at rest have not settled under the run's loads, only under part of
// them (a slow rise starts at rest); infinite for a ramp, which never ends.
double loads_final_time(const SceneSpec& spec) {
  const auto motion_final = [](const GroundMotionSpec& g) {
    switch (g.kind) {
      case GroundMotionKind::none: return 0.0;
      case GroundMotionKind::constant: return g.start_time + g.rise_time;
      case GroundMotionKind::sine_pulse: return g.start_time + g.period;
      case GroundMotionKind::record: return g.start_time + (g.record_time.empty() ? 0.0 : g.record_time.back());
      case GroundMotionKind::ramp: return std::numeric_limits<double>::infinity();
    }
    return 0.0;
  };
  double t = std::max(spec.simulation.gravity_rise_time, motion_final(spec.ground_motion));
  for (const GroundMotionSpec& c : spec.ground_motion.components) t = std::max(t, motion_final(c));
  // [[load]] tables end at their last time; [[prescribe]] tables too, and a
  // block pushed at a constant velocity never lets the others come to rest.
  for (const LoadSpec& l : spec.loads)
    if (!l.factor.empty()) t = std::max(t, l.factor.time.back());
  for (const PrescribeSpec& p : spec.prescribed) {
    if (!p.velocity_table.empty()) t = std::max(t, p.velocity_table.time.back());
    if (!p.displacement_table.empty()) t = std::max(t, p.displacement_table.time.back());
    if (p.velocity_table.empty() && p.displacement_table.empty() &&
        (p.velocity.norm() > 0 || p.angular_velocity.norm() > 0))
      t = std::numeric_limits<double>::infinity();
  }
  return t;
}

// True when every free block has been slower than settle_velocity for
// settle_time once the loads are final, the caller's ground acceleration
// too (simulation.settle_*; never when settle_velocity is 0).
bool settled(const SceneSpec& spec, const RunControl& control, const Simulation& sim, double& quiet_since) {
  if (!(spec.simulation.settle_velocity > 0)) return false;
  const double caller_final = control.ground_acceleration ? control.ground_acceleration_final_time : 0.0;
  if (sim.time() < std::max(loads_final_time(spec), caller_final)) {
    quiet_since = -1;
    return false;
  }
  double vmax = 0;
  for (int i : sim.blocks().free_blocks) vmax = std::max(vmax, sim.blocks().state.velocity[i].norm());
  if (vmax >= spec.simulation.settle_velocity) {
    quiet_since = -1;
    return false;
  }
  if (quiet_since < 0) quiet_since = sim.time();
  return sim.time() - quiet_since >= spec.simulation.settle_time;
}

// Continues from a checkpoint's state (see run_scene.hpp for the order).
void restore(const std::string& state, const RunControl& control, Simulation& sim, AssessmentMonitor& assessment,
             std::vector<std::unique_ptr<CheckMonitor>>& monitors, RunReport& rep, Recorder& recorder,
             LoopState& loop) {
  ByteReader r(state);
  sim.load_state(r);
  assessment.load(r);
  std::uint64_t count = 0;
  r.get(count);
  if (count != monitors.size())
    throw StateFormatError("the checkpoint has " + std::to_string(count) + " checks, the deck " +
                           std::to_string(monitors.size()));
  for (auto& m : monitors) m->load(r);
  load_loop(r, rep, recorder, loop, state.size());
  bool extra = false;
  r.get(extra);
  if (extra != static_cast<bool>(control.load_extra))
    throw StateFormatError("the caller's section does not fit (snapshots on one side only)");
  if (extra) control.load_extra(r);
  if (!r.at_end()) throw StateFormatError(std::to_string(r.remaining()) + " bytes left over");
  recorder.reserve_rows();
}

// The end of a run: what the recorder, the assessment and the checks found,
// and the final (or last good) state.
void finish_report(RunReport& rep, const Simulation& sim, Recorder& recorder, AssessmentMonitor& assessment,
                   std::vector<std::unique_ptr<CheckMonitor>>& monitors) {
  recorder.finish_walking(sim);
  rep.walking = recorder.walk;
  rep.histories = std::move(recorder.histories);
  rep.energies = std::move(recorder.energies);
  rep.assessment = assessment.finish(sim);
  rep.status = rep.assessment.status;
  rep.steps = sim.steps();
  rep.time_step = sim.dt();
  rep.time_step_reductions = sim.time_step_reductions();
  rep.damping_split_fraction = sim.split_fraction();
  if (sim.time_step_source().governing_block >= 0) {
    rep.critical = sim.time_step_source();
    rep.time_step_set_by = "joints at a detection";
  }
  if (rep.critical.governing_block >= 0) rep.time_step_block = sim.blocks().props.name[rep.critical.governing_block];
  rep.end_time = sim.time();
  rep.detections = sim.contacts().detections;
  rep.pairs_resampled = sim.pairs_resampled();
  rep.pairs_clipped = sim.pairs_clipped();
  rep.energy = sim.energies();
  rep.energy_start = recorder.first_energy ? rep.energy : recorder.start;
  rep.energy_reference = recorder.reference;
  rep.energy_balance_error = recorder.balance_error();
  rep.numerical_at_detections = sim.contacts().numerical_at_detections();
  for (auto& m : monitors) rep.checks.push_back(m->finish(sim));
  const BlockState& final_state = rep.unstable ? sim.last_good_state() : sim.blocks().state;
  rep.final_position = final_state.position;
  rep.final_velocity = final_state.velocity;
  rep.final_orientation = final_state.orientation;
  if (rep.unstable) {
    rep.status = "unstable";
    rep.last_good_time = sim.last_good_time();
    for (int i = 0; i < sim.blocks().count; ++i)
      rep.final_shapes.push_back(transformed(sim.blocks().props.local_shape[i], final_state.rotation[i],
                                             final_state.position[i]));
  }
}

}  // namespace

// What a run keeps between advance() calls besides the Simulation.
struct SceneRun::Loop {
  Loop(const SceneSpec& spec, const Simulation& sim)
      : assessment(spec.assessment, sim, spec.simulation.gravity, spec.simulation.overlap_tolerance), monitors(checks(spec, sim)), recorder(spec, sim) {}
  static std::vector<std::unique_ptr<CheckMonitor>> checks(const SceneSpec& spec, const Simulation& sim) {
    std::vector<std::unique_ptr<CheckMonitor>> m;
    for (const CheckSpec& c : spec.checks) m.push_back(make_check(c, spec, sim));
    return m;
  }
  Clock::time_point wall_start;
  AssessmentMonitor assessment;
  std::vector<std::unique_ptr<CheckMonitor>> monitors;
  Recorder recorder;
  LoopState state;
  std::string checkpoint_buffer;  // reused: one allocation for the run
  double output_seconds = 0;
};

SceneRun::SceneRun(const SceneSpec& spec, const RunControl& control)
    : spec_(spec), control_(control), threads_(run_threads(control.threads, spec)) {
  const auto wall_start = Clock::now();
  const ScopedThreads threads(threads_);  // only while the run works (scoped_threads.hpp)
  RunReport& rep = report_;

  // 1. Setup.
  RunSetup setup;
  sim_ = build_simulation(spec_, setup, control_.ground_acceleration);
  Simulation& sim = *sim_;
  sim.set_parallel_threshold(control_.parallel_threshold);
  sim.set_code_path(control_.code_path);
  rep.blocks = sim.blocks().count;
  rep.free_blocks = static_cast<int>(sim.blocks().free_blocks.size());
  rep.margin = setup.margin;
  rep.detection_travel = sim.detection_travel();
  rep.critical = setup.critical;
  rep.time_step_set_by = spec_.simulation.time_step > 0 ? "deck" : "all-faces bound";
  rep.time_step = setup.time_step;
  rep.initial_time_step = sim.dt();
  // The static stage, also on a restart: it is deterministic, and the
  // monitors and the checkpoint's state start from the state it reaches.
  if (spec_.equilibrium.enabled) {
    rep.equilibrium = solve_equilibrium(spec_.equilibrium, spec_.simulation.gravity, sim);
    rep.profile.equilibrium = rep.equilibrium.wall_seconds;
  }

  // 2. Monitors and the recorder.
  loop_ = std::make_unique<Loop>(spec_, sim);
  loop_->assessment.set_loads_final_time(std::max(
      loads_final_time(spec_), control_.ground_acceleration ? control_.ground_acceleration_final_time : 0.0));
  loop_->wall_start = wall_start;
  LoopState& loop = loop_->state;
  const double end = spec_.simulation.end_time;
  loop.records = Periodic::every(spec_.output.history_interval, 0.0, end);
  loop.snapshots = Periodic::every(spec_.output.snapshot_interval, 0.0, end,
                                   spec_.output.snapshot_interval > 0 && static_cast<bool>(control_.snapshot));
  loop.checkpoints = Periodic::every(spec_.output.checkpoint_interval, spec_.output.checkpoint_interval, end,
                                     spec_.output.checkpoint_interval > 0 && static_cast<bool>(control_.checkpoint));

  if (control_.restart) {
    restore(*control_.restart, control_, sim, loop_->assessment, loop_->monitors, rep, loop_->recorder, loop);
  } else if (loop.snapshots.enabled) {
    control_.snapshot(sim, 0.0);
    loop.snapshots.advance();
  }
  rep.profile.setup = seconds_since(wall_start) - rep.profile.equilibrium;
}

SceneRun::~SceneRun() = default;

void SceneRun::write_checkpoint() {
  const auto t0 = Clock::now();
  std::string& buffer = loop_->checkpoint_buffer;
  buffer.clear();
  ByteWriter w(buffer);
  sim_->save_state(w);
  loop_->assessment.save(w);
  w.put(static_cast<std::uint64_t>(loop_->monitors.size()));
  for (const auto& m : loop_->monitors) m->save(w);
  save_loop(w, report_, loop_->recorder, loop_->state, seconds_since(loop_->wall_start));
  w.put(static_cast<bool>(control_.save_extra));
  if (control_.save_extra) control_.save_extra(w);
  control_.checkpoint(buffer);
  ++report_.checkpoints;
  report_.checkpoint_bytes = static_cast<long>(buffer.size());
  report_.checkpoint_wall_seconds += seconds_since(t0);
}

bool SceneRun::over() const {
  return over_ || finished_ || !(sim_->time() < spec_.simulation.end_time - 0.5 * sim_->dt());
}

// 3. The loop.
long SceneRun::advance(long max_steps, double until) {
  if (over()) return 0;
  const ScopedThreads threads(threads_);
  Simulation& sim = *sim_;
  RunReport& rep = report_;
  LoopState& loop = loop_->state;
  const double end = spec_.simulation.end_time;
  long taken = 0;
  try {
    while (taken < max_steps && sim.time() < end - 0.5 * sim.dt() && sim.time() < until - 0.5 * sim.dt()) {
      sim.step();
      ++taken;
      const auto t_output = Clock::now();
      rep.subcontact_updates += static_cast<long>(sim.contacts().sub.size());
      for (auto& m : loop_->monitors) m->observe(sim);
      loop_->assessment.observe(sim);
      if (spec_.assessment.stop_on_collapse && loop_->assessment.collapsed()) {
        over_ = true;
        break;
      }
      if (loop.records.due(sim.time() - sim.dt())) {
        loop_->recorder.record(sim);
        loop.records.advance();
      }
      if (control_.progress && sim.steps() % control_.progress_every == 0) control_.progress(sim);
      if (loop.snapshots.due(sim.time())) {
        control_.snapshot(sim, sim.time());
        loop.snapshots.advance();
      }
      if (settled(spec_, control_, sim, loop.quiet_since)) {
        rep.settled = true;
        over_ = true;
        break;
      }
      if (loop.checkpoints.due(sim.time())) {
        loop.checkpoints.skip_past(sim.time());
        write_checkpoint();
      }
      if (control_.after_step) control_.after_step(sim);
      loop_->output_seconds += seconds_since(t_output);
    }
  } catch (const InstabilityError& e) {
    // Stop, but keep what was computed: the histories so far and the state
    // of the last passed check.
    rep.unstable = true;
    rep.instability = e.what();
    over_ = true;
  }
  return taken;
}

// 4. The end.
const RunReport& SceneRun::finish() {
  if (finished_) return report_;
  finished_ = true;
  const ScopedThreads threads(threads_);
  Simulation& sim = *sim_;
  RunReport& rep = report_;
  const auto t_end = Clock::now();
  if (loop_->recorder.energies_on && !rep.unstable) loop_->recorder.record(sim);  // the final state is always in the ledger
  if (loop_->state.snapshots.passed_last(sim.time())) control_.snapshot(sim, sim.time());
  finish_report(rep, sim, loop_->recorder, loop_->assessment, loop_->monitors);
  loop_->output_seconds += seconds_since(t_end);
  rep.wall_seconds = loop_->state.wall_before + seconds_since(loop_->wall_start);
  const StepProfile& sp = sim.profile();
  rep.profile.detection = sp.detection;
  rep.profile.patch = sp.patch;
  rep.profile.joint_law = sp.joint_law;
  rep.profile.gather_update = sp.gather_update;
  rep.profile.guard = sp.guard;
  rep.profile.output = loop_->output_seconds;
  rep.profile.steps = sim.steps();
  rep.profile.threads_given = sp.threads_given;
  const ThreadGovernor& g = sim.thread_governor();
  rep.profile.thread_probes = g.probes;
  rep.profile.thread_switches = g.switches;
  rep.profile.thread_stall_drops = g.stall_drops;
  rep.profile.steps_on_one_thread = g.steps_on_one;
  rep.profile.total = seconds_since(loop_->wall_start);
  return rep;
}

RunReport run_scene(const SceneSpec& spec, const RunControl& control) {
  SceneRun run(spec, control);
  run.advance(std::numeric_limits<long>::max());
  return run.finish();
}

}  // namespace polydem
