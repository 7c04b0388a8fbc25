// The report names the estimate that set the time step: its frequency and
// damping ratio give back the step the run used, dt = s·(2/ω)(√(1+ξ²) − ξ).
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polydem {
namespace {

void expect_step_from_reported_estimate(const SceneSpec& spec, const RunReport& r) {
  const double w = r.critical.omega_max, xi = r.critical.damping_ratio;
  EXPECT_NEAR(xi, 0.5 * spec.joint.damping * w, 1e-12 * xi);
  const double critical = (2.0 / w) * (std::sqrt(1.0 + xi * xi) - xi);
  EXPECT_NEAR(r.critical.critical, critical, 1e-12 * critical);
  EXPECT_NEAR(r.time_step, spec.simulation.safety_factor * critical, 1e-12 * critical);
  EXPECT_FALSE(r.time_step_block.empty());
}

// The spire: the joints found at the first detection are stiffer than the
// all-faces bound allows for (the top course's corner stones), and they set
// the step.
TEST(TimeStep, TheSpiresStepIsSetByItsJointsAndReportedSo) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml",
                                   {"simulation.end_time=0.001", "output.histories=[]", "output.walking=false"});
  const RunReport r = run_scene(spec);
  EXPECT_EQ(r.time_step_set_by, "joints at a detection");
  EXPECT_GE(r.time_step_reductions, 1);
  expect_step_from_reported_estimate(spec, r);
  EXPECT_EQ(r.time_step_block.rfind("course19", 0), 0u) << r.time_step_block;
}

// A block on a fixed base: the all-faces bound sets it.
TEST(TimeStep, ARestingBlocksStepIsTheAllFacesBound) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/resting_block.toml",
                                   {"simulation.end_time=0.001"});
  const RunReport r = run_scene(spec);
  EXPECT_EQ(r.time_step_set_by, "all-faces bound");
  expect_step_from_reported_estimate(spec, r);
  EXPECT_EQ(r.time_step_block, "stone");
}

// simulation.time_step_bound = "joint": the first detection's joints, each
// shared between its blocks, lower the all-faces start as the default bound's
// do, and are reported the same way; on the spire the step is 1.143 times the
// default bound's (docs/benchmarks.md; ±0.005).
TEST(TimeStep, TheJointBoundSetsTheSpiresStepFromItsJoints) {
  const std::vector<std::string> base = {"simulation.end_time=0.001", "output.histories=[]", "output.walking=false"};
  auto with = [&](const std::string& bound) {
    std::vector<std::string> set = base;
    set.push_back("simulation.time_step_bound=\"" + bound + "\"");
    return set;
  };
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml";
  const SceneSpec spec = read_deck(path, with("joint"));
  ASSERT_EQ(spec.simulation.time_step_bound, StepBound::joint);
  const RunReport joint = run_scene(spec);
  const RunReport block = run_scene(read_deck(path, with("block")));
  EXPECT_EQ(joint.time_step_set_by, "joints at a detection");
  EXPECT_GE(joint.time_step_reductions, 1);
  expect_step_from_reported_estimate(spec, joint);
  EXPECT_EQ(joint.time_step_block.rfind("course19", 0), 0u) << joint.time_step_block;
  EXPECT_NEAR(joint.time_step / block.time_step, 1.143, 0.005);
}

// The all-faces start caps the joint bound as it caps the default one: a
// block landing on a face after flight or rocking on an edge is integrated
// with the step of its face in full contact (without the cap, the energy
// of the undamped rocking block, energy_conservation.toml, drifts 0.93 %
// against its 0.5 % tolerance). The four-drum column's
// first joints allow more than the start; it keeps the start's step.
TEST(TimeStep, TheJointBoundKeepsTheAllFacesStart) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/column_rocking.toml";
  const RunReport block = run_scene(read_deck(path, {"simulation.end_time=0.001"}));
  const SceneSpec spec = read_deck(path, {"simulation.end_time=0.001", "simulation.time_step_bound=\"joint\""});
  const RunReport joint = run_scene(spec);
  EXPECT_EQ(block.time_step_set_by, "all-faces bound");
  EXPECT_EQ(joint.time_step_set_by, "all-faces bound");
  EXPECT_EQ(joint.time_step, block.time_step);
}

// A deck's own step is kept under the joint bound too.
TEST(TimeStep, ADecksOwnStepIsKeptUnderTheJointBound) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/column_rocking.toml";
  const RunReport r = run_scene(
      read_deck(path, {"simulation.end_time=0.001", "simulation.time_step=1e-5", "simulation.time_step_bound=\"joint\""}));
  EXPECT_EQ(r.time_step_set_by, "deck");
  EXPECT_EQ(r.time_step, 1e-5);
}

}  // namespace
}  // namespace polydem
