// Runs every verification deck in examples/verification/ and requires each of
// its checks (exact or analytical results, tolerances stated in the deck) to
// pass. The decks are what a user runs; this test is what keeps them honest.
#include "run/run_scene.hpp"
#include "io/deck.hpp"
#include "core/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
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
  // The numerical line's largest excursion over the energy put in: 1 %
  // (issue 31's ledger target); 0.68 % at most over these decks, the
  // rocking column's impacts (docs/results.md).
  EXPECT_LT(r.energy_balance_error, 0.01) << "energy ledger does not close";
  std::cout << "  " << GetParam() << ": ledger " << r.energy_balance_error << "\n";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeck,
                         ::testing::ValuesIn(kDecks), deck_test_name);

// The same decks and checks under the split damping scheme
// (simulation.damping_scheme = "split", docs/deck.md): every analytical
// result the explicit scheme meets, at the split scheme's larger step.
class VerificationDeckSplitDamping : public ::testing::TestWithParam<const char*> {};

// A deck run with one setting changed, each of its checks required to pass
// (printed with `label`).
RunReport run_with_checks(const char* name, const std::string& setting, const std::string& label) {
  const SceneSpec spec = read_deck(deck(name), {setting});
  const RunReport r = run_scene(spec);
  for (const CheckResult& c : r.checks) {
    EXPECT_TRUE(c.passed) << c.name << ": measured " << c.measured << " expected " << c.expected << " tolerance "
                          << c.tolerance << " (" << c.note << ")";
    std::cout << "  " << name << " (" << label << ") " << c.name << ": measured " << c.measured << " expected "
              << c.expected << " " << c.unit << "\n";
  }
  return r;
}

TEST_P(VerificationDeckSplitDamping, ChecksPass) {
  const RunReport r = run_with_checks(GetParam(), "simulation.damping_scheme=\"split\"", "split");
  // The split scheme's step is twice the explicit one's, and the ledger's
  // numerical line on the rocking decks is the impacts' integration, first
  // order in the step: column_rocking's is 1.06 % of the energy put in at
  // safety factor 0.8 and 0.47 % at 0.4, the others 0.71 % at most.
  EXPECT_LT(r.energy_balance_error, 0.015) << "energy ledger does not close";
  std::cout << "  " << GetParam() << " (split): " << r.steps << " steps of " << r.time_step << " s, theta "
            << r.damping_split_fraction << "\n";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeckSplitDamping,
                         ::testing::ValuesIn(kDecks), deck_test_name);

// The same decks and checks with the joints re-sampled scene-wide
// (simulation.detection_trigger = "scene", contact/detection.hpp): every
// analytical result and the ledger's 1 % as pair by pair.
class VerificationDeckSceneTrigger : public ::testing::TestWithParam<const char*> {};

TEST_P(VerificationDeckSceneTrigger, ChecksPass) {
  const RunReport r = run_with_checks(GetParam(), "simulation.detection_trigger=\"scene\"", "scene");
  EXPECT_LT(r.energy_balance_error, 0.01) << "energy ledger does not close";
  EXPECT_EQ(r.pairs_resampled, 0);
  std::cout << "  " << GetParam() << " (scene): " << r.detections << " scene detections, ledger "
            << r.energy_balance_error << "\n";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeckSceneTrigger, ::testing::ValuesIn(kDecks), deck_test_name);

// The same decks and checks with the joints re-sampled at detection
// (simulation.joint_sampling = "detection", docs/contact.md): every
// analytical result and the ledger's 1 % as clipped.
class VerificationDeckAtDetection : public ::testing::TestWithParam<const char*> {};

TEST_P(VerificationDeckAtDetection, ChecksPass) {
  const RunReport r = run_with_checks(GetParam(), "simulation.joint_sampling=\"detection\"", "detection");
  EXPECT_LT(r.energy_balance_error, 0.01) << "energy ledger does not close";
  std::cout << "  " << GetParam() << " (detection): ledger " << r.energy_balance_error << "\n";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeckAtDetection, ::testing::ValuesIn(kDecks), deck_test_name);

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

// The decks whose analytical results hold for a Winkler bed under the overlap
// joint model (simulation.joint_model = "overlap", docs/contact.md). Left
// out: the rocking decks (free_rocking, the pulses, column_rocking: an
// elastic bed with these decks' light damping loses less at each impact than
// Housner's restitution, 0.99 against 0.91), dry_base_slide (cohesion),
// arch_self_weight and slope_stick (their checks pass; their ledgers'
// numerical lines are 16 % of 0.04 J and 10 % of 4 mJ put in), slope_
// equilibrium as written (below), and dry_stone_wall (its checks pass in a
// minute: the overlap model is slow on 182 units).
constexpr const char* kOverlapDecks[] = {"resting_block.toml",  "slope_slide.toml",   "energy_conservation.toml",
                                         "stack_of_ten.toml",   "cut_wall.toml",      "imported_wall.toml",
                                         "three_components.toml"};

class VerificationDeckOverlapModel : public ::testing::TestWithParam<const char*> {};

TEST_P(VerificationDeckOverlapModel, ChecksPass) {
  const RunReport r = run_with_checks(GetParam(), "simulation.joint_model=\"overlap\"", "overlap");
  // No detection re-samples a joint's force and the rocking pillar is not
  // among these decks: 8.4e-5 at most.
  EXPECT_LT(r.energy_balance_error, 1e-3) << "energy ledger does not close";
}

INSTANTIATE_TEST_SUITE_P(Decks, VerificationDeckOverlapModel, ::testing::ValuesIn(kOverlapDecks), deck_test_name);

// A block on a Winkler bed lifts its heel when the resultant leaves the
// middle third of its base: under a slow horizontal ramp, at a/g = b/(3h),
// a third of the rigid block's rocking onset b/h that the subcontacts (the
// base's corners) give. rocking_onset.toml's check measures when the heel
// first opens; its expected value is b/h.
TEST(VerificationOverlapModel, AWinklerBedLiftsItsHeelAtTheMiddleThird) {
  const SceneSpec spec = read_deck(deck("rocking_onset.toml"), {"simulation.joint_model=\"overlap\""});
  const RunReport r = run_scene(spec);
  ASSERT_EQ(r.checks.size(), 1u);
  const double b_over_h = r.checks[0].expected;
  std::cout << "  heel lifts at " << r.checks[0].measured << " g, b/(3h) = " << b_over_h / 3 << "\n";
  EXPECT_NEAR(r.checks[0].measured, b_over_h / 3, 0.005);
}

// On a Winkler bed a rocking block cannot reach b/h: as the resultant nears
// the toe the bed under it narrows to a strip of width c whose pressure
// acts c/3 inside the toe, and the block must turn by θ = 2W/(kn·w·c²) to
// squeeze the strip, moving its centroid θ·h_c towards the toe. A horizontal
// load λW at the centroid's height h_c is held while
//   λ·h_c ≤ b/2 − c/3 − θ·h_c   for some c,
// whose right side is largest at c³ = 12·W·h_c/(kn·w): the limit is
// λ_W = (b − c)/(2·h_c), below b/h by c/(2·h_c). rocking_onset.toml's
// pillar (b = w = 0.5 m, h_c = 1 m, 12.75 kN, kn = 98 GPa/m): c = 14.6 mm,
// λ_W = 0.2427 against b/h = 0.25. The loss grows with the weight a joint
// carries over its width, W·h_c/(kn·w): under the overlap model a tall
// structure on narrow, heavily loaded joints holds less than its rigid
// blocks would; the subcontacts at the base's corners hold the rigid b/h.
TEST(VerificationOverlapModel, APillarOnAWinklerBedTipsAtTheLimitOfItsSqueezedToe) {
  const auto run_at = [](double lambda, const char* model) {
    const std::string a = std::to_string(lambda);
    const SceneSpec spec = read_deck(
        deck("rocking_onset.toml"),
        {std::string("simulation.joint_model=\"") + model + "\"", "ground_motion.kind=\"constant\"",
         "ground_motion.acceleration_g=" + a, "ground_motion.rise_time=2.0", "simulation.end_time=5.0",
         "assessment.stop_on_collapse=true"});
    return run_scene(spec).status;
  };
  const double b = 0.5, w = 0.5, h_c = 1.0, weight = 2600.0 * b * w * 2 * h_c * kGravity, kn = 98e9;
  const double c = std::cbrt(12 * weight * h_c / (kn * w));
  const double lambda_w = (b - c) / (2 * h_c);
  std::cout << "  Winkler limit " << lambda_w << " g, b/h = " << b / (2 * h_c) << "\n";
  EXPECT_EQ(run_at(lambda_w - 0.003, "overlap"), "intact");
  EXPECT_EQ(run_at(lambda_w + 0.002, "overlap"), "collapsed");
  EXPECT_EQ(run_at(lambda_w + 0.002, "subcontacts"), "intact");
}

// slope_equilibrium.toml's bed (kn = 1e7 Pa/m) is so soft that a Winkler bed
// under its 40° load, the resultant 0.42 m from the centre of a 1 m base,
// lifts the heel and sinks the toe 16 mm: the block tips over. At a joint
// stiffness of masonry's order the static stage finds the equilibrium.
TEST(VerificationOverlapModel, SlopeEquilibriumOnAStifferBed) {
  const SceneSpec spec = read_deck(deck("slope_equilibrium.toml"),
                                   {"simulation.joint_model=\"overlap\"", "joint.normal_stiffness=1e9",
                                    "joint.shear_stiffness=1e9"});
  const RunReport r = run_scene(spec);
  for (const CheckResult& c : r.checks) EXPECT_TRUE(c.passed) << c.name << ": measured " << c.measured;
}

}  // namespace
}  // namespace polydem
