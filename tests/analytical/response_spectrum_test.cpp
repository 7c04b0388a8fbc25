// The elastic response spectra (analytical/response_spectrum.hpp) against
// the closed-form response of a damped oscillator to a sine (from rest and
// in steady state) and against a fine-step Newmark average-acceleration
// integration of a random piecewise-linear record.
#include "analytical/response_spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace pa = polydem::analytical;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The oscillator (ω, ξ) from rest under a_g = A sin(Ω t) for 0 ≤ t ≤ t_end,
// at rest ground after: u(t) in closed form (Chopra, eq. 3.2.1-3.2.4, with
// the load −a_g).
struct SineResponse {
  double omega, xi, A, Omega, t_end;

  double wd() const { return omega * std::sqrt(1 - xi * xi); }
  // Steady-state u = C sin Ωt + D cos Ωt.
  double C() const {
    const double r = Omega / omega, den = std::pow(1 - r * r, 2) + std::pow(2 * xi * r, 2);
    return -A / (omega * omega) * (1 - r * r) / den;
  }
  double D() const {
    const double r = Omega / omega, den = std::pow(1 - r * r, 2) + std::pow(2 * xi * r, 2);
    return -A / (omega * omega) * (-2 * xi * r) / den;
  }
  // Free vibration from (u0, v0): displacement and velocity after time t.
  void free(double u0, double v0, double t, double& u, double& v) const {
    const double e = std::exp(-xi * omega * t), c = std::cos(wd() * t), s = std::sin(wd() * t);
    u = e * (u0 * c + (v0 + xi * omega * u0) / wd() * s);
    v = e * (v0 * c - (omega * omega * u0 + xi * omega * v0) / wd() * s);
  }
  void forced(double t, double& u, double& v) const {
    double uf, vf;
    free(-D(), -C() * Omega, t, uf, vf);
    u = C() * std::sin(Omega * t) + D() * std::cos(Omega * t) + uf;
    v = C() * Omega * std::cos(Omega * t) - D() * Omega * std::sin(Omega * t) + vf;
  }
  double u(double t) const {
    double x, v;
    if (t <= t_end) {
      forced(t, x, v);
      return x;
    }
    double ue, ve;
    forced(t_end, ue, ve);
    free(ue, ve, t - t_end, x, v);
    return x;
  }
  double steady_amplitude() const { return std::hypot(C(), D()); }
};

void sine_record(double A, double Omega, double t_end, double dt, std::vector<double>& t, std::vector<double>& a) {
  const int n = static_cast<int>(std::lround(t_end / dt));
  t.resize(static_cast<std::size_t>(n) + 1);
  a.resize(t.size());
  for (int i = 0; i <= n; ++i) {
    t[static_cast<std::size_t>(i)] = i * dt;
    a[static_cast<std::size_t>(i)] = A * std::sin(Omega * i * dt);
  }
}

// Newmark average acceleration (γ = 1/2, β = 1/4) with `sub` substeps per
// sample; the peak |u| over the substep points and one period of free
// vibration after the record.
double newmark_peak(const std::vector<double>& t, const std::vector<double>& a, double T, double xi, int sub) {
  const double w = 2 * kPi / T;
  double u = 0, v = 0, acc = -a[0], peak = 0;
  const auto step = [&](double h, double p1) {
    const double k = w * w + 2 * xi * w * 2 / h + 4 / (h * h);
    const double p = p1 + 4 / (h * h) * u + 4 / h * v + acc + 2 * xi * w * (2 / h * u + v);
    const double u1 = p / k;
    const double v1 = 2 / h * (u1 - u) - v;
    acc = 4 / (h * h) * (u1 - u) - 4 / h * v - acc;
    u = u1;
    v = v1;
    peak = std::max(peak, std::abs(u));
  };
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double h = (t[i] - t[i - 1]) / sub;
    for (int j = 1; j <= sub; ++j) step(h, -(a[i - 1] + (a[i] - a[i - 1]) * j / sub));
  }
  // The ground at rest after the record: the load drops to zero.
  acc = -2 * xi * w * v - w * w * u;
  const int n = 20 * sub;
  for (int j = 0; j < n; ++j) step(T / n, 0.0);
  return peak;
}

}  // namespace

// The response history from rest to a finely sampled sine follows the
// closed form; the spectral ordinate is its peak (record and free tail).
TEST(ResponseSpectrum, FromRestMatchesClosedFormSine) {
  const double A = 2.0, Omega = 2 * kPi * 1.3, t_end = 6.0, dt = 1e-3;
  std::vector<double> t, a;
  sine_record(A, Omega, t_end, dt, t, a);
  double worst_history = 0, worst_ordinate = 0;
  for (double T : {0.05, 0.2, 0.77, 1.0, 2.5}) {
    for (double xi : {0.0, 0.05, 0.2}) {
      const SineResponse exact{2 * kPi / T, xi, A, Omega, t_end};
      const auto u = pa::oscillator_displacement(t, a, T, xi);
      double peak = 0, err = 0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        err = std::max(err, std::abs(u[i] - exact.u(t[i])));
        peak = std::max(peak, std::abs(exact.u(t[i])));
      }
      for (int k = 1; k <= 2000; ++k) peak = std::max(peak, std::abs(exact.u(t_end + T * k / 2000.0)));
      worst_history = std::max(worst_history, err / peak);
      const double sd = pa::response_spectrum(t, a, {T}, xi).displacement[0];
      worst_ordinate = std::max(worst_ordinate, std::abs(sd - peak) / peak);
    }
  }
  // Piecewise-linear sampling of the sine: O((Ω dt)²/8) ~ 7e-6 of its
  // amplitude; the peak between points is found to about 4e-5.
  EXPECT_LT(worst_history, 2e-5);
  EXPECT_LT(worst_ordinate, 3e-4);
  std::printf("[ sine from rest ] worst history error %.2e, worst ordinate error %.2e (relative to the peak)\n",
              worst_history, worst_ordinate);
}

// A sine that rises and falls slowly (raised-cosine envelope over many
// cycles) leaves no transient: every ordinate is the steady-state amplitude
// A/ω² / √((1 − r²)² + (2ξr)²).
TEST(ResponseSpectrum, SlowlyEnvelopedSineGivesSteadyStateAmplitude) {
  const double A = 1.0, f = 2.0, Omega = 2 * kPi * f, dt = 0.002;
  const double ramp = 60.0, hold = 20.0, t_end = 2 * ramp + hold;
  std::vector<double> t, a;
  sine_record(A, Omega, t_end, dt, t, a);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double s = t[i] < ramp ? t[i] / ramp : t[i] > ramp + hold ? (t_end - t[i]) / ramp : 1.0;
    a[i] *= 0.5 * (1 - std::cos(kPi * s));
  }
  std::vector<double> periods;
  for (int k = 0; k < 20; ++k) periods.push_back(0.05 * std::pow(40.0, k / 19.0));  // 0.05 s to 2 s
  const double xi = 0.05;
  const pa::ResponseSpectrum s = pa::response_spectrum(t, a, periods, xi);
  double worst = 0;
  for (std::size_t j = 0; j < periods.size(); ++j) {
    const SineResponse ss{2 * kPi / periods[j], xi, A, Omega, t_end};
    const double err = std::abs(s.displacement[j] - ss.steady_amplitude()) / ss.steady_amplitude();
    worst = std::max(worst, err);
    EXPECT_LT(err, 5e-4) << "T = " << periods[j];
    EXPECT_NEAR(s.pseudo_acceleration[j], std::pow(2 * kPi / periods[j], 2) * s.displacement[j], 1e-12);
  }
  std::printf("[ steady state ] worst ordinate error %.2e over %zu periods\n", worst, periods.size());
}

// A random piecewise-linear record: the exact recurrence against Newmark's
// average acceleration with 200 substeps per sample.
TEST(ResponseSpectrum, AgreesWithFineNewmarkIntegration) {
  std::mt19937 rng(33);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> t, a;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(0.01 * i + (i % 3 == 0 ? 0.0 : 0.002 * (i % 3)));  // uneven steps
    a.push_back(i == 0 ? 0.0 : 2.0 * noise(rng));
  }
  double worst = 0;
  for (double T : {0.02, 0.1, 0.5, 1.0, 3.0}) {
    const double exact = pa::response_spectrum(t, a, {T}, 0.05).displacement[0];
    const double newmark = newmark_peak(t, a, T, 0.05, 200);
    const double err = std::abs(exact - newmark) / exact;
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-4) << "T = " << T;
  }
  std::printf("[ newmark ] worst ordinate difference %.2e\n", worst);
}

// Exact for piecewise-linear acceleration: the same record with 99 more
// points on each straight piece (0.1 ms apart) has the same spectrum; what
// differs is only where the peak is looked for (Hermite, within 4e-5).
TEST(ResponseSpectrum, ResamplingTheSameRecordChangesNothing) {
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> t, a, tf, af;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(0.01 * i);
    a.push_back(noise(rng));
  }
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    for (int k = 0; k < 100; ++k) {
      tf.push_back(t[i] + (t[i + 1] - t[i]) * k / 100);
      af.push_back(a[i] + (a[i + 1] - a[i]) * k / 100);
    }
  tf.push_back(t.back());
  af.push_back(a.back());
  const std::vector<double> periods{0.05, 0.3, 1.0, 5.0, 10.0};
  const auto coarse = pa::response_spectrum(t, a, periods, 0.05);
  const auto fine = pa::response_spectrum(tf, af, periods, 0.05);
  double worst = 0;
  for (std::size_t j = 0; j < periods.size(); ++j)
    worst = std::max(worst, std::abs(fine.displacement[j] - coarse.displacement[j]) / coarse.displacement[j]);
  EXPECT_LT(worst, 1e-5);
  std::printf("[ resampled x100 ] worst ordinate difference %.2e\n", worst);
}

TEST(ResponseSpectrum, ShortPeriodGivesPeakGroundAcceleration) {
  std::vector<double> t, a;
  for (int i = 0; i <= 500; ++i) {
    t.push_back(0.01 * i);
    a.push_back(std::sin(0.37 * i) * std::exp(-0.004 * i) + 0.3 * std::cos(1.1 * i));
  }
  // A stiff oscillator follows the ground: u ≈ −a_g/ω², PSA ≈ |a_g|; what is
  // left rings at the record's kinks, of order Δȧ_g/ω, and vanishes as T → 0.
  const pa::ResponseSpectrum s = pa::response_spectrum(t, a, {1e-2, 1e-3, 1e-4}, 0.05);
  const double pga = s.peak_ground_acceleration;
  EXPECT_NEAR(s.pseudo_acceleration[1] / pga, 1.0, 5e-3);
  EXPECT_NEAR(s.pseudo_acceleration[2] / pga, 1.0, 5e-4);
  std::printf("[ T -> 0 ] PSA/PGA - 1 = %.2e, %.2e, %.2e at T = 0.01, 0.001, 0.0001 s\n", s.pseudo_acceleration[0] / pga - 1,
              s.pseudo_acceleration[1] / pga - 1, s.pseudo_acceleration[2] / pga - 1);
}

TEST(ResponseSpectrum, LinearInTheRecord) {
  const std::vector<double> t{0, 0.02, 0.04, 0.06, 0.1, 0.3}, a{0, 1, -2, 0.5, 0.25, 0};
  std::vector<double> a3 = a;
  for (double& x : a3) x *= -3;
  const auto s1 = pa::response_spectrum(t, a, {0.1, 0.5}, 0.02);
  const auto s3 = pa::response_spectrum(t, a3, {0.1, 0.5}, 0.02);
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(s3.displacement[j], 3 * s1.displacement[j], 1e-14);
}

TEST(ResponseSpectrum, SuiteMedianAndDispersion) {
  const std::vector<double> t{0, 0.01, 0.02, 0.03}, a{0, 1, -1, 0};
  const std::vector<double> periods = pa::default_spectrum_periods();
  ASSERT_EQ(periods.size(), 100u);
  EXPECT_NEAR(periods.front(), 0.01, 1e-15);
  EXPECT_NEAR(periods.back(), 5.0, 1e-13);
  std::vector<pa::ResponseSpectrum> spectra;
  for (double k : {0.5, 1.0, 2.0}) {
    std::vector<double> ak = a;
    for (double& x : ak) x *= k;
    spectra.push_back(pa::response_spectrum(t, ak, periods, 0.05));
  }
  const pa::SuiteSpectrum s = pa::suite_spectrum(spectra);
  EXPECT_EQ(s.records, 3);
  for (std::size_t j = 0; j < periods.size(); ++j) {
    EXPECT_NEAR(s.median_pseudo_acceleration[j] / spectra[1].pseudo_acceleration[j], 1.0, 1e-12);
    EXPECT_NEAR(s.dispersion[j], std::log(2.0), 1e-12);  // ln 0.5, 0, ln 2 with n − 1
  }
  EXPECT_EQ(pa::suite_spectrum({spectra[0]}).dispersion[5], 0.0);
}

TEST(ResponseSpectrum, RefusesBadInput) {
  const std::vector<double> t{0, 0.01, 0.02}, a{0, 1, 0};
  EXPECT_THROW(pa::response_spectrum(t, a, {0.0}), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum(t, a, {-1.0}), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum(t, a, {}), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum(t, a, {1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum(t, a, {1.0}, -0.1), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum({0, 0.01, 0.01}, a, {1.0}), std::invalid_argument);
  EXPECT_THROW(pa::response_spectrum({0, 0.01}, a, {1.0}), std::invalid_argument);
  const auto s = pa::response_spectrum(t, a, {0.1, 0.2});
  auto other = pa::response_spectrum(t, a, {0.1, 0.3});
  EXPECT_THROW(pa::suite_spectrum({s, other}), std::invalid_argument);
  EXPECT_THROW(pa::suite_spectrum({}), std::invalid_argument);
}
