// A `polydem run` that dies: runs the deck as the command does and kills
// its own process with SIGKILL after the given step, as a machine that
// dies would, so that the restart test can continue from what it left.
//
//   polydem_killed_run STEP DECK OUT_DIR THREADS [KEY=VALUE ...]
#include "apps/run_command.hpp"
#include "integrators/simulation.hpp"

#include <csignal>
#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: polydem_killed_run STEP DECK OUT_DIR THREADS [KEY=VALUE ...]\n";
    return 2;
  }
  const long kill_at = std::atol(argv[1]);
  polydem::RunOptions o;
  o.deck_path = argv[2];
  o.out_dir = argv[3];
  o.threads = std::atoi(argv[4]);
  o.quiet = true;
  for (int i = 5; i < argc; ++i) o.overrides.emplace_back(argv[i]);
  o.after_step = [kill_at](const polydem::Simulation& sim) {
    if (sim.steps() == kill_at) std::raise(SIGKILL);
  };
  return polydem::run_command(o);
}
