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
constexpr const char* kFallingStone = R"(
[simulation]
end_time = 0.6

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
  EXPECT_NEAR(a.moving_speed_limit, std::sqrt(2 * 9.81 * 0.005), 1e-3);
  EXPECT_TRUE(a.dislodged_blocks.empty());
}

}  // namespace
}  // namespace polydem
