// polydem: the command line. Subcommands: run, analytic, mesh.
#include "apps/analytic_command.hpp"
#include "apps/mesh_command.hpp"
#include "apps/run_command.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"polydem: discrete elements for rigid convex polyhedral blocks (masonry under earthquakes)"};
  app.set_version_flag("--version", std::string("polydem ") + POLYDEM_VERSION);
  app.require_subcommand(1);

  polydem::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a deck: writes DIR/summary.json and DIR/results.h5");
  run_cmd->add_option("deck", run.deck_path, "Deck file (TOML)");
  run_cmd->add_flag("--default", run.use_default, "Run the built-in default deck (the main job)");
  run_cmd->add_option("--out", run.out_dir, "Output directory")->capture_default_str();
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (0: OMP_NUM_THREADS or all cores)");
  run_cmd->add_option("--set", run.overrides, "Override a deck key: section.key=value (repeatable)");
  run_cmd->add_flag("--quiet", run.quiet, "No progress or report on stderr");

  auto* analytic_cmd = app.add_subcommand("analytic", "Analytical models of the paper (polydem analytic --help)");
  analytic_cmd->prefix_command();  // everything after `analytic` goes to the model's own parser
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
  if (run_cmd->parsed()) {
    if (run.deck_path.empty() && !run.use_default) {
      std::cerr << "polydem run: give a deck file or --default\n";
      return polydem::exit_bad_input;
    }
    return polydem::run_command(run);
  }
  return 0;
}
