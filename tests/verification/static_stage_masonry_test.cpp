// The static stage at the default safety factor on masonry whose blocks sit
// close to the step's frequency bound (issue 32): local damping raises a
// force against the velocity to (1 + α) times itself, and without the
// stage's (1 + α) inertia these cases chattered without equilibrium (the
// wall's stage under gravity alone, a ratio of 36 after 10⁶ steps; the arch
// at 0.25 g, 200,000 steps).
#include "static_stage_masonry.hpp"

#include "run/run_scene.hpp"
#include "studies/collapse_search.hpp"

#include <iostream>

namespace polydem {
namespace {

using namespace static_stage_masonry;

// The 182-unit wall reaches equilibrium under its weight, its units moving
// microns (the joints' settlement under 1.5 m of stone).
TEST(StaticStageMasonry, SmallUnitWallReachesEquilibrium) {
  SceneSpec s = small_unit_wall();
  ASSERT_EQ(s.simulation.safety_factor, 0.8);
  s.equilibrium.enabled = true;
  s.simulation.end_time = 0.001;
  s.ground_motion.acceleration = 0;
  const RunReport r = run_scene(s);
  ASSERT_FALSE(r.unstable) << r.instability;
  ASSERT_TRUE(r.equilibrium.ran);
  std::cout << "  wall: equilibrium in " << r.equilibrium.steps << " steps, ratio " << r.equilibrium.ratio
            << ", largest movement " << r.equilibrium.max_displacement << " m\n";
  EXPECT_LE(r.equilibrium.ratio, s.equilibrium.ratio);
  EXPECT_LT(r.equilibrium.steps, 30000);  // 9,135 measured
  EXPECT_LT(r.equilibrium.max_displacement, 1e-4);
}

// A static trial on the wall at 0.1 g (0.78 of its b/h) stands.
TEST(StaticStageMasonry, SmallUnitWallStandsAtFourFifthsOfItsLimit) {
  const SceneSpec s = small_unit_wall();
  const double lp = lp_lambda(s, Vec3(0, 1, 0));
  EXPECT_NEAR(lp, 0.2 / 1.568, 1e-5);
  const CollapseTrial t = static_collapse_trial(s, 90.0, 0.1, CollapseSearchOptions{});
  EXPECT_FALSE(t.no_equilibrium) << t.no_equilibrium_detail;
  EXPECT_FALSE(t.collapsed);
  EXPECT_LT(t.assessment.peak_displacement, 1e-3);
}

// The arch's static bisection brackets the limit analysis of the same
// voussoirs (0.3090 g; a four-hinge mechanism), the bracket 0.01 g wide and
// each end within 1 % of the LP's value beyond it (the joints' elastic give
// and the solve's tolerance). Measured [0.3063, 0.3156] g.
TEST(StaticStageMasonry, ArchBisectionBracketsTheLimitAnalysis) {
  const SceneSpec s = arch_of_25();
  ASSERT_EQ(s.simulation.safety_factor, 0.8);
  const double lp = lp_lambda(s, Vec3(1, 0, 0));
  CollapseSearchOptions o;
  o.low_g = 0.25;
  o.high_g = 0.4;
  o.tolerance_g = 0.01;
  const BisectionResult b = bisect_collapse_static(s, 0.0, o);
  ASSERT_TRUE(b.error.empty()) << b.error;
  std::cout << "  arch: LP " << lp << " g, static bracket [" << b.low_g << ", " << b.high_g << "] g in " << b.runs
            << " trials\n";
  EXPECT_LE(b.low_g, 1.01 * lp);
  EXPECT_GE(b.high_g, 0.99 * lp);
  EXPECT_LE(b.high_g - b.low_g, o.tolerance_g + 1e-12);
}

}  // namespace
}  // namespace polydem
