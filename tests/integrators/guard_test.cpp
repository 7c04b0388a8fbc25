// The guard stops a run that goes wrong, naming the cause, and keeps the
// state of its last passed check.
#include "integrators/simulation.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

std::vector<BlockSpec> block_on_base() {
  BlockSpec base, stone;
  base.name = "base";
  base.shape = make_box(Vec3(2, 2, 0.5), Vec3(0, 0, -0.25));
  base.motion = BlockMotion::fixed;
  stone.name = "stone";
  stone.shape = make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5));
  return {base, stone};
}

// A step above the critical one is lowered at once by the joints found at
// the first detection, and the run stays stable.
TEST(Guard, StepAboveTheCriticalOneIsLoweredAutomatically) {
  SimulationSpec sim;
  JointSpec joint;
  joint.damping = 0;
  Blocks blocks = build_blocks(block_on_base());
  const double critical = critical_time_step(blocks, make_joint_law(joint), 1.0).critical;
  Simulation s = one_law_simulation(std::move(blocks), sim, joint, GroundMotion{}, 0.02, 3.0 * critical);
  // Lowered to the joints' own bound (one face in contact: less stiff than
  // the all-faces bound, so the new step may exceed `critical`).
  const double from_joints = critical_time_step_from_contacts(s.blocks(), s.contacts(), s.joint_laws(), joint.damping, sim.safety_factor).chosen;
  EXPECT_EQ(s.dt(), from_joints);
  EXPECT_LT(s.dt(), 3.0 * critical);
  EXPECT_EQ(s.time_step_reductions(), 1);
  EXPECT_NO_THROW(for (int n = 0; n < 20000; ++n) s.step());
}

// With the automatic lowering off, six times the critical step makes the
// joint spring's oscillation grow without bound. The guard must stop it on
// its energy or penetration test, long before anything is non-finite.
TEST(Guard, UnstableRunIsStoppedWithACause) {
  SimulationSpec sim;
  JointSpec joint;
  joint.damping = 0;
  Blocks blocks = build_blocks(block_on_base());
  const double critical = critical_time_step(blocks, make_joint_law(joint), 1.0).critical;
  Simulation s = one_law_simulation(std::move(blocks), sim, joint, GroundMotion{}, 0.02, 6.0 * critical, /*adaptive_time_step=*/false);
  std::string message;
  try {
    for (int n = 0; n < 100000; ++n) s.step();
  } catch (const InstabilityError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "the guard did not stop an unstable run";
  EXPECT_TRUE(message.find("energy") != std::string::npos || message.find("overlap") != std::string::npos)
      << message;
  EXPECT_NE(message.find("last good state"), std::string::npos) << message;
  // The kept state is finite and earlier than the failure.
  EXPECT_TRUE(s.last_good_state().position[1].allFinite());
  EXPECT_LT(s.last_good_step(), s.steps());
}

// The same scene at the automatic step runs on untouched.
TEST(Guard, StableRunIsNotStopped) {
  SimulationSpec sim;
  JointSpec joint;
  Blocks blocks = build_blocks(block_on_base());
  const double dt = critical_time_step(blocks, make_joint_law(joint), 0.8).chosen;
  Simulation s = one_law_simulation(std::move(blocks), sim, joint, GroundMotion{}, 0.02, dt);
  EXPECT_NO_THROW(for (int n = 0; n < 20000; ++n) s.step());
  EXPECT_EQ(s.last_good_step(), s.steps() - s.steps() % 256);
}

}  // namespace
}  // namespace polydem
