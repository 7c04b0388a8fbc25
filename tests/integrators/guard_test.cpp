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

// The penetration test judges the blocks' true overlap, not the joint's
// measure along a plane that no longer faces the contact. Two stones side by
// side, touching on a vertical face, with their joint kept on the plane of
// a bed (the overlap model's plane, carried while the pair stays loaded):
// along that plane the face they share reads as 0.3 m of "overlap", and the
// run must go on. Pushed 0.2 m into each other it must stop, with 0.2 m.
TEST(Guard, JudgesTheBlocksTrueOverlapNotTheJointsMeasure) {
  BlockSpec left, right;
  left.name = "left";
  left.shape = make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5));
  right.name = "right";
  right.shape = make_box(Vec3(1, 1, 1), Vec3(1, 0, 0.5));
  Blocks blocks = build_blocks({left, right});
  ContactSet contacts;
  ContactPair cp;
  cp.a = 0;
  cp.b = 1;
  cp.ref_block = 0;
  contacts.pairs.push_back(cp);
  contacts.joints.resize(1);
  contacts.joints.ref_block[0] = 0;
  contacts.joints.overlap[0] = 0.3;  // along a horizontal plane: the shared face's height, clipped
  Guard g;
  g.restart(blocks.state);
  const EnergyLedger e;
  EXPECT_NO_THROW(check_health(g, blocks, contacts, 0.003, e, Vec3(0, 0, -9.81), 256, 0.01, 1e-5));

  blocks.state.position[1].x() -= 0.2;  // now 0.2 m into the left stone
  contacts.joints.overlap[0] = 0.3;
  std::string message;
  try {
    check_health(g, blocks, contacts, 0.003, e, Vec3(0, 0, -9.81), 512, 0.02, 1e-5);
  } catch (const InstabilityError& err) {
    message = err.what();
  }
  ASSERT_FALSE(message.empty()) << "blocks 0.2 m into each other passed the guard";
  EXPECT_NE(message.find("overlap by 0.2 m"), std::string::npos) << message;
}

}  // namespace
}  // namespace polydem
