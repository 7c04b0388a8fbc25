#include "apps/run_command.hpp"

#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/deck.hpp"
#include "io/run_outputs.hpp"
#include "io/snapshots.hpp"
#include "io/summary.hpp"
#include "io/vtk.hpp"
#include "run/run_scene.hpp"
#include "run/verdict.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace polydem {

namespace {

// On stderr: with --verbose the step statistics and where the time went,
// then the deck's checks and where the results are. On stdout, last: the
// verdict (run/verdict.hpp).
void print_report(const SceneSpec& spec, const RunReport& r, const std::string& out_dir, bool verbose) {
  if (verbose) {
    std::cerr << fmt::format(
        "polydem: {} steps of {:.3e} s to t = {:.4g} s in {:.2f} s ({:.3g} subcontact updates/s)\n", r.steps,
        r.time_step, r.end_time, r.wall_seconds, r.wall_seconds > 0 ? r.subcontact_updates / r.wall_seconds : 0.0);
    const RunProfile& p = r.profile;
    if (p.total > 0 && p.steps > 0)
      std::cerr << fmt::format(
          "polydem: profile {:.1f} us/step: detection {:.0f} %, patch {:.0f} %, joint law {:.0f} %, gather and "
          "update {:.0f} %, guard {:.0f} %, output {:.0f} %, setup {:.0f} %\n",
          1e6 * (p.total - p.setup) / p.steps, 100 * p.detection / p.total, 100 * p.patch / p.total,
          100 * p.joint_law / p.total, 100 * p.gather_update / p.total, 100 * p.guard / p.total,
          100 * p.output / p.total, 100 * p.setup / p.total);
  }
  for (const CheckResult& c : r.checks)
    std::cerr << fmt::format("  check {:<34} measured {:>13.6g} expected {:>13.6g} tol {:>9.3g} {} [{}]\n", c.name,
                             c.measured, c.expected, c.tolerance, c.unit, c.passed ? "passed" : "FAILED");
  std::cerr << "polydem: results in " << out_dir << "/summary.json and " << out_dir << "/results.h5\n";
  std::cerr.flush();
  for (const std::string& line : verdict_lines(spec, r)) std::cout << line << "\n";
  std::cout.flush();
}

}  // namespace

int run_command(const RunOptions& o) {
  SceneSpec spec;
  try {
    spec = o.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, o.overrides)
                         : read_deck(o.deck_path, o.overrides);
  } catch (const std::exception& e) {
    std::cerr << "polydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  for (const std::string& w : spec.warnings) std::cerr << "polydem: warning: " << w << "\n";
  // Checkpoints and restarts: the fingerprint ties a checkpoint to the deck
  // text, the overrides, the record's bytes and the polydem version.
  const std::string out_dir = o.restart_dir.empty() ? o.out_dir : o.restart_dir;
  std::string restart_state;
  std::uint64_t fingerprint = 0;
  if (spec.output.checkpoint_interval > 0 || !o.restart_dir.empty()) {
    fingerprint = run_fingerprint(spec, o.overrides);
  }
  if (!o.restart_dir.empty()) {
    try {
      const std::string path = o.restart_dir + "/" + kCheckpointFile;
      restart_state = decode_checkpoint(read_checkpoint_file(path), fingerprint, path);
    } catch (const std::exception& e) {
      std::cerr << "polydem: error: " << e.what() << "\n";
      return exit_bad_input;
    }
  }

  RunControl control;
  control.threads = o.threads;
  if (!o.restart_dir.empty()) control.restart = &restart_state;
  if (spec.output.checkpoint_interval > 0) {
    control.checkpoint = [&out_dir, fingerprint, made = false](const std::string& state) mutable {
      if (!made) {
        std::filesystem::create_directories(out_dir);
        made = true;
      }
      write_file_atomic(out_dir + "/" + kCheckpointFile, encode_checkpoint(fingerprint, state));
    };
  }
  control.after_step = o.after_step;
  if (!o.quiet) {
    const bool tty = isatty(STDERR_FILENO);
    control.progress_every = 2000;
    control.progress = [tty, end = spec.simulation.end_time,
                        start = std::chrono::steady_clock::now(), last_print = -1.0](const Simulation& sim) mutable {
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!tty && wall - last_print < 5.0) return;
      last_print = wall;
      const double frac = sim.time() / end;
      const double eta = frac > 0 ? wall * (1 - frac) / frac : 0;
      // Where the step's time goes so far (the profile's stages, in %).
      const StepProfile& p = sim.profile();
      const double stepping = std::max(p.detection + p.joint_law + p.gather_update + p.guard, 1e-12);
      std::cerr << fmt::format(
          "{}t = {:.4f} / {:.4g} s  {:.0f} steps/s  dt = {:.3e} s  ETA {:.0f} s  [detect {:.0f}% law {:.0f}% "
          "update {:.0f}%]{}",
          tty ? "\r" : "", sim.time(), end, sim.steps() / std::max(wall, 1e-9), sim.dt(), eta,
          100 * p.detection / stepping, 100 * p.joint_law / stepping, 100 * p.gather_update / stepping,
          tty ? "   " : "\n");
    };
  }
  std::unique_ptr<SnapshotWriter> snapshots;
  if (spec.output.snapshot_interval > 0) {
    snapshots = std::make_unique<SnapshotWriter>(out_dir + "/vtk", spec.output.snapshot_joints);
    control.snapshot = [&snapshots](const Simulation& sim, double t) { snapshots->write(sim, t); };
    control.save_extra = [&snapshots](ByteWriter& w) { snapshots->save(w); };
    control.load_extra = [&snapshots](ByteReader& r) { snapshots->load(r); };
  }
  RunReport report;
  try {
    report = run_scene(spec, control);
  } catch (const StateFormatError& e) {
    std::cerr << "\npolydem: error: " << o.restart_dir << "/" << kCheckpointFile
              << ": the checkpoint does not fit this scene: " << e.what() << "\n";
    return exit_bad_input;
  } catch (const SceneError& e) {
    std::cerr << "\npolydem: error: " << locate_scene_error(e, spec) << "\n";
    return exit_bad_input;
  } catch (const InstabilityError& e) {
    std::cerr << "\npolydem: stopped: " << e.what() << "\n";
    if (snapshots) snapshots->finish();  // the snapshots before the instability stay readable
    return exit_instability;
  } catch (const std::exception& e) {
    std::cerr << "\npolydem: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  if (!o.quiet && isatty(STDERR_FILENO)) std::cerr << "\n";
  if (snapshots) snapshots->finish();

  write_run_outputs(out_dir, spec, report, report.profile.threads_given);
  if (report.unstable) {
    std::cerr << "\npolydem: stopped: " << report.instability << "\npolydem: last good state in " << out_dir
              << "/last_good_state.vtu, results so far in " << out_dir << "/summary.json and results.h5\n";
    return exit_instability;
  }
  if (!o.quiet) print_report(spec, report, out_dir, o.verbose);
  return report.all_checks_passed() ? exit_success : exit_check_failed;
}

}  // namespace polydem
