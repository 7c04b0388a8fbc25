// The stochastic ground-motion model against its own targets
// (analytical/synthetic_target.hpp): the record taken apart into its unit
// records adds back up to the simulated record; without the post-filter the
// expected intensity and times are the parameters; a suite of 200 records
// for fixed parameters has the target's mean Arias intensity, median D5-95
// and t_mid, and median spectrum at 0.1-2 s; the same suite fails the
// check against the target of a filter frequency 20 % off.
#include "synthetic_suite_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace pa = polydem::analytical;
namespace pt = polydem::analytical::testing;

namespace {

const std::vector<double> kPeriods = {0.1, 0.2, 0.3, 0.5, 1.0, 2.0};
constexpr int kRecords = 200;
// The Vanmarcke median's error against 2000-record suites of three
// scenarios and two seeds (synthetic_target_slow_test.cpp,
// docs/fragility.md): the suite's median is 0.974 to 1.060 times it from
// 0.1 to 2 s, at most 0.058 in ln PSa.
constexpr double kApproximation = 0.06;

const pa::SyntheticMotionParameters& parameters() {
  static const pa::SyntheticMotionParameters p = pa::median_parameters({6.5, 20.0, 760.0, false});
  return p;
}

const pa::SyntheticTarget& target() {
  static const pa::SyntheticTarget t = pa::synthetic_target(parameters(), {}, kPeriods);
  return t;
}

const pt::MeasuredSuite& suite() {
  static const pt::MeasuredSuite s = pt::measure_suite(parameters(), {}, kPeriods, kRecords, 2010);
  return s;
}

// The periods where the suite's median is outside the tolerance of `t`.
int misses(const pa::SyntheticTarget& t) {
  int count = 0;
  for (std::size_t j = 0; j < kPeriods.size(); ++j)
    if (std::fabs(std::log(suite().median_psa[j] / t.median_pseudo_acceleration[j])) >
        pt::median_tolerance(target(), j, kRecords, kApproximation))
      ++count;
  return count;
}

}  // namespace

TEST(SyntheticTarget, UnitRecordsAddUpToTheRecord) {
  const pa::SyntheticMotionParameters& p = parameters();
  for (double f_c : {0.2, 0.0}) {
    pa::SyntheticOptions o;
    o.high_pass = f_c;
    pa::RandomStream rs(11), again(11);
    const pa::SyntheticRecord r = pa::simulate_record(p, o, rs);
    std::vector<double> sum(r.acceleration.size(), 0.0), mean_square(r.acceleration.size(), 0.0);
    const std::size_t n = pa::for_each_unit_record(p, o, [&](std::size_t first, const std::vector<double>& g) {
      const double u = again.normal();
      for (std::size_t k = 0; k < g.size(); ++k) {
        sum[first + k] += u * g[k];
        mean_square[first + k] += g[k] * g[k];
      }
    });
    ASSERT_EQ(n, r.acceleration.size());
    double peak = 0.0, error = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      peak = std::max(peak, std::fabs(r.acceleration[k]));
      error = std::max(error, std::fabs(sum[k] - r.acceleration[k]));
    }
    EXPECT_LT(error, 1e-12 * peak) << "f_c " << f_c;
    if (f_c == 0.0) {
      // The normalisation makes E[x²(t)] = q²(t) while the noise runs.
      const pa::ModulatingFunction q = pa::modulating_function(p, o.g);
      for (std::size_t k = 1; k < 1000; ++k) {
        const double t = static_cast<double>(k) * o.dt;
        const double qk = q.alpha1 * std::pow(t, q.alpha2 - 1.0) * std::exp(-q.alpha3 * t);
        EXPECT_NEAR(mean_square[k], qk * qk, 1e-12 * qk * qk) << "t = " << t;
      }
    }
  }
}

TEST(SyntheticTarget, ExpectedIntensityAndTimesAreTheParameters) {
  // Without the post-filter the expected cumulative intensity is q²'s
  // gamma law (shape k, rate r) stopped where it reaches 99.9 %: I_a × 0.999,
  // and its 5, 45 and 95 % times are those of the parameters' law at
  // 0.999 × 5, 45, 95 % (to the sampling of q² at Δt).
  const pa::SyntheticMotionParameters& p = parameters();
  pa::SyntheticOptions o;
  o.high_pass = 0.0;
  const pa::SyntheticTarget t = pa::synthetic_target(p, o, {1.0});
  const pa::ModulatingFunction q = pa::modulating_function(p, o.g);
  const auto time_at = [&](double share) { return pa::gamma_quantile(q.shape(), share * o.energy_end) / q.rate(); };
  RecordProperty("arias_ratio", std::to_string(t.arias_intensity / p.arias_intensity));
  RecordProperty("t45", std::to_string(t.t45));
  RecordProperty("d5_95", std::to_string(t.d5_95));
  EXPECT_NEAR(t.arias_intensity / p.arias_intensity, o.energy_end, 1e-4);
  EXPECT_NEAR(t.t5, time_at(0.05), 0.005);
  EXPECT_NEAR(t.t45, time_at(0.45), 0.005);
  EXPECT_NEAR(t.t95, time_at(0.95), 0.005);
  // Which differ from the parameters by the stop alone.
  EXPECT_NEAR(t.t45, p.t_mid, 0.01);
  EXPECT_NEAR(t.d5_95, p.d5_95, 0.07);
  // The post-filter takes a few per cent of the intensity and shortens the
  // strong phase slightly.
  EXPECT_LT(target().arias_intensity, t.arias_intensity);
  EXPECT_GT(target().arias_intensity, 0.95 * t.arias_intensity);
}

// One test for the intensity, times and spectrum: each test is its own
// process under ctest, and the suite takes most of the time.
TEST(SyntheticTarget, SuiteMatchesTheTarget) {
  const pt::MeasuredSuite& s = suite();
  const pa::SyntheticTarget& t = target();
  RecordProperty("arias_mean_ratio", std::to_string(s.mean_arias / t.arias_intensity));
  RecordProperty("d5_95_median_ratio", std::to_string(s.median_d5_95 / t.d5_95));
  RecordProperty("t45_median_ratio", std::to_string(s.median_t45 / t.t45));
  // E[I_a] is exact: the sample mean within three standard errors.
  EXPECT_NEAR(s.mean_arias, t.arias_intensity, 3.0 * s.arias_standard_error);
  // The median of the records' own D5-95 and 45 % times is not exactly
  // that of the expected cumulative curve (0.5 % shorter and 0.1 % later
  // over 2000 records); the bands leave room for that and for the sampling
  // of 200.
  EXPECT_NEAR(s.median_d5_95 / t.d5_95, 1.0, 0.03);
  EXPECT_NEAR(s.median_t45 / t.t45, 1.0, 0.015);
  for (std::size_t j = 0; j < kPeriods.size(); ++j) {
    const double ratio = s.median_psa[j] / t.median_pseudo_acceleration[j];
    const double tolerance = pt::median_tolerance(t, j, kRecords, kApproximation);
    std::ostringstream key, value;
    key << "T" << kPeriods[j];
    value << s.median_psa[j] << " / " << t.median_pseudo_acceleration[j] << " = " << ratio << " (tolerance "
          << tolerance << " in ln)";
    RecordProperty(key.str(), value.str());
    EXPECT_LT(std::fabs(std::log(ratio)), tolerance) << "T = " << kPeriods[j] << " s";
    // Poisson's independent crossings overstate the peak; the rms of the
    // response understates it.
    EXPECT_GT(t.poisson_median_pseudo_acceleration[j], t.median_pseudo_acceleration[j]);
    EXPECT_LT(t.rms_pseudo_acceleration[j], t.median_pseudo_acceleration[j]);
  }
}

TEST(SyntheticTarget, CheckSeesAFilterFrequencyTwentyPerCentOff) {
  for (double factor : {0.8, 1.2}) {
    pa::SyntheticMotionParameters p = parameters();
    p.f_mid *= factor;
    const int missed = misses(pa::synthetic_target(p, {}, kPeriods));
    std::ostringstream key;
    key << "f_mid_x" << factor << "_misses";
    RecordProperty(key.str(), missed);
    EXPECT_GE(missed, 2) << "f_mid x " << factor;
  }
  EXPECT_EQ(misses(target()), 0);
}

TEST(SyntheticTarget, RefusesBadInput) {
  EXPECT_THROW(pa::synthetic_target(parameters(), {}, {}), std::invalid_argument);
  EXPECT_THROW(pa::synthetic_target(parameters(), {}, {0.0}), std::invalid_argument);
  EXPECT_THROW(pa::synthetic_target(parameters(), {}, {1.0}, 0.0), std::invalid_argument);
  pa::SyntheticOptions o;
  o.dt = 0.0;
  EXPECT_THROW(pa::synthetic_target(parameters(), o, {1.0}), std::invalid_argument);
}
