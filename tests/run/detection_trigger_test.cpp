// The joints re-sampled pair by pair (simulation.detection_trigger =
// "pair") in whole runs: what a checkpoint must hold for it.
#include "run/run_scene.hpp"

#include "restart_check.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem {
namespace {

// A restart from a checkpoint ends bit for bit as the run that was not
// stopped: each pair's poses when it was sampled decide when it is
// re-sampled next, and the count of re-samplings goes on. The 52-stone
// dry-stone wall under a pulse, its pairs re-sampled between checkpoints.
TEST(DetectionTrigger, APairByPairRunRestartsBitwise) {
  const SceneSpec spec = pulsed_wall_with_checkpoints("simulation.detection_trigger=\"pair\"");
  const RunReport whole = expect_restart_continues_bitwise(spec);
  EXPECT_GT(whole.pairs_resampled, 2 * static_cast<long long>(whole.detections));
}

}  // namespace
}  // namespace polydem
