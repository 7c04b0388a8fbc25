// The joints re-sampled pair by pair (simulation.detection_trigger =
// "pair", the subcontact model's default) in whole runs: which runs do,
// and what a checkpoint must hold for it.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include "restart_check.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem {
namespace {

// A deck that does not name the trigger re-samples pair by pair under the
// subcontact model and scene-wide under the overlap model (which samples
// nothing); naming it decides, and "pair" is refused with the overlap model.
TEST(DetectionTrigger, PairByPairByDefaultSceneWideUnderTheOverlapModel) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/resting_block.toml";
  EXPECT_TRUE(pair_by_pair(read_deck(path).simulation));
  EXPECT_FALSE(pair_by_pair(read_deck(path, {"simulation.detection_trigger=\"scene\""}).simulation));
  EXPECT_FALSE(pair_by_pair(read_deck(path, {"simulation.joint_model=\"overlap\""}).simulation));
  EXPECT_THROW(read_deck(path, {"simulation.joint_model=\"overlap\"", "simulation.detection_trigger=\"pair\""}),
               DeckError);
}

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
