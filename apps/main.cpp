// polydem: the command line. Subcommands: run, collapse, sweep, ensemble, ida, analytic, mesh.
#include "apps/analytic_command.hpp"
#include "apps/collapse_command.hpp"
#include "apps/ensemble_command.hpp"
#include "apps/ida_command.hpp"
#include "apps/mesh_command.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_command.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"polydem: discrete elements for rigid convex polyhedral blocks (masonry under earthquakes)"};
  app.set_version_flag("--version", std::string("polydem ") + POLYDEM_VERSION);
  app.require_subcommand(1);

  polydem::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a deck: writes DIR/summary.json and DIR/results.h5");
  run_cmd->add_option("deck", run.deck_path, "Deck file (TOML)");
  run_cmd->add_flag("--default", run.use_default, "Run the built-in default deck (the main job)");
  auto* run_out = run_cmd->add_option("--out", run.out_dir, "Output directory")->capture_default_str();
  run_cmd->add_option("--threads", run.threads,
                      "OpenMP threads (0: the deck's simulation.threads, else OMP_NUM_THREADS or all cores)");
  run_cmd->add_option("--set", run.overrides, "Override a deck key: section.key=value (repeatable)");
  run_cmd->add_flag("--quiet", run.quiet, "No progress, report or verdict");
  run_cmd->add_flag("--verbose", run.verbose, "Also the step statistics and where the time went (stage profile)");
  run_cmd->add_option("--restart", run.restart_dir,
                      "Continue from DIR/checkpoint.bin (output.checkpoint_interval) and write the results into DIR; "
                      "give the same deck and --set options as the original run");

  polydem::CollapseOptions col;
  auto* collapse_cmd = app.add_subcommand("collapse", "Collapse acceleration under a constant horizontal acceleration");
  collapse_cmd->add_option("deck", col.deck_path, "Deck file (TOML)");
  collapse_cmd->add_flag("--default", col.use_default, "Use the built-in default deck");
  collapse_cmd->add_option("--out", col.out_dir, "Output directory")->capture_default_str();
  collapse_cmd->add_option("--direction", col.directions_deg, "Azimuth of the ground motion, degrees (repeatable)");
  collapse_cmd->add_option("--method", col.method,
                           "bisection | ramp | both (bisection and ramp) | static (bisection by static solves)")
      ->check(CLI::IsMember({"bisection", "ramp", "both", "static"}))->capture_default_str();
  collapse_cmd->add_option("--static-increments", col.static_increments, "static: load increments per trial")
      ->check(CLI::PositiveNumber)->capture_default_str();
  collapse_cmd->add_option("--static-ratio", col.static_ratio, "static: unbalanced-force ratio that counts as solved")
      ->check(CLI::PositiveNumber)->capture_default_str();
  collapse_cmd->add_option("--static-max-steps", col.static_max_steps, "static: steps an increment may take")
      ->check(CLI::PositiveNumber)->capture_default_str();
  collapse_cmd->add_flag("--density-scaling", col.density_scaling,
                         "static: density scaling (each block vibrates at the step's frequency)");
  collapse_cmd->add_option("--low", col.low_g, "Lower end of the bracket, g")->capture_default_str();
  collapse_cmd->add_option("--high", col.high_g, "Upper end of the bracket, g")->capture_default_str();
  collapse_cmd->add_option("--tolerance", col.tolerance_g, "Bracket width to stop at, g")->capture_default_str();
  collapse_cmd->add_option("--rise-time", col.rise_time, "Rise of each constant acceleration, s")->capture_default_str();
  collapse_cmd->add_option("--hold-time", col.hold_time, "Hold after the rise, s")->capture_default_str();
  collapse_cmd->add_option("--ramp-rate", col.ramp_rate_g, "Ramp rate, g/s")->capture_default_str();
  collapse_cmd->add_option("--threads", col.threads, "OpenMP threads");
  collapse_cmd->add_option("--set", col.overrides, "Override a deck key (repeatable)");
  collapse_cmd->add_flag("--quiet", col.quiet, "No per-run lines on stderr");

  polydem::SweepOptions sweep;
  auto* sweep_cmd = app.add_subcommand(
      "sweep", "Run a deck over a grid of key values (local processes or mpirun), with a boundary search: "
               "DIR/sweep.csv, boundaries.csv, sweep.h5; resumable");
  sweep_cmd->add_option("deck", sweep.deck_path, "Deck file (TOML)");
  sweep_cmd->add_flag("--default", sweep.use_default, "Use the built-in default deck");
  sweep_cmd->add_option("--out", sweep.out_dir, "Output directory (finished points in DIR/points are reused)")
      ->capture_default_str();
  sweep_cmd->add_option("--vary", sweep.vary, "KEY=START:STOP:N or KEY=V1,V2,... (repeatable; full grid)");
  sweep_cmd->add_option("--search", sweep.search,
                        "KEY=START:STOP:N: for each --vary point, a coarse scan of N values of KEY, then "
                        "bisection of every change of class (intact/damaged/Mode I/Mode II) to --resolution");
  sweep_cmd->add_option("--resolution", sweep.resolution, "Bracket width the boundary search stops at (KEY's unit)");
  sweep_cmd->add_option("--jobs", sweep.jobs, "Local worker processes (0: cores / threads)")->capture_default_str();
  sweep_cmd->add_option("--threads", sweep.threads, "OpenMP threads of each run")->capture_default_str();
  sweep_cmd->add_option("--set", sweep.overrides, "Override a deck key for every point (repeatable)");
  sweep_cmd->add_option("--replicas", sweep.replicas,
                        "Each point as an ensemble of N replicas (polydem ensemble): DIR/ensembles.csv");
  sweep_cmd->add_option("--seed", sweep.seed, "Seed of the replicas' perturbations (with --replicas)");
  sweep_cmd->add_option("--band-axis", sweep.band_axis,
                        "With --replicas: a --vary KEY of intensity; per column of the other keys, the lognormal "
                        "fit of damage, stones lost and collapse along it: DIR/bands.csv");
  sweep_cmd->add_flag("--quiet", sweep.quiet, "Only the final table");

  polydem::EnsembleOptions ens;
  auto* ensemble_cmd = app.add_subcommand(
      "ensemble", "Run N replicas of a deck with seeded small perturbations (local processes or mpirun): "
                  "DIR/replicas.csv, ensemble.csv, ensemble.json; --resume continues");
  ensemble_cmd->add_option("deck", ens.deck_path, "Deck file (TOML)");
  ensemble_cmd->add_flag("--default", ens.use_default, "Use the built-in default deck");
  ensemble_cmd->add_option("--replicas", ens.replicas, "Number of replicas N (replica 0 is the deck as written)");
  ensemble_cmd->add_option("--seed", ens.seed, "Seed of the perturbations (default: the deck's ensemble.seed, 1)");
  ensemble_cmd->add_option("--out", ens.out_dir, "Output directory (replicas in DIR/points)")->capture_default_str();
  ensemble_cmd->add_option("--jobs", ens.jobs, "Local worker processes (0: cores / threads)")->capture_default_str();
  ensemble_cmd->add_option("--threads", ens.threads, "OpenMP threads of each run")->capture_default_str();
  ensemble_cmd->add_option("--set", ens.overrides, "Override a deck key for every replica (repeatable)");
  ensemble_cmd->add_flag("--resume", ens.resume, "Continue an ensemble in DIR: replicas finished on disk are kept");
  ensemble_cmd->add_flag("--quiet", ens.quiet, "Only the final table");

  polydem::IdaOptions ida;
  auto* ida_cmd = app.add_subcommand(
      "ida", "Incremental dynamic analysis (hunt-and-fill to collapse) or multiple stripes of a deck under a record "
             "suite (local processes or mpirun): DIR/ida.csv, capacities.csv, ida.json; --resume continues");
  ida_cmd->add_option("suite", ida.suite_path, "Record suite file (TOML, docs/records.md)")->required();
  ida_cmd->add_option("deck", ida.deck_path, "Deck file (TOML); its ground motion is replaced by each record");
  ida_cmd->add_flag("--default", ida.use_default, "Use the built-in default deck");
  ida_cmd->add_option("--im", ida.im, "Intensity measure: pga, or sa (with --period)")->capture_default_str();
  ida_cmd->add_option("--period", ida.period, "T1 (s) of Sa(T1)");
  ida_cmd->add_option("--damping", ida.damping, "Damping ratio of Sa")->capture_default_str();
  ida_cmd->add_option("--hunt", ida.hunt, "FIRST:STEP:GROWTH of the hunt's IMs, g (default 0.05:0.05:0.05)");
  ida_cmd->add_option("--tolerance", ida.tolerance, "Collapse bracket and fill stop below this IM width (g)")
      ->capture_default_str();
  ida_cmd->add_option("--max-runs", ida.max_runs, "Runs per record")->capture_default_str();
  ida_cmd->add_option("--stripes", ida.stripes, "IM1,IM2,...: every record at each IM (multiple stripes)");
  ida_cmd->add_option("--scales", ida.scales, "F1,F2,...: every record at each scale factor");
  ida_cmd->add_option("--out", ida.out_dir, "Output directory (runs in DIR/points)")->capture_default_str();
  ida_cmd->add_option("--jobs", ida.jobs, "Local worker processes (0: cores / threads)")->capture_default_str();
  ida_cmd->add_option("--threads", ida.threads, "OpenMP threads of each run")->capture_default_str();
  ida_cmd->add_option("--set", ida.overrides, "Override a deck key for every run (repeatable)");
  ida_cmd->add_flag("--resume", ida.resume, "Continue an analysis in DIR: runs finished on disk are kept");
  ida_cmd->add_flag("--quiet", ida.quiet, "Only the final table");

  auto* analytic_cmd = app.add_subcommand("analytic", "Analytical models of the paper (polydem analytic --help)");
  analytic_cmd->prefix_command();  // the models and their options: apps/analytic_command.cpp
  analytic_cmd->set_help_flag();

  polydem::MeshOptions mesh;
  auto* mesh_cmd = app.add_subcommand("mesh", "Build a deck's blocks (e.g. its [spire]): DIR/blocks.vtu and a summary");
  mesh_cmd->add_option("deck", mesh.deck_path, "Deck file (TOML)")->required();
  mesh_cmd->add_option("--out", mesh.out_dir, "Output directory")->capture_default_str();
  mesh_cmd->add_option("--set", mesh.overrides, "Override a deck key: section.key=value (repeatable)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : polydem::exit_bad_input;
  }
  if (analytic_cmd->parsed()) return run_analytic_command(analytic_cmd->remaining());
  if (mesh_cmd->parsed()) return polydem::mesh_command(mesh);
  if (sweep_cmd->parsed()) {
    if (sweep.deck_path.empty() && !sweep.use_default) {
      std::cerr << "polydem sweep: error: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    if (!sweep.search.empty() && !(sweep.resolution > 0)) {
      std::cerr << "polydem sweep: error: --search needs --resolution (the bracket width to bisect down to)\n";
      return polydem::exit_bad_input;
    }
    return polydem::sweep_command(sweep);
  }
  if (ida_cmd->parsed()) {
    if (ida.deck_path.empty() && !ida.use_default) {
      std::cerr << "polydem ida: error: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    return polydem::ida_command(ida);
  }
  if (ensemble_cmd->parsed()) {
    if (ens.deck_path.empty() && !ens.use_default) {
      std::cerr << "polydem ensemble: error: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    return polydem::ensemble_command(ens);
  }
  if (collapse_cmd->parsed()) {
    if (col.deck_path.empty() && !col.use_default) {
      std::cerr << "polydem collapse: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    return polydem::collapse_command(col);
  }
  if (run_cmd->parsed()) {
    if (run.deck_path.empty() && !run.use_default) {
      std::cerr << "polydem run: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    if (!run.restart_dir.empty() && run_out->count() > 0 &&
        std::filesystem::path(run.out_dir).lexically_normal() !=
            std::filesystem::path(run.restart_dir).lexically_normal()) {
      std::cerr << "polydem run: --restart DIR writes its results into DIR; drop --out or give the same directory\n";
      return polydem::exit_bad_input;
    }
    return polydem::run_command(run);
  }
  return 0;
}
