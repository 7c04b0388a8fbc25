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

// With [[joint]] between, the default φ is the laws': the pillar's one
// joint takes the pair's 10 degrees, not [joint]'s 30, so it slides at
// tan 10°; two laws with different φ acting are no single default.
TEST(LimitStudy, FrictionAngleDefaultsToTheActingLaws) {
  SceneSpec pillar = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml");
  ASSERT_EQ(pillar.blocks.size(), 2u);
  pillar.blocks[0].group = "a";
  pillar.blocks[1].group = "b";
  JointPairSpec pair;
  pair.group_a = "a";
  pair.group_b = "b";
  pair.joint = pillar.joint;
  pair.joint.friction_angle = 10.0;
  pillar.joint_pairs.push_back(pair);
  LimitStudyOptions o;
  o.directions_deg = {0.0};
  o.pyramids = {FrictionPyramid::inscribed};
  o.method = LpMethod::simplex;
  const LimitStudy s = limit_study(pillar, o);
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_NEAR(s.cases[0].friction_angle_deg, 10.0, 1e-12);
  EXPECT_NEAR(s.cases[0].results[0].lambda, std::tan(10.0 * M_PI / 180.0), 1e-9);
  // A second group pair with its own φ: both act, no single default.
  SceneSpec three = pillar;
  three.blocks.push_back(three.blocks[1]);
  three.blocks.back().name = "second";
  three.blocks.back().group = "c";
  JointPairSpec other = pair;
  other.group_b = "c";
  other.joint.friction_angle = 20.0;
  three.joint_pairs.push_back(other);
  EXPECT_THROW(limit_study(three, o), std::invalid_argument);
}

}  // namespace
}  // namespace polydem
