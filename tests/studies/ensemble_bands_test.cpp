// Bands from a grid of ensembles (studies/ensemble_bands.hpp): the fit
// recovers the median and dispersion of synthetic outcomes drawn from known
// lognormal capacities, leaves out the replicas without a verdict (and
// counts them), reports bounds where there is no fit, and the observed
// fractions of a point count each replica once in every outcome it reached.
#include "studies/ensemble_bands.hpp"

#include "analytical/probability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polydem {
namespace {

using Rows = std::vector<std::pair<SweepPoint, PointResult>>;

const std::string kAxis = "ground_motion.acceleration_g";
const std::string kColumn = "ground_motion.period";

PointResult replica(const std::string& status, int dislodged = 0) {
  PointResult r;
  r.status = status;
  r.dislodged = dislodged;
  r.collapse_mode.assign(status == "collapsed" ? 1 : 0, 'I');
  return r;
}

SweepPoint at(double period, double a) { return SweepPoint{{{kColumn, period}, {kAxis, a}}}; }

// The grid of the tip's figure: a_p = 0.2 ... 3.0 g by 0.1 g.
std::vector<double> amplitudes() {
  std::vector<double> a;
  for (int i = 2; i <= 30; ++i) a.push_back(i / 10.0);
  return a;
}

// Capacities θ·e^(βz) with one z per replica for all three outcomes (so
// they stay nested: damaged before stones lost before collapse). A replica
// at amplitude a reaches each outcome whose capacity is at most a.
struct Truth {
  double theta[3];
  double beta[3];
};
constexpr Truth kTruth = {{0.6, 1.2, 1.5}, {0.25, 0.30, 0.35}};

Rows synthetic_column(double period, int replicas, std::uint64_t seed, const Truth& truth = kTruth) {
  analytical::RandomStream rs(seed);
  Rows rows;
  for (double a : amplitudes())
    for (int k = 0; k < replicas; ++k) {
      const double z = rs.normal();
      int reached = 0;
      for (int i = 0; i < 3; ++i) reached += truth.theta[i] * std::exp(truth.beta[i] * z) <= a ? 1 : 0;
      const char* status[] = {"intact", "damaged", "damaged", "collapsed"};
      rows.emplace_back(at(period, a), replica(status[reached], reached == 2 ? 3 : 0));
    }
  return rows;
}

TEST(EnsembleBands, RecoverTheMedianAndDispersionOfSyntheticOutcomes) {
  // 29 points of 200 replicas: the standard error of ln θ is about 0.01.
  const auto bands = fit_bands({kColumn}, kAxis, synthetic_column(1.0, 200, 7));
  ASSERT_EQ(bands.size(), 1u);
  ASSERT_EQ(bands[0].outcomes.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const OutcomeBand& b = bands[0].outcomes[i];
    SCOPED_TRACE(b.outcome);
    EXPECT_EQ(b.status, "fitted");
    EXPECT_NEAR(std::log(b.at50 / kTruth.theta[i]), 0.0, 0.04);
    EXPECT_NEAR(b.beta / kTruth.beta[i], 1.0, 0.12);
    EXPECT_NEAR(b.at16, b.at50 * std::exp(-b.beta), 1e-12);
    EXPECT_NEAR(b.at84, b.at50 * std::exp(b.beta), 1e-12);
    EXPECT_EQ(b.runs, 29 * 200);
    EXPECT_LT(b.largest_gap, 0.12);  // the observed fractions scatter by √(p(1−p)/200) ≤ 0.035
    // The observed 50 % lies in the bracket, one grid step wide.
    EXPECT_LE(b.below, kTruth.theta[i] + 0.1);
    EXPECT_GE(b.above, kTruth.theta[i] - 0.1);
    EXPECT_NEAR(b.above - b.below, 0.1, 1e-9);
  }
  EXPECT_STREQ(bands[0].outcomes[0].outcome, "damage");
  EXPECT_STREQ(bands[0].outcomes[1].outcome, "stones_lost");
  EXPECT_STREQ(bands[0].outcomes[2].outcome, "collapse");
}

TEST(EnsembleBands, FewReplicasStillBracketTheTruth) {
  // 20 replicas a point, as the tip's figure: over 20 seeds the fitted
  // median of collapse stays within 10 % of θ and the mean β within 15 %.
  double mean_beta = 0.0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const OutcomeBand b = fit_bands({kColumn}, kAxis, synthetic_column(1.0, 20, seed))[0].outcomes[2];
    ASSERT_EQ(b.status, "fitted") << seed;
    EXPECT_NEAR(std::log(b.at50 / 1.5), 0.0, 0.1) << seed;
    mean_beta += b.beta / 20;
  }
  EXPECT_NEAR(mean_beta / 0.35, 1.0, 0.15);
}

TEST(EnsembleBands, ReplicasWithoutAVerdictAreLeftOutAndCounted) {
  // A quarter of the replicas end undetermined and one in twenty fails,
  // whatever they would have done: left out, the fits stay where they were;
  // read as intact, they would drag every median up.
  Rows rows = synthetic_column(1.0, 200, 11);
  analytical::RandomStream rs(3);
  long undetermined = 0, failed = 0;
  for (auto& [point, r] : rows) {
    const double u = rs.uniform();
    if (u < 0.25) {
      r = replica("undetermined");
      ++undetermined;
    } else if (u < 0.30) {
      r = replica(u < 0.275 ? "unstable" : "error");
      ++failed;
    }
  }
  const auto bands = fit_bands({kColumn}, kAxis, rows)[0].outcomes;
  Rows as_intact = rows;
  for (auto& [point, r] : as_intact)
    if (r.status == "undetermined") r = replica("intact");
  const auto biased = fit_bands({kColumn}, kAxis, as_intact)[0].outcomes;
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(bands[i].outcome);
    EXPECT_EQ(bands[i].undetermined, undetermined);
    EXPECT_EQ(bands[i].failed, failed);
    EXPECT_EQ(bands[i].runs, 29 * 200 - undetermined - failed);
    EXPECT_NEAR(std::log(bands[i].at50 / kTruth.theta[i]), 0.0, 0.05);
    EXPECT_GT(std::log(biased[i].at50 / kTruth.theta[i]), 0.1);
  }
}

TEST(EnsembleBands, NoFitGivesTheBracketOfTheFiftyPerCentPoint) {
  Rows rows;
  const std::vector<double> a = {0.5, 0.6, 0.7, 0.8};
  auto add = [&](double period, double x, const std::string& status, int n) {
    for (int k = 0; k < n; ++k) rows.emplace_back(at(period, x), replica(status));
  };
  // Column 1: never damaged; column 2: always collapsed; column 3: a sharp
  // step between 0.6 and 0.7; column 4: a step with one point between
  // (3 of 10 at 0.7); column 5: nothing but undetermined runs.
  for (double x : a) {
    add(1.0, x, "intact", 10);
    add(2.0, x, "collapsed", 10);
    add(3.0, x, x < 0.65 ? "intact" : "collapsed", 10);
    add(4.0, x, x < 0.65 ? "intact" : "collapsed", x == 0.7 ? 3 : 10);
    if (x == 0.7) add(4.0, x, "intact", 7);
    add(5.0, x, "undetermined", 10);
  }
  const auto bands = fit_bands({kColumn}, kAxis, rows);
  ASSERT_EQ(bands.size(), 5u);
  const OutcomeBand& none = bands[0].outcomes[2];
  EXPECT_EQ(none.status, "none_reached");
  EXPECT_DOUBLE_EQ(none.below, 0.8);
  EXPECT_TRUE(std::isnan(none.above));
  EXPECT_TRUE(std::isnan(none.at50));
  const OutcomeBand& all = bands[1].outcomes[0];
  EXPECT_EQ(all.status, "all_reached");
  EXPECT_TRUE(std::isnan(all.below));
  EXPECT_DOUBLE_EQ(all.above, 0.5);
  const OutcomeBand& step = bands[2].outcomes[2];
  EXPECT_EQ(step.status, "not_identified");
  EXPECT_DOUBLE_EQ(step.below, 0.6);
  EXPECT_DOUBLE_EQ(step.above, 0.7);
  EXPECT_TRUE(std::isnan(step.beta));
  const OutcomeBand& one_between = bands[3].outcomes[2];
  EXPECT_EQ(one_between.status, "not_identified");
  EXPECT_DOUBLE_EQ(one_between.below, 0.7);  // 3 of 10 at 0.7: under half
  EXPECT_DOUBLE_EQ(one_between.above, 0.8);
  EXPECT_EQ(one_between.reached, 13);
  const OutcomeBand& nothing = bands[4].outcomes[1];
  EXPECT_EQ(nothing.status, "no_runs");
  EXPECT_EQ(nothing.runs, 0);
  EXPECT_EQ(nothing.undetermined, 40);
  // Columns in increasing order, each with its value.
  for (std::size_t c = 0; c < bands.size(); ++c) {
    ASSERT_EQ(bands[c].column.values.size(), 1u);
    EXPECT_DOUBLE_EQ(bands[c].column.values[0].second, 1.0 + static_cast<double>(c));
  }
}

TEST(EnsembleBands, AFallAboveTheFirstRiseIsLeftOutOfItsFit) {
  // Collapses out of 20 at 0.5 ... 1.2 g: a rise to certainty at 0.9 g,
  // then a window at 1.1 g where 5 survive (a Mode I region closing before
  // Mode II). The fit is the rise's alone, and the window is named.
  const std::vector<std::pair<double, int>> counts = {{0.5, 0}, {0.6, 2},  {0.7, 8},  {0.8, 15},
                                                      {0.9, 20}, {1.0, 20}, {1.1, 15}, {1.2, 20}};
  Rows all, rise;
  for (const auto& [x, collapsed] : counts)
    for (int k = 0; k < 20; ++k) {
      all.emplace_back(at(1.0, x), replica(k < collapsed ? "collapsed" : "damaged"));
      if (x < 0.95) rise.push_back(all.back());
    }
  const OutcomeBand alone = fit_bands({kColumn}, kAxis, rise)[0].outcomes[2];
  const OutcomeBand b = fit_bands({kColumn}, kAxis, all)[0].outcomes[2];
  ASSERT_EQ(alone.status, "fitted");
  EXPECT_EQ(b.status, "fitted");
  EXPECT_DOUBLE_EQ(b.at50, alone.at50);
  EXPECT_DOUBLE_EQ(b.beta, alone.beta);
  EXPECT_DOUBLE_EQ(b.falls_back, 1.1);
  EXPECT_TRUE(std::isnan(alone.falls_back));
  EXPECT_EQ(b.runs, 160);
  EXPECT_EQ(b.reached, 100);
  // The rise: 50 % between 0.7 and 0.8 g, β about 0.2.
  EXPECT_GT(b.at50, 0.7);
  EXPECT_LT(b.at50, 0.8);
  EXPECT_NEAR(b.beta, 0.2, 0.1);
  // Fitted with the window, the band would be wider.
  analytical::FragilityOptions o;
  o.method = analytical::FragilityMethod::stripes;
  o.bootstrap = 0;
  std::vector<analytical::FragilityRun> runs;
  for (const auto& [point, r] : all) runs.push_back({"", point.values[1].second, *replica_state(r)});
  EXPECT_GT(analytical::fit_fragility(runs, o).states[2].curve.beta, 1.3 * b.beta);
}

TEST(EnsembleBands, ObservedFractionsCountEachReplicaInEveryOutcomeItReached) {
  const std::vector<PointResult> replicas = {replica("intact"),      replica("damaged"),
                                             replica("damaged", 2),  replica("collapsed"),
                                             replica("undetermined"), replica("error")};
  const OutcomeFractions f = outcome_fractions(replicas);
  EXPECT_EQ(f.judged, 4);
  EXPECT_DOUBLE_EQ(f.p[0], 0.75);  // damage: all but the intact one
  EXPECT_DOUBLE_EQ(f.p[1], 0.5);   // stones lost: the one with stones out and the collapse
  EXPECT_DOUBLE_EQ(f.p[2], 0.25);
  EXPECT_TRUE(std::isnan(outcome_fractions({replica("undetermined")}).p[0]));
  EXPECT_FALSE(replica_state(replica("unstable")).has_value());
}

TEST(EnsembleBands, AnAxisValueThatIsNotPositiveIsRefused) {
  const Rows rows = {{at(1.0, 0.0), replica("intact")}};
  EXPECT_THROW((void)fit_bands({kColumn}, kAxis, rows), std::invalid_argument);
}

}  // namespace
}  // namespace polydem
