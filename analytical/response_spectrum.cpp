#include "analytical/response_spectrum.hpp"

#include "analytical/constants.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace polydem::analytical {
namespace {

// Peaks are looked for at points no further apart than T / kPointsPerPeriod.
constexpr int kPointsPerPeriod = 20;

std::string text(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

void check_record(const std::vector<double>& t, const std::vector<double>& a) {
  if (t.size() != a.size())
    throw std::invalid_argument("record: " + std::to_string(t.size()) + " times but " + std::to_string(a.size()) +
                                " accelerations");
  if (t.size() < 2) throw std::invalid_argument("record: needs at least two samples");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || !std::isfinite(a[i]))
      throw std::invalid_argument("record: sample " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(t[i] > t[i - 1]))
      throw std::invalid_argument("record: time " + text(t[i]) + " s does not increase (sample " +
                                  std::to_string(i + 1) + ")");
  }
}

void check_oscillator(double period, double damping) {
  if (!(period > 0.0) || !std::isfinite(period))
    throw std::invalid_argument("period must be > 0 s and finite, got " + text(period));
  if (!(damping >= 0.0 && damping < 1.0))
    throw std::invalid_argument("damping ratio must be in [0, 1), got " + text(damping));
}

// The step map with the step length it was made for (integrate reuses it
// while the substep length stays the same).
struct StepMap {
  double h = -1.0;
  double A[2][2] = {{0, 0}, {0, 0}};
  double B[2][2] = {{0, 0}, {0, 0}};
};

StepMap step_map(double h, double omega, double xi) {
  const OscillatorStep o = oscillator_step(h, omega, xi);
  StepMap m;
  m.h = h;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      m.A[i][j] = o.A[i][j];
      m.B[i][j] = o.B[i][j];
    }
  return m;
}

// The largest |u| over a substep of length h from (u0, v0) to (u1, v1):
// the end values, and where u̇ changes sign inside the substep the extremum
// of the cubic Hermite interpolant of u and u̇. For a substep of T/20 the
// interpolant's error is about (ωh)⁴/384 ≈ 4e-5 of the amplitude, where the
// end points alone could miss a peak by 1 − cos(π/20) ≈ 1.2 %.
double hermite_peak(double u0, double v0, double u1, double v1, double h) {
  double peak = std::max(std::abs(u0), std::abs(u1));
  if (!(v0 * v1 < 0.0)) return peak;
  // p(s), s in [0, 1]: p'(s) = A s² + B s + C.
  const double A = 6 * u0 + 3 * h * v0 - 6 * u1 + 3 * h * v1;
  const double B = -6 * u0 - 4 * h * v0 + 6 * u1 - 2 * h * v1;
  const double C = h * v0;
  const auto value = [&](double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * u0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * u1 + (s3 - s2) * h * v1;
  };
  const auto consider = [&](double s) {
    if (s > 0.0 && s < 1.0) peak = std::max(peak, std::abs(value(s)));
  };
  if (std::abs(A) < 1e-14 * (std::abs(B) + std::abs(C))) {
    if (B != 0.0) consider(-C / B);
    return peak;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0.0) return peak;
  // The root formula without cancellation.
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  if (q != 0.0) {
    consider(q / A);
    consider(C / q);
  }
  return peak;
}

// Steps the oscillator through the record and one period of free vibration
// after it; returns max |u| over every substep point. `history`, when given,
// receives u at the record's samples.
double integrate(const std::vector<double>& t, const std::vector<double>& a, double period, double xi,
                 std::vector<double>* history) {
  const double omega = 2.0 * pi / period;
  const double longest = period / kPointsPerPeriod;
  double u = 0.0, v = 0.0, peak = 0.0;
  StepMap map;
  // One step of length h from acceleration a0 to a1, cut into substeps.
  const auto advance = [&](double h, double a0, double a1) {
    const int n = std::max(1, static_cast<int>(std::ceil(h / longest)));
    const double hs = h / n;
    if (hs != map.h) map = step_map(hs, omega, xi);
    for (int k = 0; k < n; ++k) {
      const double b0 = a0 + (a1 - a0) * k / n;
      const double b1 = k + 1 == n ? a1 : a0 + (a1 - a0) * (k + 1) / n;
      const double u1 = map.A[0][0] * u + map.A[0][1] * v + map.B[0][0] * b0 + map.B[0][1] * b1;
      const double v1 = map.A[1][0] * u + map.A[1][1] * v + map.B[1][0] * b0 + map.B[1][1] * b1;
      peak = std::max(peak, hermite_peak(u, v, u1, v1, hs));
      u = u1;
      v = v1;
    }
  };
  if (history) {
    history->assign(t.size(), 0.0);
  }
  for (std::size_t i = 1; i < t.size(); ++i) {
    advance(t[i] - t[i - 1], a[i - 1], a[i]);
    if (history) (*history)[i] = u;
  }
  advance(period, 0.0, 0.0);  // the ground at rest after the record
  return peak;
}

}  // namespace

// A: the damped free vibration from (u0, v0),
//   u(τ) = e^{−ξωτ} [u0 cos ω_d τ + (v0 + ξω u0)/ω_d sin ω_d τ],
// and its derivative. B: the response from rest to p(τ) = p0 + p1 τ (the
// right-hand side −a_g), the particular solution
//   u_p(τ) = (p0 + p1 τ)/ω² − 2ξ p1/ω³,  u̇_p = p1/ω²
// plus the free vibration that cancels u_p(0) and u̇_p(0); the columns are
// a0 = 1 (p0 = −1, p1 = 1/h) and a1 = 1 (p0 = 0, p1 = −1/h).
OscillatorStep oscillator_step(double h, double omega, double xi) {
  OscillatorStep m;
  const double wd = omega * std::sqrt(1.0 - xi * xi);
  const double e = std::exp(-xi * omega * h);
  const double c = std::cos(wd * h), s = std::sin(wd * h);
  const double w2 = omega * omega;
  m.A[0][0] = e * (c + xi * omega / wd * s);
  m.A[0][1] = e * s / wd;
  m.A[1][0] = -e * w2 / wd * s;
  m.A[1][1] = e * (c - xi * omega / wd * s);
  const auto forced = [&](double p0, double p1, int column) {
    const double up0 = p0 / w2 - 2.0 * xi * p1 / (w2 * omega);
    const double uph = up0 + p1 * h / w2;
    const double vp = p1 / w2;
    m.B[0][column] = uph - m.A[0][0] * up0 - m.A[0][1] * vp;
    m.B[1][column] = vp - m.A[1][0] * up0 - m.A[1][1] * vp;
  };
  forced(-1.0, 1.0 / h, 0);
  forced(0.0, -1.0 / h, 1);
  return m;
}

ResponseSpectrum response_spectrum(const std::vector<double>& time, const std::vector<double>& acceleration,
                                   const std::vector<double>& periods, double damping) {
  check_record(time, acceleration);
  if (periods.empty()) throw std::invalid_argument("no periods");
  for (double T : periods) check_oscillator(T, damping);
  ResponseSpectrum r;
  r.period = periods;
  r.damping = damping;
  for (double x : acceleration) r.peak_ground_acceleration = std::max(r.peak_ground_acceleration, std::abs(x));
  for (double T : periods) {
    const double omega = 2.0 * pi / T;
    const double sd = integrate(time, acceleration, T, damping, nullptr);
    r.displacement.push_back(sd);
    r.pseudo_velocity.push_back(omega * sd);
    r.pseudo_acceleration.push_back(omega * omega * sd);
  }
  return r;
}

std::vector<double> oscillator_displacement(const std::vector<double>& time, const std::vector<double>& acceleration,
                                            double period, double damping) {
  check_record(time, acceleration);
  check_oscillator(period, damping);
  std::vector<double> u;
  integrate(time, acceleration, period, damping, &u);
  return u;
}

std::vector<double> default_spectrum_periods() {
  constexpr int n = 100;
  const double lo = std::log(0.01), hi = std::log(5.0);
  std::vector<double> T(n);
  for (int i = 0; i < n; ++i) T[static_cast<std::size_t>(i)] = std::exp(lo + (hi - lo) * i / (n - 1));
  return T;
}

SuiteSpectrum suite_spectrum(const std::vector<ResponseSpectrum>& spectra) {
  if (spectra.empty()) throw std::invalid_argument("suite spectrum: no records");
  SuiteSpectrum s;
  s.period = spectra.front().period;
  s.records = static_cast<int>(spectra.size());
  for (const ResponseSpectrum& r : spectra)
    if (r.period != s.period) throw std::invalid_argument("suite spectrum: the records' periods differ");
  const double n = static_cast<double>(spectra.size());
  for (std::size_t j = 0; j < s.period.size(); ++j) {
    double sum = 0.0;
    for (const ResponseSpectrum& r : spectra) {
      if (!(r.displacement[j] > 0.0))
        throw std::invalid_argument("suite spectrum: a zero ordinate at T = " + text(s.period[j]) +
                                    " s (a record without motion)");
      sum += std::log(r.displacement[j]);
    }
    const double mean = sum / n;
    double squares = 0.0;
    for (const ResponseSpectrum& r : spectra) squares += std::pow(std::log(r.displacement[j]) - mean, 2);
    const double omega = 2.0 * pi / s.period[j];
    const double sd = std::exp(mean);
    s.median_displacement.push_back(sd);
    s.median_pseudo_velocity.push_back(omega * sd);
    s.median_pseudo_acceleration.push_back(omega * omega * sd);
    s.dispersion.push_back(spectra.size() > 1 ? std::sqrt(squares / (n - 1.0)) : 0.0);
  }
  return s;
}

}  // namespace polydem::analytical
