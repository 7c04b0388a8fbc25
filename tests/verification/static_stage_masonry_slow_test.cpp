// The 182-unit wall's static collapse search at the default safety factor
// (static_stage_masonry_test.cpp has the fast cases): a trial at 0.11 g
// stands and one at 0.15 g collapses, bracketing b/h = 0.1276 (the limit
// analysis); about 20 s of one core. Trials within a few per cent of the
// limit move too slowly to end in --static-max-steps either way (the top at
// 3-4 mm/s after 200,000 steps at 0.13 g), so the bracket stays wide.
#include "static_stage_masonry.hpp"

#include "studies/collapse_search.hpp"

#include <iostream>

namespace polydem {
namespace {

using namespace static_stage_masonry;

TEST(StaticStageMasonrySlow, SmallUnitWallBisectionBracketsTheLimitAnalysis) {
  const SceneSpec s = small_unit_wall();
  const double lp = lp_lambda(s, Vec3(0, 1, 0));
  CollapseSearchOptions o;
  o.low_g = 0.11;
  o.high_g = 0.15;
  o.tolerance_g = 0.05;
  const BisectionResult b = bisect_collapse_static(s, 90.0, o);
  ASSERT_TRUE(b.error.empty()) << b.error;
  std::cout << "  wall: LP " << lp << " g, static bracket [" << b.low_g << ", " << b.high_g << "] g in " << b.runs
            << " trials\n";
  EXPECT_LE(b.low_g, lp);
  EXPECT_GE(b.high_g, lp);
}

}  // namespace
}  // namespace polydem
