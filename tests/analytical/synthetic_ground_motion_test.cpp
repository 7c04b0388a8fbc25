// The stochastic ground-motion model (analytical/synthetic_ground_motion.hpp):
// the modulating function against its closed form, the predictive
// equations' trends and spread, a suite of 50 records against the model's
// targets (Arias intensity, D5-95, t_mid, the filter frequency by
// up-crossings), the post-filter's zero residual velocity, determinism.
#include "analytical/synthetic_ground_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pa = polydem::analytical;

namespace {

constexpr double g = 9.80665;
constexpr double pi = 3.14159265358979323846;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One suite, simulated once for the tests that measure it.
const std::vector<pa::SyntheticRecord>& suite50() {
  static const std::vector<pa::SyntheticRecord> s = pa::synthetic_suite({6.5, 20.0, 760.0, false}, 50, 2024, {});
  return s;
}

}  // namespace

TEST(SyntheticMotion, ModulatingFunctionHasTheTargetIntensityAndTimes) {
  pa::SyntheticMotionParameters p;
  p.arias_intensity = 0.5, p.d5_95 = 12.0, p.t_mid = 8.0, p.f_mid = 5.0, p.zeta_f = 0.3;
  const pa::ModulatingFunction q = pa::modulating_function(p, g);
  EXPECT_GT(q.alpha2, 1.0);
  // q² ∝ gamma(shape, rate): its 45 % time is t_mid, its 5-95 % span D5-95.
  EXPECT_NEAR(pa::gamma_quantile(q.shape(), 0.45) / q.rate(), p.t_mid, 1e-9);
  EXPECT_NEAR((pa::gamma_quantile(q.shape(), 0.95) - pa::gamma_quantile(q.shape(), 0.05)) / q.rate(), p.d5_95, 1e-9);
  // π/(2g) ∫ q² dt = I_a, by the trapezoidal rule on a fine grid.
  double integral = 0.0;
  const double h = 1e-3;
  for (double t = h; t < 200.0; t += h) {
    const double v = q.alpha1 * std::pow(t, q.alpha2 - 1.0) * std::exp(-q.alpha3 * t);
    integral += v * v * h;
  }
  EXPECT_NEAR(pi / (2.0 * g) * integral, p.arias_intensity, 1e-6);
  p.t_mid = 2.0;  // D5-95 / t_mid = 6: no modulating function with α₂ > 1
  EXPECT_THROW(pa::modulating_function(p, g), std::invalid_argument);
}

TEST(SyntheticMotion, PredictiveEquationsFollowTheScenario) {
  const auto near = pa::median_parameters({6.5, 10.0, 760.0, false});
  const auto far = pa::median_parameters({6.5, 60.0, 760.0, false});
  const auto big = pa::median_parameters({7.5, 10.0, 760.0, false});
  const auto soft = pa::median_parameters({6.5, 10.0, 300.0, false});
  EXPECT_GT(near.arias_intensity, far.arias_intensity);
  EXPECT_GT(big.arias_intensity, near.arias_intensity);
  EXPECT_GT(soft.arias_intensity, near.arias_intensity);
  EXPECT_GT(far.d5_95, near.d5_95);
  EXPECT_GT(big.d5_95, near.d5_95);
  // M 7, R 25 km, V_s30 750 m/s, strike-slip: ν₁ = −2.2962 + 2.9440, so
  // ln I_a[s g] = −4.8255 + 1.4318 × 0.6478.
  const auto ref = pa::median_parameters({7.0, 25.0, 750.0, false});
  EXPECT_NEAR(ref.arias_intensity, std::exp(-4.8255 + 1.4318 * 0.6478) * g, 1e-12);
  for (const auto& p : {near, far, big, soft, ref}) {
    EXPECT_GT(p.f_mid, 0.0);
    EXPECT_GE(p.f_slope, -2.0);
    EXPECT_LE(p.f_slope, 0.5);
    EXPECT_GT(p.zeta_f, 0.02);
    EXPECT_LT(p.zeta_f, 1.0);
  }
  EXPECT_THROW(pa::median_parameters({6.5, 0.0, 760.0, false}), std::invalid_argument);
}

TEST(SyntheticMotion, MedianAriasIntensityAgreesWithAnIndependentEquation) {
  // The I_a equation's intercept is the one number the public sources of
  // the coefficients disagree on (docs/fragility.md). Against Travasarou,
  // Bray & Abrahamson (2003, EESD 32:1133-1155, their Table 3: rock sites,
  // strike-slip),
  //   ln I_a = 2.800 − 1.981 (M − 6) + 20.72 ln(M/6) − 1.703 ln √(R² + 8.78²),
  // fitted to other records, the median here is within 0.4 in ln (a third
  // of either equation's scatter) where both have most of their data:
  // M 6.5-7.5 at 20-40 km. The other intercept, −1.844, is 0.3-0.9 above.
  for (double m : {6.5, 7.0, 7.5}) {
    for (double r : {20.0, 40.0}) {
      const double travasarou =
          2.800 - 1.981 * (m - 6.0) + 20.72 * std::log(m / 6.0) - 1.703 * std::log(std::hypot(r, 8.78));
      const double here = std::log(pa::median_parameters({m, r, 760.0, false}).arias_intensity);
      EXPECT_NEAR(here, travasarou, 0.4) << "M " << m << ", R " << r << " km";
    }
  }
}

TEST(SyntheticMotion, SampledParametersSpreadAsTheEquationsSay) {
  // ln I_a has the marginal's 1.4318 times the total error's
  // √(σ² + τ²) = 0.6538 as standard deviation, about the median's ln I_a.
  const pa::EarthquakeScenario s{6.5, 20.0, 760.0, false};
  const double ln_median = std::log(pa::median_parameters(s).arias_intensity);
  pa::RandomStream rs(77);
  const int n = 4000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = std::log(pa::sample_parameters(s, rs).arias_intensity) - ln_median;
    sum += e, sum2 += e * e;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.06);
  EXPECT_NEAR(sd, 1.4318 * std::hypot(0.5937, 0.2738), 0.05);
}

TEST(SyntheticMotion, SuiteMatchesItsTargets) {
  // Each record against the parameters it was drawn for; the medians over
  // the 50 records of measured / target: I_a (the model's expected value:
  // the mean) within 8 %, D5-95 and t_mid (medians) within 10 %, and the zero up-crossings within ±2 s of t_mid within
  // 10 % of ω_f/2π integrated over that window.
  std::vector<double> ia, d, tm;
  double crossings = 0.0, expected = 0.0;
  for (const auto& r : suite50()) {
    const auto m = pa::record_measures(r.dt, r.acceleration);
    const auto& p = r.parameters;
    ia.push_back(m.arias_intensity / p.arias_intensity);
    d.push_back(m.d5_95 / p.d5_95);
    tm.push_back(m.t45 / p.t_mid);
    const double t0 = std::max(0.0, p.t_mid - 2.0), t1 = p.t_mid + 2.0;
    crossings += pa::upcrossings(r.dt, r.acceleration, t0, t1);
    for (double t = t0; t < t1; t += 0.001) expected += 0.001 * std::max(0.3, p.f_mid + p.f_slope * (t - p.t_mid));
  }
  double ia_mean = 0.0;
  for (double x : ia) ia_mean += x / static_cast<double>(ia.size());
  RecordProperty("arias_mean_ratio", std::to_string(ia_mean));
  RecordProperty("d5_95_median_ratio", std::to_string(median(d)));
  RecordProperty("t_mid_median_ratio", std::to_string(median(tm)));
  RecordProperty("upcrossing_ratio", std::to_string(crossings / expected));
  EXPECT_NEAR(ia_mean, 1.0, 0.08);
  EXPECT_NEAR(median(d), 1.0, 0.10);
  EXPECT_NEAR(median(tm), 1.0, 0.10);
  EXPECT_NEAR(crossings / expected, 1.0, 0.10);
}

TEST(SyntheticMotion, PostFilterLeavesNoResidualVelocity) {
  for (const auto& r : suite50()) {
    const auto m = pa::record_measures(r.dt, r.acceleration);
    EXPECT_LT(std::fabs(m.residual_velocity), 0.02 * m.pgv) << r.name;
    EXPECT_EQ(r.acceleration.front(), 0.0);
  }
}

TEST(SyntheticMotion, SameSeedSameBits) {
  const pa::EarthquakeScenario s{6.0, 30.0, 500.0, true};
  const auto a = pa::synthetic_suite(s, 3, 5, {});
  const auto b = pa::synthetic_suite(s, 2, 5, {});
  EXPECT_EQ(a[0].acceleration, b[0].acceleration);
  EXPECT_EQ(a[1].acceleration, b[1].acceleration);
  EXPECT_EQ(a[1].seed, b[1].seed);
  EXPECT_NE(a[0].acceleration, a[1].acceleration);
  EXPECT_EQ(a[2].name, "synthetic_03");
  EXPECT_NE(pa::synthetic_suite(s, 1, 6, {})[0].acceleration, a[0].acceleration);
  EXPECT_THROW(pa::synthetic_suite(s, 0, 5, {}), std::invalid_argument);
}
