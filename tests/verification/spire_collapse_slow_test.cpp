// The full-resolution spire (402 blocks) under a ramp of 0.1 g/s normal to
// a window face: the mechanism forms between the limit-analysis multiplier
// of the block model and 30 % above it (measured: 0.217 g against 0.171;
// the ramp's lag and the finite joint stiffness raise it). Slow label: a few
// minutes on 2 cores.
#include "analytical/refined_lambda.hpp"
#include "run/run_scene.hpp"
#include "io/deck.hpp"
#include "structures/generator_specs.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

TEST(SpireCollapseSlow, FullSpireUnderARamp) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/collapse_ramp.toml",
                                   {"output.snapshot_interval=0", "output.histories=[]", "assessment.stop_on_collapse=true"});
  RunControl control;
  control.threads = 2;
  const RunReport r = run_scene(spec, control);
  ASSERT_EQ(r.assessment.status, "collapsed");
  const double dem = r.assessment.ground_acceleration_at_damage / 9.81;
  const SpireModel model = build_spire(*spire_of(spec.generators));
  analytical::RefinedLambdaOptions opts;
  opts.directions = {{"face 0", 0.0}};
  const double limit = analytical::refined_lambda(model, spec.blocks.back().density, opts).governing.lambda;
  std::cout << "  full spire: DEM mechanism at " << dem << " g, limit analysis " << limit << " g, " << r.steps
            << " steps, " << r.wall_seconds << " s\n";
  EXPECT_GT(dem, limit * 0.95);
  EXPECT_LT(dem, limit * 1.3);
}

}  // namespace
}  // namespace polydem
