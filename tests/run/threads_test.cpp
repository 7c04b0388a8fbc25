// The threads a run is given (run_scene.hpp RunControl::threads): the
// caller's (the command line's --threads), else the deck's
// simulation.threads, else OpenMP's default. summary.json reports them as
// profile.threads.given.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <string>

namespace polydem {
namespace {

std::string block_deck(const std::string& threads_line) {
  return "[simulation]\nend_time = 0.001\n" + threads_line +
         "[joint]\nnormal_stiffness = 1e9\n[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [2, 2, 0.5]\n"
         "center = [0, 0, -0.25]\nmotion = \"fixed\"\n[[block]]\nshape = \"box\"\nsize = [0.3, 0.3, 0.2]\n"
         "center = [0, 0, 0.1]\n";
}

int threads_given(const std::string& deck, int control_threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);  // what OMP_NUM_THREADS=2 gives
  RunControl control;
  control.threads = control_threads;
  const RunReport r = run_scene(parse_deck(deck, "block.toml"), control);
  omp_set_num_threads(before);
  return r.profile.threads_given;
}

TEST(RunThreads, TheDeckSetsThemTheCallerOverrides) {
  EXPECT_EQ(threads_given(block_deck(""), 0), 2) << "no deck key, no caller: OpenMP's default";
  EXPECT_EQ(threads_given(block_deck("threads = 1\n"), 0), 1) << "the deck's simulation.threads";
  EXPECT_EQ(threads_given(block_deck("threads = 1\n"), 2), 2) << "the caller's --threads wins";
  EXPECT_EQ(threads_given(block_deck("threads = 0\n"), 1), 1);
}

// OpenMP's count is the calling thread's setting: a run sets it while it
// works and puts it back, so a deck's threads do not carry over to the next
// run in the same process (Python, in-process sweeps).
TEST(RunThreads, ARunLeavesOpenMPsCountAsItFoundIt) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  RunControl control;
  SceneRun run(parse_deck(block_deck("threads = 1\n"), "block.toml"), control);
  EXPECT_EQ(omp_get_max_threads(), 2) << "after the setup";
  run.advance(10);
  EXPECT_EQ(omp_get_max_threads(), 2) << "after steps";
  const RunReport r = run.finish();
  EXPECT_EQ(r.profile.threads_given, 1);
  EXPECT_EQ(omp_get_max_threads(), 2) << "after the run";
  EXPECT_EQ(threads_given(block_deck(""), 0), 2) << "the next run in the process: OpenMP's default";
  omp_set_num_threads(before);
}

}  // namespace
}  // namespace polydem
