// `polydem run`: deck in, summary.json and results.h5 out.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace polydem {

class Simulation;

// Exit codes, documented in the README.
enum ExitCode : int {
  exit_success = 0,
  exit_check_failed = 1,  // the run finished but a verification check failed
  exit_bad_input = 2,     // deck, record or geometry rejected; nothing written
  exit_instability = 3,   // the run stopped on a non-finite state
};

struct RunOptions {
  std::string deck_path;          // empty with use_default
  bool use_default = false;       // the built-in default deck
  std::string out_dir = "out";
  int threads = 0;
  bool quiet = false;    // no progress, report or verdict
  bool verbose = false;  // the step statistics and the stage profile too
  std::vector<std::string> overrides;  // "key=value"
  // Continue the run whose checkpoint is DIR/checkpoint.bin (written with
  // output.checkpoint_interval) and write the results into DIR. The deck and
  // overrides must be those of the original run.
  std::string restart_dir;
  // Called after every step (run/run_scene.hpp RunControl::after_step).
  std::function<void(const Simulation&)> after_step;
};

int run_command(const RunOptions& options);


}  // namespace polydem
