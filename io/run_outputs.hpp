// What a run leaves in its output directory, whoever ran it: `polydem run`
// (apps/run_command.cpp) and the Python module (python/) call this one
// function, so the two write the same files with the same bits.
//
//   DIR/results.h5            the deck, the histories, the energy ledger (io/summary.hpp)
//   DIR/last_good_state.vtu   unstable runs only: the blocks at the last passed guard check
//   DIR/summary.json          last and atomically: its presence marks a finished run
//
// Snapshots (DIR/vtk/) and checkpoints are written during the run by the
// caller's RunControl hooks (io/snapshots.hpp, io/checkpoint.hpp).
#pragma once

#include "run/run_scene.hpp"

#include <string>

namespace polydem {

// Creates DIR if needed. `threads`: the OpenMP threads the run used (for
// summary.json). Throws std::runtime_error naming the file on a write error.
void write_run_outputs(const std::string& dir, const SceneSpec& spec, const RunReport& report, int threads);

}  // namespace polydem
