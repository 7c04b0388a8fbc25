// The lognormal fragility fit (analytical/fragility.hpp) and the
// probability it rests on (analytical/probability.hpp): exact values, the
// recovery of a known θ, β from outcomes drawn from that curve (within the
// bootstrap band, and without bias over many seeds), the cases with no
// fit, and bad input.
#include "analytical/fragility.hpp"
#include "analytical/probability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace pa = polydem::analytical;
using pa::DamageState;

namespace {

// IDA outcomes of `records` records whose collapse capacities are drawn
// from the lognormal (θ, β): each record run at its capacity (collapsed)
// and at half of it (intact); a record whose capacity is above `ceiling`
// is run at the ceiling only (intact): censored there.
std::vector<pa::FragilityRun> ida_runs(double theta, double beta, int records, double ceiling, std::uint64_t seed) {
  pa::RandomStream rs(seed);
  std::vector<pa::FragilityRun> runs;
  for (int i = 0; i < records; ++i) {
    std::string name = std::to_string(i);
    name.insert(0, 1, 'r');
    const double c = theta * std::exp(beta * rs.normal());
    if (c > ceiling) {
      runs.push_back({name, ceiling, DamageState::intact});
      continue;
    }
    runs.push_back({name, 0.5 * c, DamageState::intact});
    runs.push_back({name, c, DamageState::collapsed});
  }
  return runs;
}

// Stripes at 0.1, 0.2, ... 1.0, `per` runs each, collapsing with the
// probability of the lognormal (θ, β).
std::vector<pa::FragilityRun> stripe_runs(double theta, double beta, int per, std::uint64_t seed) {
  pa::RandomStream rs(seed);
  std::vector<pa::FragilityRun> runs;
  for (int j = 1; j <= 10; ++j) {
    const double im = 0.1 * j, p = pa::fragility_probability({theta, beta}, im);
    for (int k = 0; k < per; ++k) runs.push_back({"", im, rs.uniform() < p ? DamageState::collapsed : DamageState::intact});
  }
  return runs;
}

const pa::FragilityCurveFit& collapse(const pa::FragilityResult& r) { return r.states.back(); }

// Fits 300 outcome sets drawn from (θ, β): the mean of ln θ̂/θ is 0 within
// 3 standard errors and the mean β̂ is β within 0.02.
void expect_unbiased(pa::FragilityMethod method, double theta, double beta,
                     const std::function<std::vector<pa::FragilityRun>(std::uint64_t)>& draw) {
  pa::FragilityOptions o;
  o.method = method;
  o.bootstrap = 0;
  double sum_log = 0.0, sum_log2 = 0.0, sum_beta = 0.0;
  const int seeds = 300;
  for (int s = 0; s < seeds; ++s) {
    const auto r = pa::fit_fragility(draw(static_cast<std::uint64_t>(s)), o);
    const auto& c = collapse(r);
    ASSERT_EQ(c.status, pa::FitStatus::fitted);
    const double e = std::log(c.curve.theta / theta);
    sum_log += e, sum_log2 += e * e, sum_beta += c.curve.beta;
  }
  const double mean = sum_log / seeds, se = std::sqrt((sum_log2 / seeds - mean * mean) / seeds);
  EXPECT_LT(std::fabs(mean), 3.0 * se + 1e-3) << "mean ln(theta_hat/theta) " << mean << " se " << se;
  EXPECT_NEAR(sum_beta / seeds, beta, 0.02);
}

}  // namespace

TEST(Probability, NormalCdfAndQuantileAreInverse) {
  EXPECT_DOUBLE_EQ(pa::normal_cdf(0.0), 0.5);
  EXPECT_NEAR(pa::normal_cdf(1.0), 0.8413447460685429, 1e-15);
  EXPECT_NEAR(pa::normal_cdf(-3.0), 0.0013498980316300946, 1e-17);
  for (double p : {1e-12, 1e-5, 0.01, 0.02425, 0.3, 0.5, 0.77, 0.99, 1 - 1e-9}) {
    EXPECT_NEAR(pa::normal_cdf(pa::normal_quantile(p)), p, 1e-14 * std::max(p, 1e-2)) << p;
  }
  EXPECT_NEAR(pa::normal_quantile(0.975), 1.959963984540054, 1e-13);
  EXPECT_NEAR(pa::log_normal_cdf(-40.0), -804.60844201, 1e-6);  // no underflow to -inf
  EXPECT_NEAR(pa::log_normal_sf(0.0), std::log(0.5), 1e-15);
}

TEST(Probability, GammaAndBetaAgainstClosedForms) {
  for (double x : {0.01, 0.5, 1.0, 3.0, 20.0}) {
    EXPECT_NEAR(pa::gamma_cdf(1.0, x), 1.0 - std::exp(-x), 1e-14) << x;          // exponential
    EXPECT_NEAR(pa::gamma_cdf(2.0, x), 1.0 - (1.0 + x) * std::exp(-x), 1e-14) << x;  // Erlang 2
  }
  for (double k : {0.3, 1.0, 4.5, 60.0})
    for (double p : {0.05, 0.45, 0.95}) EXPECT_NEAR(pa::gamma_cdf(k, pa::gamma_quantile(k, p)), p, 1e-13);
  for (double x : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(pa::beta_cdf(1.0, 1.0, x), x, 1e-15);
    // Beta(2, 3): density 12 t (1 - t)^2, CDF 6x^2 - 8x^3 + 3x^4.
    EXPECT_NEAR(pa::beta_cdf(2.0, 3.0, x), 6 * x * x - 8 * x * x * x + 3 * x * x * x * x, 1e-14);
  }
  EXPECT_NEAR(pa::beta_quantile(1.1314, 2.4474, pa::beta_cdf(1.1314, 2.4474, 0.3)), 0.3, 1e-14);
}

TEST(Probability, PercentileIsNumpysLinear) {
  std::vector<double> v = {4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(pa::percentile(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(pa::percentile(v, 0.05), 1.15);
  EXPECT_DOUBLE_EQ(pa::percentile(v, 1.0), 4.0);
}

TEST(Probability, RandomStreamIsSeededAndStandard) {
  pa::RandomStream a(7), b(7), c(8);
  EXPECT_EQ(a.normal(), b.normal());
  EXPECT_NE(pa::RandomStream(7).uniform(), c.uniform());
  pa::RandomStream rs(pa::mix_seed(3, 0));
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = rs.normal();
    sum += z, sum2 += z * z;
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 4.0 * std::sqrt(2.0 / n));
}

TEST(Fragility, UncensoredCapacitiesGiveTheLogMoments) {
  const double e = std::exp(1.0);
  const auto f = pa::fit_capacities({1.0, e, e * e}, {});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->theta, e, 1e-14);
  EXPECT_NEAR(f->beta, std::sqrt(2.0 / 3.0), 1e-14);
  EXPECT_FALSE(pa::fit_capacities({0.3, 0.3}, {}));  // equal capacities: β = 0
  EXPECT_FALSE(pa::fit_capacities({}, {0.3}));
  EXPECT_THROW(pa::fit_capacities({-1.0}, {}), std::invalid_argument);
}

TEST(Fragility, CensoredMaximumIsStationary) {
  // At the maximum the log-likelihood is flat: no small step in ln θ or β
  // raises it.
  const std::vector<double> cap = {0.2, 0.3, 0.35, 0.5, 0.45}, cen = {0.5, 0.5, 0.4};
  const auto f = pa::fit_capacities(cap, cen);
  ASSERT_TRUE(f);
  auto ll = [&](double theta, double beta) {
    double s = 0.0;
    for (double c : cap) s += -std::log(beta) - 0.5 * std::pow(std::log(c / theta) / beta, 2);
    for (double c : cen) s += pa::log_normal_sf(std::log(c / theta) / beta);
    return s;
  };
  const double best = ll(f->theta, f->beta);
  for (double d : {-1e-4, 1e-4}) {
    EXPECT_LE(ll(f->theta * std::exp(d), f->beta), best + 1e-12);
    EXPECT_LE(ll(f->theta, f->beta * std::exp(d)), best + 1e-12);
  }
  // The censored records push θ above the uncensored log-mean.
  EXPECT_GT(f->theta, pa::fit_capacities(cap, {})->theta);
}

TEST(Fragility, IdaRecoversKnownCurveWithinItsBand) {
  const double theta = 0.4, beta = 0.35;
  pa::FragilityOptions o;
  o.bootstrap = 400;
  const auto r = pa::fit_fragility(ida_runs(theta, beta, 40, 0.5, 11), o);
  const auto& c = collapse(r);
  ASSERT_EQ(c.status, pa::FitStatus::fitted);
  EXPECT_EQ(c.observations, 40);
  EXPECT_LT(c.reached, 40);  // some records censored at 0.5
  EXPECT_LE(c.theta_low, theta);
  EXPECT_GE(c.theta_high, theta);
  EXPECT_LE(c.beta_low, beta);
  EXPECT_GE(c.beta_high, beta);
  EXPECT_GT(c.bootstrap_fitted, 390);
  // The band holds the true curve at every grid IM.
  for (std::size_t i = 1; i < r.im.size(); ++i) {
    const double p = pa::fragility_probability({theta, beta}, r.im[i]);
    EXPECT_LE(c.band_low[i], p + 1e-12) << r.im[i];
    EXPECT_GE(c.band_high[i], p - 1e-12) << r.im[i];
  }
  // Every state is reached at collapse here, so all three curves agree.
  EXPECT_DOUBLE_EQ(r.states[0].curve.theta, c.curve.theta);
}

TEST(Fragility, IdaFitIsUnbiasedOverSeeds) {
  // 300 suites of 40 records, about 26 % censored at 0.5. Ignoring the
  // censored records would pull θ̂ down by about 15 %: this test sees it.
  expect_unbiased(pa::FragilityMethod::ida, 0.4, 0.35,
                  [](std::uint64_t s) { return ida_runs(0.4, 0.35, 40, 0.5, 1000 + s); });
}

TEST(Fragility, StripesRecoverKnownCurveWithinItsBand) {
  const double theta = 0.5, beta = 0.4;
  pa::FragilityOptions o;
  o.method = pa::FragilityMethod::stripes;
  o.bootstrap = 400;
  const auto r = pa::fit_fragility(stripe_runs(theta, beta, 20, 5), o);
  const auto& c = collapse(r);
  ASSERT_EQ(c.status, pa::FitStatus::fitted);
  EXPECT_EQ(c.observations, 200);
  EXPECT_EQ(c.points.size(), 10u);
  EXPECT_LE(c.theta_low, theta);
  EXPECT_GE(c.theta_high, theta);
  EXPECT_LE(c.beta_low, beta);
  EXPECT_GE(c.beta_high, beta);
}

TEST(Fragility, StripesFitIsUnbiasedOverSeeds) {
  expect_unbiased(pa::FragilityMethod::stripes, 0.5, 0.4,
                  [](std::uint64_t s) { return stripe_runs(0.5, 0.4, 20, 5000 + s); });
}

TEST(Fragility, StripeMaximumIsStationary) {
  const std::vector<pa::Stripe> s = {{0.2, 10, 1}, {0.4, 10, 3}, {0.6, 10, 7}, {0.8, 10, 8}};
  const auto f = pa::fit_stripes(s);
  ASSERT_TRUE(f);
  auto ll = [&](double theta, double beta) {
    double sum = 0.0;
    for (const auto& x : s) {
      const double u = std::log(x.im / theta) / beta;
      sum += x.reached * pa::log_normal_cdf(u) + (x.runs - x.reached) * pa::log_normal_sf(u);
    }
    return sum;
  };
  const double best = ll(f->theta, f->beta);
  for (double d : {-1e-4, 1e-4}) {
    EXPECT_LE(ll(f->theta * std::exp(d), f->beta), best + 1e-12);
    EXPECT_LE(ll(f->theta, f->beta * std::exp(d)), best + 1e-12);
  }
}

TEST(Fragility, StatesWithoutAFitAreNamedAndTheOthersFitted) {
  // Stripes where nothing collapses, everything is damaged above 0.3 and
  // stones are lost only at 0.5 and 0.7 (separated: no finite MLE).
  std::vector<pa::FragilityRun> runs;
  for (double im : {0.1, 0.3, 0.5, 0.7})
    for (int k = 0; k < 4; ++k) {
      DamageState s = im >= 0.5 ? DamageState::stones_lost : im >= 0.3 && k % 2 ? DamageState::damaged : DamageState::intact;
      runs.push_back({"", im, s});
    }
  pa::FragilityOptions o;
  o.method = pa::FragilityMethod::stripes;
  o.bootstrap = 50;
  const auto r = pa::fit_fragility(runs, o);
  EXPECT_EQ(r.states[0].status, pa::FitStatus::fitted);
  EXPECT_EQ(r.states[1].status, pa::FitStatus::not_identified);
  EXPECT_TRUE(std::isnan(r.states[1].curve.theta));
  EXPECT_EQ(r.states[2].status, pa::FitStatus::none_reached);
  EXPECT_TRUE(std::isnan(r.states[2].probability[5]));

  // Everything collapses at every stripe: θ is below the lowest IM.
  for (auto& run : runs) run.state = DamageState::collapsed;
  EXPECT_EQ(collapse(pa::fit_fragility(runs, o)).status, pa::FitStatus::all_reached);
  // IDA where every record collapses is an ordinary fit.
  pa::FragilityOptions ida;
  ida.bootstrap = 20;
  EXPECT_EQ(collapse(pa::fit_fragility(ida_runs(0.4, 0.3, 10, 100.0, 3), ida)).status, pa::FitStatus::fitted);
}

TEST(Fragility, SameSeedSameBandOtherSeedOtherBand) {
  pa::FragilityOptions o;
  o.bootstrap = 100;
  const auto runs = ida_runs(0.4, 0.35, 20, 0.6, 9);
  const auto a = pa::fit_fragility(runs, o), b = pa::fit_fragility(runs, o);
  EXPECT_EQ(collapse(a).band_low, collapse(b).band_low);
  EXPECT_EQ(collapse(a).theta_high, collapse(b).theta_high);
  o.seed = 2;
  EXPECT_NE(collapse(pa::fit_fragility(runs, o)).band_low, collapse(a).band_low);
}

TEST(Fragility, BadInputIsRefused) {
  pa::FragilityOptions o;
  EXPECT_THROW(pa::fit_fragility({}, o), std::invalid_argument);
  EXPECT_THROW(pa::fit_fragility({{"a", -0.1, DamageState::collapsed}}, o), std::invalid_argument);
  EXPECT_THROW(pa::fit_fragility({{"a", std::nan(""), DamageState::collapsed}}, o), std::invalid_argument);
  EXPECT_THROW(pa::fit_fragility({{"", 0.1, DamageState::collapsed}}, o), std::invalid_argument);  // IDA, no record
  o.confidence = 1.0;
  EXPECT_THROW(pa::fit_fragility({{"a", 0.1, DamageState::collapsed}}, o), std::invalid_argument);
  EXPECT_THROW(pa::fit_stripes({{0.1, 2, 3}}), std::invalid_argument);
  EXPECT_EQ(pa::damage_state_named("stones-lost"), DamageState::stones_lost);
  EXPECT_EQ(pa::damage_state_named("3"), DamageState::collapsed);
  EXPECT_FALSE(pa::damage_state_named("broken"));
}
