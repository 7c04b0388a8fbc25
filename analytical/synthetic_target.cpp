#include "analytical/synthetic_target.hpp"

#include "analytical/constants.hpp"
#include "analytical/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace polydem::analytical {
namespace {

// Second moments of one oscillator's response at every sample.
struct ResponseMoments {
  double omega = 0.0;
  OscillatorStep step;
  std::vector<double> uu, vv, uv;  // E[u²], E[u̇²], E[u u̇]
};

// The bandwidth δ = √(1 − λ₁²/(λ₀λ₂)) of the stationary displacement of
// the oscillator (ω_n, ξ) under the filter (ω_f, ζ_f) and the post-filter
// (ω_c; none when 0): the spectral moments of
//   S(ω) = ω_f⁴ / ((ω_f² − ω²)² + 4ζ_f²ω_f²ω²) · ω⁴/(ω_c² + ω²)²
//          / ((ω_n² − ω²)² + 4ξ²ω_n²ω²)
// by the trapezoidal rule in ln ω over six decades around the three
// frequencies, 4000 points (the oscillator's peak, ξ = 5 % wide in ln ω,
// gets about 12 of them).
double bandwidth(double wn, double xi, double wf, double zf, double wc) {
  const double lo = std::log(1e-3 * std::min({wn, wf, wc > 0.0 ? wc : wn}));
  const double hi = std::log(1e3 * std::max(wn, wf));
  constexpr int n = 4000;
  const double h = (hi - lo) / n;
  double l0 = 0.0, l1 = 0.0, l2 = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = std::exp(lo + h * i), w2 = w * w;
    const double filter = wf * wf * wf * wf / (std::pow(wf * wf - w2, 2) + 4.0 * zf * zf * wf * wf * w2);
    const double post = wc > 0.0 ? w2 * w2 / std::pow(wc * wc + w2, 2) : 1.0;
    const double osc = 1.0 / (std::pow(wn * wn - w2, 2) + 4.0 * xi * xi * wn * wn * w2);
    const double weight = (i == 0 || i == n ? 0.5 : 1.0) * h * w;  // dω = ω d ln ω
    const double s = filter * post * osc * weight;
    l0 += s;
    l1 += s * w;
    l2 += s * w2;
  }
  return std::sqrt(std::max(0.0, 1.0 - l1 * l1 / (l0 * l2)));
}

// The rate of first crossings of ±b at one sample: Rice's rate for a
// Gaussian (u, u̇) with variances uu, vv and covariance uv, times
// Vanmarcke's clumping factor when `delta_e` > 0.
double crossing_rate(double b, double uu, double vv, double uv, double delta_e) {
  if (!(uu > 0.0) || !(vv > 0.0)) return 0.0;
  const double su = std::sqrt(uu), sv = std::sqrt(vv);
  const double r = b / su;
  if (r > 38.0) return 0.0;
  const double rho = std::clamp(uv / (su * sv), -0.999999, 0.999999);
  const double root = std::sqrt(1.0 - rho * rho);
  const double s = sv * root, eta = rho * r / root;
  const double phi_r = std::exp(-0.5 * r * r) / std::sqrt(2.0 * pi);
  const double phi_eta = std::exp(-0.5 * eta * eta) / std::sqrt(2.0 * pi);
  const double rice = 2.0 * phi_r * s * (phi_eta + eta * normal_cdf(eta)) / su;
  if (!(delta_e > 0.0)) return rice;
  const double clump = -std::expm1(-std::sqrt(pi / 2.0) * delta_e * r) / -std::expm1(-0.5 * r * r);
  return rice * clump;
}

// ∫ α(b, t) dt by the trapezoidal rule over the samples.
double exposure(double b, const ResponseMoments& m, const std::vector<double>& delta_e, double dt) {
  double sum = 0.0;
  const std::size_t n = m.uu.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double a = crossing_rate(b, m.uu[k], m.vv[k], m.uv[k], delta_e.empty() ? 0.0 : delta_e[k]);
    sum += (k == 0 || k + 1 == n ? 0.5 : 1.0) * a;
  }
  return sum * dt;
}

// The peak b with P(max |u| ≤ b) = p: ∫ α dt = −ln p, decreasing in b;
// bisection in ln b.
double peak_quantile(double p, const ResponseMoments& m, const std::vector<double>& delta_e, double dt) {
  double peak_sd = 0.0;
  for (double x : m.uu) peak_sd = std::max(peak_sd, std::sqrt(x));
  const double target = -std::log(p);
  double lo = std::log(1e-3 * peak_sd), hi = std::log(40.0 * peak_sd);
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    (exposure(std::exp(mid), m, delta_e, dt) > target ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace

SyntheticTarget synthetic_target(const SyntheticMotionParameters& p, const SyntheticOptions& o,
                                 const std::vector<double>& periods, double damping) {
  if (periods.empty()) throw std::invalid_argument("synthetic target: no periods");
  for (double T : periods)
    if (!(T > 0.0) || !std::isfinite(T))
      throw std::invalid_argument("synthetic target: period must be > 0 s, got " + std::to_string(T));
  if (!(damping > 0.0 && damping < 1.0))
    throw std::invalid_argument("synthetic target: damping must be in (0, 1)");

  std::vector<double> mean_square;
  std::vector<ResponseMoments> osc(periods.size());
  for (std::size_t j = 0; j < periods.size(); ++j) {
    osc[j].omega = 2.0 * pi / periods[j];
    osc[j].step = oscillator_step(o.dt, osc[j].omega, damping);
  }
  const std::size_t n = for_each_unit_record(p, o, [&](std::size_t first, const std::vector<double>& g) {
    const std::size_t total = first + g.size();
    if (mean_square.size() < total) {
      mean_square.resize(total, 0.0);
      for (ResponseMoments& m : osc) {
        m.uu.resize(total, 0.0);
        m.vv.resize(total, 0.0);
        m.uv.resize(total, 0.0);
      }
    }
    for (std::size_t k = 0; k < g.size(); ++k) mean_square[first + k] += g[k] * g[k];
    for (ResponseMoments& m : osc) {
      const OscillatorStep& s = m.step;
      double u = 0.0, v = 0.0;
      for (std::size_t k = 1; k < g.size(); ++k) {
        const double u1 = s.A[0][0] * u + s.A[0][1] * v + s.B[0][0] * g[k - 1] + s.B[0][1] * g[k];
        const double v1 = s.A[1][0] * u + s.A[1][1] * v + s.B[1][0] * g[k - 1] + s.B[1][1] * g[k];
        u = u1;
        v = v1;
        m.uu[first + k] += u * u;
        m.vv[first + k] += v * v;
        m.uv[first + k] += u * v;
      }
    }
  });

  SyntheticTarget t;
  t.damping = damping;
  t.period = periods;
  // The expected cumulative Arias intensity, and its 5, 45, 95 % times.
  std::vector<double> cumulative(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
    cumulative[k] = cumulative[k - 1] + 0.5 * o.dt * (mean_square[k - 1] + mean_square[k]);
  t.arias_intensity = pi / (2.0 * o.g) * cumulative.back();
  const auto time_at = [&](double share) {
    const double target = share * cumulative.back();
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
    if (it == cumulative.begin()) return 0.0;
    const std::size_t i = static_cast<std::size_t>(it - cumulative.begin());
    const double span = cumulative[i] - cumulative[i - 1];
    return o.dt * (static_cast<double>(i - 1) + (span > 0.0 ? (target - cumulative[i - 1]) / span : 0.0));
  };
  t.t5 = time_at(0.05);
  t.t45 = time_at(0.45);
  t.t95 = time_at(0.95);
  t.d5_95 = t.t95 - t.t5;

  // The filter's frequency at each sample (held after the noise ends), and
  // the bandwidth tabulated over its range.
  const ModulatingFunction q = modulating_function(p, o.g);
  const double t_noise = gamma_quantile(q.shape(), o.energy_end) / q.rate();
  const auto filter_frequency = [&](double time) {
    return 2.0 * pi * std::max(o.min_frequency, p.f_mid + p.f_slope * (std::min(time, t_noise) - p.t_mid));
  };
  double w_lo = filter_frequency(0.0), w_hi = w_lo;
  for (std::size_t k = 0; k < n; ++k) {
    w_lo = std::min(w_lo, filter_frequency(static_cast<double>(k) * o.dt));
    w_hi = std::max(w_hi, filter_frequency(static_cast<double>(k) * o.dt));
  }
  const double wc = 2.0 * pi * o.high_pass;
  constexpr int kTable = 32;
  for (ResponseMoments& m : osc) {
    std::vector<double> table(kTable + 1);
    for (int i = 0; i <= kTable; ++i)
      table[static_cast<std::size_t>(i)] = bandwidth(m.omega, damping, w_lo + (w_hi - w_lo) * i / kTable, p.zeta_f, wc);
    std::vector<double> delta_e(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double x = w_hi > w_lo ? (filter_frequency(static_cast<double>(k) * o.dt) - w_lo) / (w_hi - w_lo) * kTable : 0.0;
      const int i = std::min(kTable - 1, static_cast<int>(x));
      const double f = x - i, d = (1.0 - f) * table[static_cast<std::size_t>(i)] + f * table[static_cast<std::size_t>(i) + 1];
      delta_e[k] = std::pow(d, 1.2);
    }
    const double w2 = m.omega * m.omega;
    const double b50 = peak_quantile(0.5, m, delta_e, o.dt);
    const double b16 = peak_quantile(0.16, m, delta_e, o.dt), b84 = peak_quantile(0.84, m, delta_e, o.dt);
    double peak_sd = 0.0;
    for (double x : m.uu) peak_sd = std::max(peak_sd, std::sqrt(x));
    t.median_pseudo_acceleration.push_back(w2 * b50);
    t.poisson_median_pseudo_acceleration.push_back(w2 * peak_quantile(0.5, m, {}, o.dt));
    t.dispersion.push_back(0.5 * (std::log(b84) - std::log(b16)));
    t.rms_pseudo_acceleration.push_back(w2 * peak_sd);
    t.bandwidth.push_back(bandwidth(m.omega, damping, filter_frequency(p.t_mid), p.zeta_f, wc));
  }
  return t;
}

}  // namespace polydem::analytical
