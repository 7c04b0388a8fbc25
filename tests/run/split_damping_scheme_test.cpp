// The split damping scheme (simulation.damping_scheme = "split") in whole
// runs: the blocks it predicts velocities for, as the run moves them.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include "restart_check.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace polydem {
namespace {

// A ground motion applied kinematically moves the kinematic base; a fixed
// slab beside it stays where it is, and so must the stone resting on it.
// The split scheme's second pass takes each joint's relative velocity from
// the blocks' velocities over the step: a fixed block's is zero whatever
// the ground does (taken as the ground's, the rest of the dashpot dragged
// the stone 2.8 mm along with the ground, and the ledger's error rose to
// 1.6e-3).
TEST(SplitDampingScheme, AFixedBlockUnderAKinematicGroundMotionStaysStill) {
  const std::string deck =
      "[simulation]\nend_time = 0.4\ndamping_scheme = \"split\"\n[joint]\nnormal_stiffness = 1e10\n"
      "friction_angle = 35.0\ndamping = 2e-4\n"
      "[ground_motion]\nkind = \"sine_pulse\"\napplied_as = \"kinematic\"\ndirection = [1.0, 0.0, 0.0]\n"
      "acceleration_g = 0.5\nperiod = 0.4\n"
      "[[block]]\nname = \"ground\"\nshape = \"box\"\nsize = [2, 2, 0.5]\ncenter = [-3, 0, -0.25]\n"
      "motion = \"kinematic\"\n"
      "[[block]]\nname = \"slab\"\nshape = \"box\"\nsize = [2, 2, 0.5]\ncenter = [3, 0, -0.25]\nmotion = \"fixed\"\n"
      "[[block]]\nname = \"stone\"\nshape = \"box\"\nsize = [0.5, 0.5, 0.5]\ncenter = [3, 0, 0.25]\n"
      "[[block]]\nname = \"rider\"\nshape = \"box\"\nsize = [0.5, 0.5, 0.5]\ncenter = [-3, 0, 0.25]\n";
  const RunReport r = run_scene(parse_deck(deck, "fixed_slab.toml"));
  ASSERT_FALSE(r.unstable) << r.instability;
  EXPECT_GT(r.damping_split_fraction, 0.0);
  // The stone on the fixed slab: at rest on its joint (µm of settling).
  EXPECT_LT(std::abs(r.final_position[2].x() - 3.0), 1e-6);
  // The rider on the moving ground went with it (the pulse moves the
  // ground by a·T²/(2π) = 0.125 m).
  EXPECT_GT(r.final_position[3].x() - r.final_position[0].x() + 3.0, -1e-3);
  EXPECT_GT(r.final_position[0].x() + 3.0, 0.05);
  EXPECT_LT(r.energy_balance_error, 1e-3);
}

}  // namespace
}  // namespace polydem

namespace polydem {
namespace {

// A restart from a checkpoint under the split scheme (its θ taken again from
// the restored step, its per-block rest work and the half still to book
// restored) ends bit for bit as the run that was not stopped: the 52-stone
// dry-stone wall under a pulse.
TEST(SplitDampingScheme, ARestartContinuesBitwise) {
  const SceneSpec spec = pulsed_wall_with_checkpoints("simulation.damping_scheme=\"split\"");
  const RunReport whole = expect_restart_continues_bitwise(spec);
  ASSERT_GT(whole.damping_split_fraction, 0.0);
  EXPECT_GT(whole.energy.damping, 0.0);
}

}  // namespace
}  // namespace polydem
