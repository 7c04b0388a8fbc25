// The assessment's default monitor block is the highest free block against
// gravity, whichever axis gravity points along.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polydem {
namespace {

// Two stones stacked along +y on a fixed base, gravity along −y; the lower
// stone sits higher in z than the top one, so "highest along z" would pick
// the wrong stone.
constexpr const char* kDeck = R"(
[simulation]
end_time = 0.01
gravity = [0.0, -9.81, 0.0]

[joint]
normal_stiffness = 1e9

[[block]]
name = "base"
shape = "box"
size = [2.0, 1.0, 2.0]
center = [0.0, -0.5, 0.0]
motion = "fixed"

[[block]]
name = "lower"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.5, 0.2]

[[block]]
name = "upper"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 1.5, 0.0]
)";

TEST(Assessment, MonitorIsTheHighestBlockAgainstGravity) {
  const RunReport r = run_scene(parse_deck(kDeck, "sideways.toml"));
  EXPECT_EQ(r.assessment.monitor_block, "upper");
}

TEST(Assessment, MonitorIsTheHighestAlongZUnderOrdinaryGravity) {
  std::string text = kDeck;
  const std::string from = "gravity = [0.0, -9.81, 0.0]";
  text.replace(text.find(from), from.size(), "gravity = [0.0, 0.0, -9.81]");
  EXPECT_EQ(run_scene(parse_deck(text, "upright.toml")).assessment.monitor_block, "lower");
}

}  // namespace
}  // namespace polydem

namespace polydem {
namespace {

// A small stone sliding off a large free block and falling: dislodged
// (count, mass, where), and a collapse only when the criterion counts one
// stone as enough (collapse_mass_fraction = 0; the default 0.1 does not).
// It lands corner first at 0.7 s, bounces off the ground (the joint has no
// damping) and drops past its edge: by 2 s it is below the model and the
// pier is at rest, so the verdict is determined.
constexpr const char* kFallingStone = R"(
[simulation]
end_time = 2.0

[joint]
normal_stiffness = 1e9
friction_angle = 10.0

[[block]]
name = "ground"
shape = "box"
size = [8.0, 8.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "pier"
shape = "box"
size = [1.0, 1.0, 2.0]
center = [0.0, 0.0, 1.0]

[[block]]
name = "stone"
shape = "box"
size = [0.2, 0.2, 0.2]
center = [0.35, 0.0, 2.1]
velocity = [3.0, 0.0, 0.0]
)";

TEST(Assessment, AStoneFallingOffIsDislodgedAndCollapseWhenOneStoneCounts) {
  std::string text = kFallingStone;
  text += "\n[assessment]\ncollapse_mass_fraction = 0\n";
  const RunReport r = run_scene(parse_deck(text, "stone.toml"));
  const Assessment& a = r.assessment;
  ASSERT_EQ(a.dislodged_blocks.size(), 1u);
  EXPECT_EQ(a.dislodged_blocks[0], "stone");
  EXPECT_NEAR(a.dislodged_mass, 2600.0 * 0.008, 1e-9);
  EXPECT_NEAR(a.dislodged_mass_fraction, 0.008 / 2.008, 1e-12);
  ASSERT_EQ(a.fallen_blocks.size(), 1u);  // pushed off its base: it ends below its place
  EXPECT_NEAR(a.fallen_mass_fraction, 0.008 / 2.008, 1e-12);
  EXPECT_EQ(a.collapse_reason, "lost mass");
  EXPECT_NEAR(a.dislodged_low_z, 2.1, 1e-12);
  EXPECT_EQ(a.status, "collapsed");
}

TEST(Assessment, AStoneFallingOffLeavesTheStructureDamagedByDefault) {
  const RunReport r = run_scene(parse_deck(kFallingStone, "stone.toml"));
  EXPECT_EQ(r.assessment.dislodged_blocks.size(), 1u);
  EXPECT_EQ(r.assessment.status, "damaged");
  EXPECT_EQ(r.assessment.collapse_time, -1.0);
  EXPECT_EQ(r.assessment.stones_lost(), 1);
}

// A stone still sliding fast when the run ends: where it stops is not
// known yet, so the run is undetermined, not intact or damaged.
TEST(Assessment, AStoneStillSlidingAtTheEndIsUndetermined) {
  const RunReport r = run_scene(parse_deck(R"(
[simulation]
end_time = 0.02

[joint]
normal_stiffness = 1e9
friction_angle = 10.0

[[block]]
name = "ground"
shape = "box"
size = [8.0, 8.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "stone"
shape = "box"
size = [0.2, 0.2, 0.2]
center = [0.0, 0.0, 0.1]
velocity = [3.0, 0.0, 0.0]
)", "slide.toml"));
  const Assessment& a = r.assessment;
  EXPECT_EQ(a.status, "undetermined");
  EXPECT_EQ(a.fastest_block, "stone");
  EXPECT_GT(a.fastest_speed, 2.5);
  EXPECT_NEAR(a.moving_speed_limit, std::sqrt(2 * 9.81 * 0.0005), 1e-3);
  EXPECT_TRUE(a.dislodged_blocks.empty());
}


// A pier (0.6 x 0.6 x 2 m, slenderness 0.29 rad) set rocking about its
// +x edge with the angular velocity that lifts its centre 37.6 mm: it tips
// to 0.18 rad (its centroid 0.18 m out, beyond collapse_displacement),
// short of overturning, and rocks back and forth down to rest. Judged where
// it ends, it is not dislodged and the structure has not collapsed.
TEST(Assessment, APierThatRocksOutAndBackIsNotDislodged) {
  const RunReport r = run_scene(parse_deck(R"(
[simulation]
end_time = 10.0

[joint]
normal_stiffness = 1e10
friction_angle = 40.0

[[block]]
name = "ground"
shape = "box"
size = [4.0, 4.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "pier"
shape = "box"
size = [0.6, 0.6, 2.0]
center = [0.0, 0.0, 1.0]
velocity = [0.712, 0.0, 0.2136]
angular_velocity = [0.0, 0.712, 0.0]
)", "rocking.toml"));
  const Assessment& a = r.assessment;
  EXPECT_GT(a.peak_displacement, 0.15);  // R (sin α − sin(α − 0.18)) = 0.184 m
  EXPECT_TRUE(a.dislodged_blocks.empty());
  EXPECT_TRUE(a.fallen_blocks.empty());
  EXPECT_LT(a.max_residual_displacement, 0.02);
  EXPECT_NE(a.status, "collapsed");
  EXPECT_NE(a.status, "undetermined");
  EXPECT_LT(a.fastest_speed, a.moving_speed_limit);
}

}  // namespace
}  // namespace polydem
