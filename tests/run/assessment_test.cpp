// The assessment's default monitor block is the highest free block against
// gravity, whichever axis gravity points along.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

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
