// Ensembles (studies/ensemble.hpp): the perturbations stay within their
// bounds and are the same for the same seed and replica, the deck reader
// applies them (and refuses bad sizes with the key; drops the checks of a
// perturbed replica), and the percentiles and
// counts of a summary against a case computed by hand.
#include "studies/ensemble.hpp"

#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polydem {
namespace {

const std::string kTipDeck = std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/tip_pulse.toml";

// Two free blocks on a fixed base, with a pair law, under a record (the
// synthetic one of examples/spire, sampled every 0.01 s).
const std::string kRecordDeck = R"(
[[joint]]
friction_angle = 30
normal_stiffness = 1e9

[[joint]]
between = ["stones", "stones"]
friction_angle = 40

[[block]]
name = "base"
shape = "box"
size = [2, 2, 0.2]
center = [0, 0, -0.1]
motion = "fixed"

[[block]]
shape = "box"
size = [0.2, 0.2, 0.2]
center = [0, 0, 0.1]
group = "stones"

[[block]]
shape = "box"
size = [0.2, 0.2, 0.2]
center = [0, 0, 0.3]
group = "stones"

[ground_motion]
kind = "record"
record = "synthetic_record.csv"
start_time = 0.1

[[ground_motion.component]]
kind = "sine_pulse"
acceleration = 1
period = 0.5
direction = [0, 1, 0]
)";

SceneSpec record_deck(const std::vector<std::string>& overrides = {}) {
  return parse_deck(kRecordDeck, std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/record_ensemble.toml", overrides);
}

TEST(Ensemble, PerturbationsStayWithinTheirBoundsAndRepeatBySeed) {
  const SceneSpec base = record_deck();
  EXPECT_FALSE(base.ensemble.given);
  const EnsembleSpec sizes;  // the defaults: ±0.5°, ±5 %, below 5e-5 m/s, up to half a sample step
  ASSERT_NEAR(motion_sample_step(base), 0.01, 1e-12);
  double widest_friction = 0, widest_stiffness = 0, latest_shift = 0, fastest = 0;
  for (long k = 1; k <= 400; ++k) {
    const Perturbation p = draw_perturbation(base, k, 7);
    const EnsembleDraw& d = p.drawn;
    ASSERT_LE(std::abs(d.friction_angle_shift), sizes.friction_angle);
    ASSERT_LE(std::abs(d.normal_stiffness_factor - 1), sizes.stiffness);
    ASSERT_LE(std::abs(d.shear_stiffness_factor - 1), sizes.stiffness);
    ASSERT_GE(d.time_shift, 0.0);
    ASSERT_LT(d.time_shift, sizes.time_shift * 0.01);
    ASSERT_EQ(p.velocity.size(), 3u);
    EXPECT_EQ(p.velocity[0].norm(), 0.0);  // the fixed base does not move
    for (int b = 1; b < 3; ++b) ASSERT_LT(p.velocity[b].norm(), sizes.velocity);
    EXPECT_DOUBLE_EQ(d.largest_initial_speed, std::max(p.velocity[1].norm(), p.velocity[2].norm()));
    widest_friction = std::max(widest_friction, std::abs(d.friction_angle_shift));
    widest_stiffness = std::max(widest_stiffness, std::abs(d.normal_stiffness_factor - 1));
    latest_shift = std::max(latest_shift, d.time_shift);
    fastest = std::max(fastest, d.largest_initial_speed);
    // The same seed and replica: the same numbers, bit for bit.
    const Perturbation again = draw_perturbation(base, k, 7);
    ASSERT_EQ(again.drawn.friction_angle_shift, d.friction_angle_shift);
    ASSERT_EQ(again.drawn.time_shift, d.time_shift);
    ASSERT_EQ(again.velocity[2], p.velocity[2]);
  }
  // The draws fill their ranges (400 uniforms: the largest within 2 % of the bound).
  EXPECT_GT(widest_friction, 0.98 * sizes.friction_angle);
  EXPECT_GT(widest_stiffness, 0.98 * sizes.stiffness);
  EXPECT_GT(latest_shift, 0.98 * sizes.time_shift * 0.01);
  EXPECT_GT(fastest, 0.98 * sizes.velocity);
  // Another seed, another replica: other numbers; replica 0: none.
  EXPECT_NE(draw_perturbation(base, 1, 8).drawn.friction_angle_shift,
            draw_perturbation(base, 1, 7).drawn.friction_angle_shift);
  EXPECT_NE(draw_perturbation(base, 2, 7).drawn.friction_angle_shift,
            draw_perturbation(base, 1, 7).drawn.friction_angle_shift);
  const Perturbation none = draw_perturbation(base, 0, 7);
  EXPECT_EQ(none.drawn.friction_angle_shift, 0.0);
  EXPECT_EQ(none.drawn.normal_stiffness_factor, 1.0);
  EXPECT_EQ(none.drawn.time_shift, 0.0);
  EXPECT_EQ(none.drawn.largest_initial_speed, 0.0);
}

TEST(Ensemble, TheReaderAppliesTheReplicasDraw) {
  const SceneSpec base = record_deck();
  const SceneSpec replica = record_deck({"ensemble.replica=3", "ensemble.seed=11"});
  const Perturbation p = draw_perturbation(base, 3, 11);
  const EnsembleDraw& d = replica.ensemble.drawn;
  EXPECT_TRUE(replica.ensemble.given);
  EXPECT_EQ(d.friction_angle_shift, p.drawn.friction_angle_shift);
  EXPECT_EQ(replica.joint.friction_angle, 30 + d.friction_angle_shift);
  EXPECT_EQ(replica.joint_pairs.at(0).joint.friction_angle, 40 + d.friction_angle_shift);
  EXPECT_EQ(replica.joint.normal_stiffness, base.joint.normal_stiffness * d.normal_stiffness_factor);
  EXPECT_EQ(replica.joint_pairs.at(0).joint.shear_stiffness,
            base.joint_pairs.at(0).joint.shear_stiffness * d.shear_stiffness_factor);
  EXPECT_EQ(replica.ground_motion.start_time, 0.1 + d.time_shift);
  EXPECT_EQ(replica.ground_motion.components.at(0).start_time, d.time_shift);  // the same shift for every component
  EXPECT_EQ(replica.blocks[2].velocity, p.velocity[2]);
  // Replica 0 is the deck as written, whatever the sizes and seed.
  const SceneSpec zero = record_deck({"ensemble.seed=11", "ensemble.friction_angle=2"});
  EXPECT_EQ(zero.joint.friction_angle, 30.0);
  EXPECT_EQ(zero.blocks[2].velocity.norm(), 0.0);
  EXPECT_EQ(zero.ground_motion.start_time, 0.1);
  // A verification deck's checks hold for the deck as written only.
  const std::string column = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/column_rocking.toml";
  EXPECT_FALSE(read_deck(column, {"ensemble.replica=0"}).checks.empty());
  EXPECT_TRUE(read_deck(column, {"ensemble.replica=1"}).checks.empty());
  // A pulse with the default sample step: a shift below 0.5 × 0.01 s.
  const SceneSpec tip = read_deck(kTipDeck, {"ensemble.replica=1"});
  EXPECT_GT(tip.ground_motion.start_time, 0.0);
  EXPECT_LT(tip.ground_motion.start_time, 0.005);
}

TEST(Ensemble, BadSizesAreRefusedWithTheirKey) {
  const std::pair<const char*, const char*> cases[] = {
      {"ensemble.friction_angle=-1", "key 'ensemble.friction_angle'"},
      {"ensemble.friction_angle=10", "key 'ensemble.friction_angle'"},
      {"ensemble.stiffness=0.6", "key 'ensemble.stiffness'"},
      {"ensemble.time_shift=2", "key 'ensemble.time_shift'"},
      {"ensemble.sample_step=0", "key 'ensemble.sample_step'"},
      {"ensemble.velocity=-1e-5", "key 'ensemble.velocity'"},
      {"ensemble.replica=-1", "key 'ensemble.replica'"},
      {"ensemble.seed=-3", "key 'ensemble.seed'"},
      {"ensemble.spread=1", "key 'ensemble.spread'"},
  };
  for (const auto& [override_text, key] : cases) {
    try {
      (void)read_deck(kTipDeck, {override_text});
      ADD_FAILURE() << override_text << " accepted";
    } catch (const DeckError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("tip_pulse.toml"), std::string::npos) << e.what();
    }
  }
  // Initial velocities at or above the settling velocity are not "at rest".
  try {
    (void)read_deck(kTipDeck, {"simulation.settle_velocity=1e-4", "simulation.settle_time=0.1",
                               "ensemble.velocity=1e-4"});
    ADD_FAILURE() << "a velocity at the settling velocity accepted";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("settle_velocity"), std::string::npos) << e.what();
  }
}

TEST(Ensemble, PercentilesAndCountsAgainstAHandComputedCase) {
  // Type 7: the q-quantile at (n − 1)q between order statistics. For
  // {1, 2, 3, 4, 5}: p16 at 0.64 → 1.64, median 3, p84 at 3.36 → 4.36.
  const double nan = std::nan("");
  const Distribution d = distribution({5, nan, 1, 4, 2, 3});
  EXPECT_EQ(d.n, 5);
  EXPECT_NEAR(d.p16, 1.64, 1e-12);
  EXPECT_NEAR(d.median, 3.0, 1e-12);
  EXPECT_NEAR(d.p84, 4.36, 1e-12);
  const Distribution empty = distribution({nan});
  EXPECT_EQ(empty.n, 0);
  EXPECT_TRUE(std::isnan(empty.median));

  std::vector<PointResult> runs(6);
  const char* statuses[] = {"intact", "damaged", "collapsed", "damaged", "undetermined", "error"};
  const double peaks[] = {0.01, 0.04, 0.5, 0.02, 0.3, 0};
  for (int i = 0; i < 6; ++i) {
    runs[i].status = statuses[i];
    runs[i].peak_tip_displacement = peaks[i];
  }
  runs[2].collapse_mode = "II";
  runs[1].ground_acceleration_at_damage_g = 0.31;
  runs[3].ground_acceleration_at_damage_g = 0.27;
  const EnsembleOutcome o = summarise_ensemble(runs);
  EXPECT_EQ(o.replicas, 6);
  const std::vector<std::pair<std::string, long>> counts{
      {"collapsed", 1}, {"damaged", 2}, {"error", 1}, {"intact", 1}, {"undetermined", 1}};
  EXPECT_EQ(o.status_counts, counts);
  EXPECT_EQ(o.mode_I, 0);
  EXPECT_EQ(o.mode_II, 1);
  // The peak over the five runs that measured (the error is left out):
  // {0.01, 0.02, 0.04, 0.3, 0.5}, median 0.04, p84 0.3 + 0.36 × 0.2.
  const auto q = ensemble_quantities();
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (std::string(q[i].name) == "peak_tip_displacement_m") {
      EXPECT_EQ(o.quantities[i].n, 5);
      EXPECT_NEAR(o.quantities[i].median, 0.04, 1e-15);
      EXPECT_NEAR(o.quantities[i].p84, 0.372, 1e-12);
    }
    if (std::string(q[i].name) == "ground_acceleration_at_damage_g") {
      EXPECT_EQ(o.quantities[i].n, 2);
      EXPECT_NEAR(o.quantities[i].median, 0.29, 1e-12);
    }
  }
}

// Per course: each figure's distribution over the replicas that measured
// it; an unstable replica, or one with a different mesh, is left out.
TEST(Ensemble, CourseDistributionsOverTheReplicas) {
  std::vector<PointResult> runs(7);
  for (int i = 0; i < 7; ++i) {
    runs[i].status = i == 5 ? "unstable" : "damaged";
    runs[i].courses.resize(i == 6 ? 3 : 2);
    for (std::size_t k = 0; k < runs[i].courses.size(); ++k) {
      CourseWalking& c = runs[i].courses[k];
      c.level = 0.3 * static_cast<double>(k);
      c.bed_joints = 4;
      c.vertical_joints = 2 + static_cast<int>(k);
      c.vertical_largest = (k + 1) * 1e-3 * (i + 1);  // course 1: 2, 4, ..., 10 mm over replicas 0-4
      c.peak_vertical = 1.0;                         // the same in every replica
    }
  }
  runs[5].courses[1].vertical_largest = 1e3;  // unstable: must not count
  const EnsembleOutcome o = summarise_ensemble(runs);
  ASSERT_EQ(o.courses.size(), 2u);
  EXPECT_NEAR(o.courses[1].level, 0.3, 1e-15);
  EXPECT_EQ(o.courses[1].vertical_joints, 3);
  const auto q = course_quantities();
  ASSERT_EQ(o.courses[1].quantities.size(), q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Distribution& d = o.courses[1].quantities[i];
    EXPECT_EQ(d.n, 5) << q[i].name;  // replicas 0-4: not the unstable one, not the other mesh
    if (std::string(q[i].name) == "residual_vertical_largest_m") {
      EXPECT_NEAR(d.median, 6e-3, 1e-15);               // {2, 4, 6, 8, 10} mm
      EXPECT_NEAR(d.p16, 2e-3 + 0.64 * 2e-3, 1e-15);    // at 0.64
      EXPECT_NEAR(d.p84, 8e-3 + 0.36 * 2e-3, 1e-15);    // at 3.36
    }
    if (std::string(q[i].name) == "max_vertical_m") {
      EXPECT_EQ(d.median, 1.0);
    }
  }
}

}  // namespace
}  // namespace polydem
