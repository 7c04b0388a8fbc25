// The collapse search edits SceneSpec fields instead of re-parsing the deck
// with text overrides: each trial's scene must be the one the overrides gave
// (bit for bit), so that the search finds what it found before.
#include "io/deck.hpp"
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

}  // namespace
}  // namespace polydem
