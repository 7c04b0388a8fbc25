// The joints re-sampled pair by pair (simulation.detection_trigger =
// "pair") in whole runs: what a checkpoint must hold for it.
#include "io/deck.hpp"
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
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/dry_stone_wall.toml";
  const SceneSpec spec =
      read_deck(path, {"simulation.detection_trigger=\"pair\"", "simulation.end_time=0.03",
                       "output.checkpoint_interval=0.01", "ground_motion.kind=\"sine_pulse\"",
                       "ground_motion.acceleration_g=0.5", "ground_motion.period=0.05",
                       "ground_motion.direction=[1.0, 0.0, 0.0]"});
  const RunReport whole = expect_restart_continues_bitwise(spec);
  EXPECT_GT(whole.pairs_resampled, 2 * static_cast<long long>(whole.detections));
}

}  // namespace
}  // namespace polydem
