// Runs every verification deck in examples/verification/ and requires each of
// its checks (exact or analytical results, tolerances stated in the deck) to
// pass. The decks are what a user runs; this test is what keeps them honest.
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem {
namespace {

std::string deck(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name; }

// Every deck of examples/verification/, and a test's name from a deck's.
constexpr const char* kDecks[] = {"resting_block.toml", "slope_slide.toml", "slope_stick.toml",
                                  "rocking_onset.toml", "free_rocking.toml", "energy_conservation.toml",
                                  "stack_of_ten.toml", "dry_stone_wall.toml", "slope_equilibrium.toml",
                                  "pulse_rocking_body_force.toml", "pulse_rocking_kinematic.toml",
                                  "arch_self_weight.toml", "column_rocking.toml", "cut_wall.toml",
                                  "imported_wall.toml", "dry_base_slide.toml", "three_components.toml"};
std::string deck_test_name(const ::testing::TestParamInfo<const char*>& info) {
  const std::string n = info.param;
  return n.substr(0, n.find('.'));
}

class VerificationDeck : public ::testing::TestWithParam<const char*> {};

TEST_P(VerificationDeck, ChecksPass) {
  const SceneSpec spec = read_deck(deck(GetParam()));
  ASSERT_FALSE(spec.checks.empty()) << "a verification deck must carry checks";
  const RunReport r = run_scene(spec);
  for (const CheckResult& c : r.checks) {
    EXPECT_TRUE(c.passed) << c.name << ": measured " << c.measured << " expected " << c.expected << " tolerance "
                          << c.tolerance << " (" << c.note << ")";
    std::cout << "  " << GetParam() << " " << c.name << ": measured " << c.measured << " expected " << c.expected
              << " " << c.unit << "\n";
  }
  // The numerical line's largest excursion over the energy put in (7.2 %
  // at most over these decks with the contact model of docs/contact.md).
  EXPECT_LT(r.energy_balance_error, 0.1) << "energy ledger does not close";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeck,
                         ::testing::ValuesIn(kDecks), deck_test_name);

// The same decks and checks under the split damping scheme
// (simulation.damping_scheme = "split", docs/deck.md): every analytical
// result the explicit scheme meets, at the split scheme's larger step.
class VerificationDeckSplitDamping : public ::testing::TestWithParam<const char*> {};

TEST_P(VerificationDeckSplitDamping, ChecksPass) {
  const SceneSpec spec = read_deck(deck(GetParam()), {"simulation.damping_scheme=\"split\""});
  const RunReport r = run_scene(spec);
  for (const CheckResult& c : r.checks) {
    EXPECT_TRUE(c.passed) << c.name << ": measured " << c.measured << " expected " << c.expected << " tolerance "
                          << c.tolerance << " (" << c.note << ")";
    std::cout << "  " << GetParam() << " (split) " << c.name << ": measured " << c.measured << " expected "
              << c.expected << " " << c.unit << "\n";
  }
  EXPECT_LT(r.energy_balance_error, 0.1) << "energy ledger does not close";
  std::cout << "  " << GetParam() << " (split): " << r.steps << " steps of " << r.time_step << " s, theta "
            << r.damping_split_fraction << "\n";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeckSplitDamping,
                         ::testing::ValuesIn(kDecks), deck_test_name);

// A check that cannot fail is no check: a slope steeper than friction must
// fail the `stick` check, and a wrong expected value must fail.
TEST(VerificationChecks, CanFail) {
  SceneSpec spec = read_deck(deck("slope_stick.toml"), {"simulation.gravity=[6.0, 0.0, -7.76]"});
  RunReport r = run_scene(spec);
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_FALSE(r.checks[0].passed) << "a block on a 37.7 degree slope with phi = 30 must slide";

  spec = read_deck(deck("resting_block.toml"));
  spec.checks.resize(1);
  spec.checks[0].expected = 1.01 * 25506.0;  // 1 % more than m g
  r = run_scene(spec);
  EXPECT_FALSE(r.checks[0].passed);

  // Friction below tan(alpha) = 0.25: the pillar slides instead of rocking,
  // and its rotation no longer follows the rigid rocking body.
  spec = read_deck(deck("pulse_rocking_body_force.toml"), {"joint.friction_angle=10"});
  r = run_scene(spec);
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_FALSE(r.checks[0].passed) << "measured " << r.checks[0].measured << " expected " << r.checks[0].expected;
}

}  // namespace
}  // namespace polydem
