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

}  // namespace
}  // namespace polydem
