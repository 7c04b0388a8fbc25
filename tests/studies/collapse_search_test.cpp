// The collapse search edits SceneSpec fields instead of re-parsing the deck
// with text overrides: each trial's scene must be the one the overrides gave
// (bit for bit), so that the search finds what it found before.
#include "io/deck.hpp"
#include "run/run_scene.hpp"
#include "studies/collapse_search.hpp"

#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <numbers>

namespace polydem {
namespace {

const std::string kDeck = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/rocking_onset.toml";

std::string direction_override(double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  return fmt::format("ground_motion.direction=[{:.17g}, {:.17g}, 0.0]", std::cos(a), std::sin(a));
}

void expect_same_ground_motion(const SceneSpec& a, const SceneSpec& b) {
  EXPECT_EQ(a.ground_motion.kind, b.ground_motion.kind);
  EXPECT_EQ(a.ground_motion.acceleration, b.ground_motion.acceleration);
  EXPECT_EQ(a.ground_motion.rate, b.ground_motion.rate);
  EXPECT_EQ(a.ground_motion.rise_time, b.ground_motion.rise_time);
  EXPECT_EQ(a.ground_motion.direction, b.ground_motion.direction);
  EXPECT_EQ(a.simulation.end_time, b.simulation.end_time);
  EXPECT_EQ(a.simulation.settle_velocity, b.simulation.settle_velocity);
  EXPECT_EQ(a.assessment.stop_on_collapse, b.assessment.stop_on_collapse);
  EXPECT_EQ(a.output.energies, b.output.energies);
  EXPECT_EQ(a.output.histories.size(), b.output.histories.size());
}

TEST(CollapseSearch, ConstantAccelerationSceneEqualsTheDeckWithOverrides) {
  const SceneSpec base = read_deck(kDeck);
  for (double deg : {0.0, 22.5, 90.0}) {
    const double a_g = 0.1875, rise = 0.5, hold = 2.5;
    const SceneSpec typed = constant_acceleration_scene(base, deg, a_g, rise, hold);
    const SceneSpec parsed =
        read_deck(kDeck, {"ground_motion.kind=constant", fmt::format("ground_motion.acceleration_g={:.17g}", a_g),
                          fmt::format("ground_motion.rise_time={:.17g}", rise), direction_override(deg),
                          fmt::format("simulation.end_time={:.17g}", rise + hold), "assessment.stop_on_collapse=true",
                          "output.energies=false", "output.histories=[]"});
    expect_same_ground_motion(typed, parsed);
  }
}

TEST(CollapseSearch, RampSceneEqualsTheDeckWithOverrides) {
  const SceneSpec base = read_deck(kDeck);
  const double deg = 45.0, rate = 0.1, a_max = 0.6;
  const SceneSpec typed = ramp_scene(base, deg, rate, a_max);
  const SceneSpec parsed =
      read_deck(kDeck, {"ground_motion.kind=ramp", fmt::format("ground_motion.rate_g={:.17g}", rate),
                        direction_override(deg), fmt::format("simulation.end_time={:.17g}", a_max / rate),
                        "simulation.settle_velocity=0", "assessment.stop_on_collapse=true", "output.energies=false",
                        "output.histories=[]"});
  expect_same_ground_motion(typed, parsed);
}

// The slender block of rocking_onset.toml (b/h = 0.25): the bisection
// brackets its static collapse acceleration, tan(alpha) = 0.25 g, and the
// ramp finds the onset there too.
TEST(CollapseSearch, BisectionBracketsTheBlocksOverturningAcceleration) {
  const SceneSpec base = read_deck(kDeck);
  CollapseSearchOptions o;
  o.low_g = 0.1;
  o.high_g = 0.5;
  o.tolerance_g = 0.02;
  o.rise_time = 0.2;
  o.hold_time = 1.5;
  int trials = 0;
  const BisectionResult b = bisect_collapse(base, 0.0, o, [&](const char*, const CollapseTrial&) { ++trials; });
  ASSERT_TRUE(b.error.empty()) << b.error;
  EXPECT_EQ(trials, b.runs);
  EXPECT_LE(b.low_g, 0.25 + 1e-9);
  EXPECT_GE(b.high_g, 0.25);
  EXPECT_LE(b.high_g - b.low_g, o.tolerance_g);
}

// The static search (a static solve per trial) on a 0.5 × 0.5 × 1 m block:
// it tips at λ = b/h = 0.5 exactly when friction holds (φ = 45°), and slides
// at λ = tan φ when it does not (φ = 20°: 0.36397). Each bracket of 0.004 g
// must hold the exact value, widened by the solve's tolerance: an
// unbalanced force below static_ratio (1e-4 of the weight) counts as
// equilibrium, so the bracket may sit up to ~1e-4 g above it.
constexpr const char* kTallBlock = R"(
[simulation]
end_time = 1.0
[joint]
normal_stiffness = 1e9
friction_angle = 45
[[block]]
name = "base"
shape = "box"
size = [4.0, 4.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"
[[block]]
name = "block"
shape = "box"
size = [0.5, 0.5, 1.0]
center = [0.0, 0.0, 0.5]
)";

// A trial whose acceleration rises slowly starts at rest: it must not stop as
// "settled" before the acceleration has reached its value. The tall block
// (tips at 0.5 g) under 0.6 g rising over 3 s, settle_velocity 1 mm/s for
// 0.3 s: it collapses (before settling waited for the loads, the same run
// stopped as settled and intact at t = 0.98 s, under 0.2 g). And below the
// threshold it settles only after the rise.
TEST(CollapseSearch, ASlowRiseIsNotTakenForSettling) {
  SceneSpec base = parse_deck(kTallBlock, "tall.toml");
  base.simulation.settle_velocity = 1e-3;
  base.simulation.settle_time = 0.3;
  const RunReport above = run_scene(constant_acceleration_scene(base, 0.0, 0.6, 3.0, 2.0));
  EXPECT_EQ(above.assessment.status, "collapsed");
  EXPECT_FALSE(above.settled);
  const RunReport below = run_scene(constant_acceleration_scene(base, 0.0, 0.3, 3.0, 2.0));
  EXPECT_NE(below.assessment.status, "collapsed");
  EXPECT_TRUE(below.settled);
  EXPECT_GE(below.end_time, 3.0 + 0.3);
}

TEST(CollapseSearch, StaticBisectionFindsTippingAndSlidingOfABlock) {
  CollapseSearchOptions o;
  o.low_g = 0.2;
  o.high_g = 0.7;
  o.tolerance_g = 0.004;
  const double slack = 2 * o.static_ratio;
  const BisectionResult tip = bisect_collapse_static(parse_deck(kTallBlock, "block.toml"), 0.0, o);
  ASSERT_TRUE(tip.error.empty()) << tip.error;
  EXPECT_LE(tip.low_g, 0.5 + slack);
  EXPECT_GE(tip.high_g, 0.5);
  EXPECT_LE(tip.high_g - tip.low_g, o.tolerance_g);
  EXPECT_FALSE(tip.last_collapse.no_equilibrium);

  const BisectionResult slide =
      bisect_collapse_static(parse_deck(kTallBlock, "block.toml", {"joint.friction_angle=20"}), 90.0, o);
  ASSERT_TRUE(slide.error.empty()) << slide.error;
  const double tan_phi = std::tan(20.0 * std::numbers::pi / 180.0);
  EXPECT_LE(slide.low_g, tan_phi + slack);
  EXPECT_GE(slide.high_g, tan_phi);
}

// A trial below the threshold stands at rest; one above moves its block
// beyond collapse_displacement.
TEST(CollapseSearch, StaticTrialStandsBelowAndCollapsesAbove) {
  const SceneSpec s = parse_deck(kTallBlock, "block.toml");
  CollapseSearchOptions o;
  const CollapseTrial below = static_collapse_trial(s, 0.0, 0.45, o);
  EXPECT_FALSE(below.collapsed);
  EXPECT_LT(below.assessment.peak_displacement, 1e-3);
  const CollapseTrial above = static_collapse_trial(s, 0.0, 0.55, o);
  EXPECT_TRUE(above.collapsed);
  EXPECT_FALSE(above.no_equilibrium);
}

// A static solve that runs out of steps is neither a collapse nor a stand:
// the trial says which block is still unbalanced and the search stops with
// that, instead of counting it as a collapse (which put a false bracket on
// the spire at φ = 20°: docs/equilibrium.md).
TEST(CollapseSearch, AStaticSolveOutOfStepsIsNoEquilibriumNotACollapse) {
  const SceneSpec s = parse_deck(kTallBlock, "block.toml");
  CollapseSearchOptions o;
  o.static_max_steps = 40;  // far too few to settle the block under 0.3 g
  const CollapseTrial t = static_collapse_trial(s, 0.0, 0.3, o);
  EXPECT_TRUE(t.no_equilibrium);
  EXPECT_FALSE(t.collapsed);
  EXPECT_EQ(t.assessment.status, "no_equilibrium");
  EXPECT_NE(t.no_equilibrium_detail.find("block 'block'"), std::string::npos) << t.no_equilibrium_detail;
  o.low_g = 0.3;
  o.high_g = 0.7;
  const BisectionResult b = bisect_collapse_static(s, 0.0, o);
  EXPECT_EQ(b.runs, 1);
  EXPECT_NE(b.error.find("found no equilibrium in --static-max-steps = 40"), std::string::npos) << b.error;
  EXPECT_NE(b.error.find("not counted either way"), std::string::npos) << b.error;
}

// ...but a mechanism still under way when the steps run out (a block tipping
// over slowly under local damping, already well past the damage
// displacement) is a collapse.
TEST(CollapseSearch, AStaticSolveOutOfStepsWithAMechanismUnderWayIsACollapse) {
  const SceneSpec s = parse_deck(kTallBlock, "block.toml");
  CollapseSearchOptions o;
  o.static_increments = 1;
  o.static_max_steps = 1200;  // the block has moved ~6 cm of the 10 cm collapse displacement
  const CollapseTrial t = static_collapse_trial(s, 0.0, 0.7, o);
  EXPECT_TRUE(t.no_equilibrium);
  EXPECT_TRUE(t.collapsed);
  EXPECT_EQ(t.assessment.status, "collapsed");
  EXPECT_NE(t.no_equilibrium_detail.find("a mechanism under way"), std::string::npos) << t.no_equilibrium_detail;
  EXPECT_LT(t.assessment.peak_displacement, s.assessment.collapse_displacement);  // the monitor had not seen it
}

}  // namespace
}  // namespace polydem
