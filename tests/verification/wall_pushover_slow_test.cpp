// Verification (issue 13), the slow half (`ctest -L slow`): a wall pushover against a limit analysis of the
// same wall, examples/verification/wall_pushover.toml (a dry running-bond
// wall 2.0 x 1.5 m, one leaf 0.2 m thick, 33 units, on a fixed base; friction
// 30 degrees).
//
// Out of plane (azimuth 90 degrees) the wall tips about the leading edge of
// its base as one body: λ = b/h = 0.2/1.5 exactly (every bed joint above the
// base would need t/(h - z) > t/h; sliding tan 30 = 0.577). The LP on the
// initial joint mesh gives it to 1e-6, and the DEM's collapse bisection
// must bracket it: the bracket is the search's tolerance wide, and the
// DEM's only other departure from the rigid-block answer is the joints'
// elastic give (microns under 1.5 m of stone), far below 0.005 g.
//
// In plane (azimuth 0) the LP finds a sliding mechanism (9 units, 10 sliding
// joints) at 0.4837 g. The LP's flow rule is associative (sliding comes with
// dilatancy tan φ), so its λ is an upper bound on the collapse of joints that
// slide without dilating, as the DEM's do: a DEM trial at or below it must
// collapse (the bracket's upper end ≤ λ_LP); measured 4.2 % below
// (bisection [0.4617, 0.4656] g at 0.005 g); the test allows down to
// 0.85 λ_LP.
#include "io/deck.hpp"
#include "studies/collapse_search.hpp"
#include "limit_lambda.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace polydem {
namespace {

const std::string kDeckPath = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/wall_pushover.toml";

TEST(WallPushover, InPlaneDemCollapsesBelowTheLimitAnalysisUpperBound) {
  const SceneSpec s = read_deck(kDeckPath);
  const double lp = lp_lambda(s, Vec3(1, 0, 0));
  CollapseSearchOptions o;
  o.low_g = 0.40;
  o.high_g = 0.56;
  o.tolerance_g = 0.02;
  const BisectionResult b = bisect_collapse(s, 0.0, o);
  ASSERT_TRUE(b.error.empty()) << b.error;
  std::cout << "  in plane: LP " << lp << ", DEM bracket [" << b.low_g << ", " << b.high_g << "] g in " << b.runs
            << " runs\n";
  EXPECT_LE(b.high_g, lp) << "a trial at or below the LP's upper bound must collapse";
  EXPECT_GE(b.high_g, 0.85 * lp);
}

}  // namespace
}  // namespace polydem
