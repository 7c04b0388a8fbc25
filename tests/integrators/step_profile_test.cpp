// StepProfile: every step is counted and its stages timed; the profile is
// not part of the checkpointed state.
//
// Scene: a unit cube falling from 5 mm above a fixed base, within the 20 mm
// margin, so that the steps detect contacts and build patches.
#include "integrators/simulation.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem {
namespace {

BlockSpec box_spec(const std::string& name, Vec3 size, Vec3 centre, BlockMotion motion) {
  BlockSpec s;
  s.name = name;
  s.shape = make_box(size, centre);
  s.density = 2000.0;
  s.motion = motion;
  return s;
}

Simulation dropped_cube() {
  return one_law_simulation(build_blocks({box_spec("base", Vec3(3, 3, 1), Vec3(0, 0, -0.5), BlockMotion::fixed),
                                  box_spec("cube", Vec3(1, 1, 1), Vec3(0, 0, 0.505), BlockMotion::free)}),
                    SimulationSpec{}, JointSpec{}, GroundMotion{}, 0.02, 1e-5);
}

TEST(StepProfile, CountsEveryStepAndTimesEachStage) {
  Simulation s = dropped_cube();
  EXPECT_EQ(s.profile().steps, 0);
  EXPECT_EQ(s.profile().joint_law, 0.0);
  for (int n = 0; n < 600; ++n) s.step();
  const StepProfile& p = s.profile();
  EXPECT_EQ(p.steps, 600);
  EXPECT_EQ(p.steps, s.steps());
  for (double t : {p.detection, p.patch, p.joint_law, p.gather_update, p.guard}) {
    EXPECT_GE(t, 0.0);
    EXPECT_LT(t, 60.0);
  }
  EXPECT_GT(p.detection + p.patch + p.joint_law + p.gather_update, 0.0);
  EXPECT_GT(s.contacts().sub.size(), 0u);
}

TEST(StepProfile, IsNotCheckpointed) {
  Simulation a = dropped_cube();
  for (int n = 0; n < 300; ++n) a.step();
  std::string saved;
  ByteWriter w(saved);
  a.save_state(w);

  Simulation b = dropped_cube();
  ByteReader r(saved);
  b.load_state(r);
  EXPECT_EQ(b.profile().steps, 0);  // the resumed run counts its own steps only
  EXPECT_EQ(b.steps(), 300);
  std::string again;
  ByteWriter w2(again);
  b.save_state(w2);
  EXPECT_EQ(again, saved);  // nothing of the profile in the payload
}

}  // namespace
}  // namespace polydem
