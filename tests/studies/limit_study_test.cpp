// The table of limit-analysis cases (studies/limit_study.hpp) on the pillar
// of rocking_onset.toml (0.5 x 0.5 x 2 m on a fixed base, friction 30
// degrees): lambda = min(b/h, tan phi) in every direction of a face.
#include "studies/limit_study.hpp"

#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polydem {
namespace {

TEST(LimitStudy, EveryDirectionThenEveryFrictionAngle) {
  const SceneSpec pillar = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml");
  LimitStudyOptions o;
  o.directions_deg = {0.0, 90.0};
  o.friction_angles_deg = {10.0, 30.0};
  o.pyramids = {FrictionPyramid::inscribed};
  o.method = LpMethod::simplex;
  const LimitStudy s = limit_study(pillar, o);
  ASSERT_EQ(s.cases.size(), 4u);
  EXPECT_EQ(s.free_blocks, 1);
  EXPECT_EQ(s.deck, pillar.deck_path);
  const double slide = std::tan(10.0 * M_PI / 180.0);
  for (int k = 0; k < 4; ++k) {
    const LimitCase& c = s.cases[k];
    EXPECT_EQ(c.direction_deg, o.directions_deg[k / 2]);
    EXPECT_EQ(c.friction_angle_deg, o.friction_angles_deg[k % 2]);
    ASSERT_EQ(c.results.size(), 1u);
    EXPECT_NEAR(c.results[0].lambda, k % 2 ? 0.25 : slide, 1e-9) << k;
  }
}

TEST(LimitStudy, FrictionAngleDefaultsToTheDecks) {
  const SceneSpec pillar = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml");
  const LimitStudy s = limit_study(pillar, LimitStudyOptions{});
  EXPECT_EQ(s.options.friction_angles_deg, std::vector<double>{pillar.joint.friction_angle});
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_EQ(s.cases[0].results.size(), 2u);  // circumscribed, inscribed
  EXPECT_GE(s.cases[0].results[0].lambda, s.cases[0].results[1].lambda - 1e-9);
}

}  // namespace
}  // namespace polydem
