#include "analytical/synthetic_ground_motion.hpp"

#include "analytical/constants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <stdexcept>

namespace polydem::analytical {

namespace {

// ---------------------------------------------------- predictive equations
//
// Rezaeian & Der Kiureghian (2010), the predictive equations of the six
// parameters in the standard normal space:
//   ν₁ = β₀ + β₁ (M/7) + β₂ F + β₃ ln(R/25) + β₄ ln(V/750)      (I_a)
//   νᵢ = β₀ + β₁ M     + β₂ F + β₃ R       + β₄ V              (the others)
// with the errors' standard deviations σ (intra-event) and τ (inter-event)
// and the correlation of the total errors. The same numbers are used by
// the SCEC Broadband Platform's implementation of these equations as
// GMPEs of the six parameters.
constexpr int kParameters = 6;
constexpr double kBeta[kParameters][5] = {
    {-2.2962, 2.9440, -0.0707, -1.3564, -0.2654},  // I_a [s g]
    {-6.1946, 0.9703, -0.7034, 0.0087, -0.0007},   // D5-95 [s]
    {-5.0105, 0.6625, -0.3450, 0.0139, -0.0002},   // t_mid [s]
    {2.2525, -0.2586, -0.0808, -0.0084, 0.0000},   // ω_mid/2π [Hz]
    {-2.4886, 0.3440, 0.0441, 0.0026, -0.0001},    // ω′/2π [Hz/s]
    {-0.2583, 0.1293, -0.4772, -0.0115, 0.0004},   // ζ_f
};
constexpr double kSigma[kParameters] = {0.5937, 0.5688, 0.4145, 0.7228, 0.9529, 0.7601};
constexpr double kTau[kParameters] = {0.2738, 0.4574, 0.5114, 0.6918, 0.1286, 0.6815};
constexpr double kRho[kParameters][kParameters] = {
    {1.0000, -0.3555, 0.0066, -0.1545, 0.1341, -0.0078}, {-0.3555, 1.0000, 0.6729, -0.1303, -0.1576, -0.1958},
    {0.0066, 0.6729, 1.0000, -0.2761, -0.1977, -0.2188}, {-0.1545, -0.1303, -0.2761, 1.0000, -0.2034, 0.2814},
    {0.1341, -0.1576, -0.1977, -0.2034, 1.0000, -0.0137}, {-0.0078, -0.1958, -0.2188, 0.2814, -0.0137, 1.0000},
};

// The fitted marginals, physical value from the standard normal ν:
//   I_a ~ lognormal, ln I_a [s g] ~ N(−4.8255, 1.4318)
//   D5-95 ~ 5 + 40 Beta(1.1314, 2.4474)        [s]
//   t_mid ~ 0.5 + 39.5 Beta(1.5792, 3.6405)    [s]
//   ω_mid/2π ~ Gamma(shape 4.0982, scale 1.4330)   [Hz]
//   ω′/2π ~ two-sided exponential on [−2, 0.5]: density c e^{b x} below 0,
//           c e^{−a x} above, a = 17.095, b = 6.7729, c = 4.8512  [Hz/s]
//   ζ_f ~ 0.02 + 0.98 Beta(1.4250, 5.7208)
double slope_quantile(double p) {
  const double a = 17.095, b = 6.7729, c = 4.8512, lo = -2.0;
  const double at_zero = c / b * (1.0 - std::exp(b * lo));
  if (p < at_zero) return std::log(p * b / c + std::exp(b * lo)) / b;
  return -std::log(1.0 - (p - at_zero) * a / c) / a;
}

// ζ_f is capped below 1 so that the filter stays an underdamped oscillator.
constexpr double kMaxZeta = 0.95;

SyntheticMotionParameters from_normal_space(const std::array<double, kParameters>& nu, double g) {
  SyntheticMotionParameters p;
  p.arias_intensity = std::exp(-4.8255 + 1.4318 * nu[0]) * g;
  p.d5_95 = 5.0 + 40.0 * beta_quantile(1.1314, 2.4474, normal_cdf(nu[1]));
  p.t_mid = 0.5 + 39.5 * beta_quantile(1.5792, 3.6405, normal_cdf(nu[2]));
  p.f_mid = 1.4330 * gamma_quantile(4.0982, normal_cdf(nu[3]));
  p.f_slope = slope_quantile(normal_cdf(nu[4]));
  p.zeta_f = std::min(kMaxZeta, 0.02 + 0.98 * beta_quantile(1.4250, 5.7208, normal_cdf(nu[5])));
  return p;
}

std::array<double, kParameters> regression_means(const EarthquakeScenario& s) {
  if (!(s.magnitude > 0.0 && s.distance > 0.0 && s.vs30 > 0.0))
    throw std::invalid_argument("synthetic motion: magnitude, distance and vs30 must be > 0");
  const double F = s.reverse ? 1.0 : 0.0;
  std::array<double, kParameters> nu{};
  for (int i = 0; i < kParameters; ++i) {
    const double* b = kBeta[i];
    nu[i] = i == 0 ? b[0] + b[1] * s.magnitude / 7.0 + b[2] * F + b[3] * std::log(s.distance / 25.0) +
                         b[4] * std::log(s.vs30 / 750.0)
                   : b[0] + b[1] * s.magnitude + b[2] * F + b[3] * s.distance + b[4] * s.vs30;
  }
  return nu;
}

// Lower Cholesky factor of the total errors' covariance.
std::array<std::array<double, kParameters>, kParameters> error_factor() {
  std::array<std::array<double, kParameters>, kParameters> L{};
  double cov[kParameters][kParameters];
  for (int i = 0; i < kParameters; ++i)
    for (int j = 0; j < kParameters; ++j)
      cov[i][j] = kRho[i][j] * std::hypot(kSigma[i], kTau[i]) * std::hypot(kSigma[j], kTau[j]);
  for (int i = 0; i < kParameters; ++i) {
    for (int j = 0; j <= i; ++j) {
      double s = cov[i][j];
      for (int k = 0; k < j; ++k) s -= L[i][k] * L[j][k];
      L[i][j] = i == j ? std::sqrt(s) : s / L[j][j];
    }
  }
  return L;
}

// D5-95 / t_mid of a gamma law of shape k (rate 1).
double duration_ratio(double k) {
  return (gamma_quantile(k, 0.95) - gamma_quantile(k, 0.05)) / gamma_quantile(k, 0.45);
}

constexpr double kMinShape = 1.0;  // α₂ > 1: q(0) = 0

// ------------------------------------------------------------- simulation

// Response ü of the critically damped post-filter ü + 2ω u̇ + ω² u = x,
// from rest, by the average-acceleration (trapezoidal) rule: second order,
// unconditionally stable; with ω Δt ≈ 0.013 its error is far below the
// record's own randomness.
std::vector<double> high_pass(const std::vector<double>& x, double dt, double f_c) {
  const double w = 2.0 * pi * f_c, c = 2.0 * w, k = w * w;
  std::vector<double> out(x.size(), 0.0);
  double u = 0.0, v = 0.0, acc = x.empty() ? 0.0 : x[0];
  if (!x.empty()) out[0] = acc;
  const double k_eff = k + 2.0 * c / dt + 4.0 / (dt * dt);
  for (std::size_t n = 1; n < x.size(); ++n) {
    const double rhs = x[n] + c * (2.0 / dt * u + v) + 4.0 / (dt * dt) * u + 4.0 / dt * v + acc;
    const double u1 = rhs / k_eff;
    const double v1 = 2.0 / dt * (u1 - u) - v;
    const double a1 = 4.0 / (dt * dt) * (u1 - u) - 4.0 / dt * v - acc;
    u = u1, v = v1, acc = a1;
    out[n] = acc;
  }
  return out;
}

// The record's length and envelope for parameters and options, after the
// checks every simulation makes.
struct RecordLayout {
  ModulatingFunction q;
  std::size_t n_noise = 0;  // samples carrying noise, from t = 0
  std::size_t n_total = 0;  // plus the post-filter's tail
};

RecordLayout record_layout(const SyntheticMotionParameters& p, const SyntheticOptions& o) {
  if (!(o.dt > 0.0 && o.dt <= 0.1)) throw std::invalid_argument("synthetic motion: dt must be in (0, 0.1] s");
  if (!(o.high_pass >= 0.0) || !(o.min_frequency > 0.0) || !(o.energy_end > 0.5 && o.energy_end < 1.0) ||
      !(o.tail >= 0.0) || !(o.g > 0.0))
    throw std::invalid_argument("synthetic motion: options out of range");
  if (!(p.f_mid > 0.0) || !(p.zeta_f > 0.0 && p.zeta_f < 1.0))
    throw std::invalid_argument("synthetic motion: f_mid must be > 0 and zeta_f in (0, 1)");
  RecordLayout l;
  l.q = modulating_function(p, o.g);
  const double t_noise = gamma_quantile(l.q.shape(), o.energy_end) / l.q.rate();
  l.n_noise = static_cast<std::size_t>(std::ceil(t_noise / o.dt)) + 1;
  l.n_total = l.n_noise + static_cast<std::size_t>(std::ceil(o.tail / o.dt));
  return l;
}

// The filter bank behind x(t) = q(t) Σᵢ sᵢ(t) uᵢ, walked over the noise
// samples k = 1 … n_noise − 1. Each impulse keeps its filter's state as a
// complex number w with Im w = h(t − tᵢ; tᵢ): w is multiplied by
// e^{(−ζω + iω_d)Δt} per step. Impulses whose |w| has decayed below 1e-9 of
// its start contribute nothing measurable and are dropped (in order).
//
// At t_k the impulse of t_{k−1} enters carrying enter(k) (its uᵢ when
// simulating, its index when the record is taken apart); then
// sample(k, q(t_k), Σ h², live) sees every live impulse (h = w.imag(), and
// its payload) before they advance one step.
template <class Payload, class Enter, class Sample>
void walk_filter_bank(const SyntheticMotionParameters& p, const SyntheticOptions& o, const RecordLayout& l,
                      Enter enter, Sample sample) {
  struct Impulse {
    std::complex<double> w, step;
    Payload payload;
    double floor;
  };
  std::vector<Impulse> live;
  const double root = std::sqrt(1.0 - p.zeta_f * p.zeta_f);
  for (std::size_t k = 1; k < l.n_noise; ++k) {
    const double t = static_cast<double>(k) * o.dt;
    // The impulse at t_{k−1} enters; it has advanced one step by t_k.
    const double tau = t - o.dt;
    const double f = std::max(o.min_frequency, p.f_mid + p.f_slope * (tau - p.t_mid));
    const double omega = 2.0 * pi * f;
    const std::complex<double> step = std::exp(std::complex<double>(-p.zeta_f * omega, omega * root) * o.dt);
    const double amplitude = omega / root;
    live.push_back({amplitude * step, step, enter(k), 1e-9 * amplitude});
    double norm = 0.0;
    for (const Impulse& m : live) {
      const double h = m.w.imag();
      norm += h * h;
    }
    const ModulatingFunction& q = l.q;
    const double envelope = q.alpha1 * std::pow(t, q.alpha2 - 1.0) * std::exp(-q.alpha3 * t);
    sample(k, envelope, norm, live);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < live.size(); ++i) {
      Impulse& m = live[i];
      m.w *= m.step;
      if (std::abs(m.w) >= m.floor) live[kept++] = m;
    }
    live.resize(kept);
  }
}

}  // namespace

ModulatingFunction modulating_function(const SyntheticMotionParameters& p, double g) {
  if (!(p.arias_intensity > 0.0 && p.d5_95 > 0.0 && p.t_mid > 0.0))
    throw std::invalid_argument("synthetic motion: I_a, D5-95 and t_mid must be > 0");
  const double target = p.d5_95 / p.t_mid;
  if (!(target < duration_ratio(kMinShape)))
    throw std::invalid_argument("synthetic motion: D5-95 / t_mid must be < 4.92 (the modulating function needs alpha2 > 1)");
  // The ratio falls as the shape grows: bisection in ln k.
  double lo = std::log(kMinShape), hi = std::log(kMinShape);
  while (duration_ratio(std::exp(hi)) > target) hi += 1.0;
  for (int i = 0; i < 100 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    (duration_ratio(std::exp(mid)) > target ? lo : hi) = mid;
  }
  const double k = std::exp(0.5 * (lo + hi));
  const double rate = gamma_quantile(k, 0.45) / p.t_mid;
  // ∫ q² dt = α₁² Γ(k) / rate^k = 2 g I_a / π.
  const double energy = 2.0 * g * p.arias_intensity / pi;
  ModulatingFunction q;
  q.alpha2 = 0.5 * (k + 1.0);
  q.alpha3 = 0.5 * rate;
  q.alpha1 = std::sqrt(energy * std::exp(k * std::log(rate) - std::lgamma(k)));
  return q;
}

SyntheticMotionParameters median_parameters(const EarthquakeScenario& s) {
  return from_normal_space(regression_means(s), SyntheticOptions{}.g);
}

SyntheticMotionParameters sample_parameters(const EarthquakeScenario& s, RandomStream& rs) {
  static const auto L = error_factor();
  const std::array<double, kParameters> mean = regression_means(s);
  const double ratio_limit = duration_ratio(kMinShape);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    std::array<double, kParameters> z{}, nu = mean;
    for (double& zi : z) zi = rs.normal();
    for (int i = 0; i < kParameters; ++i)
      for (int j = 0; j <= i; ++j) nu[i] += L[i][j] * z[j];
    const SyntheticMotionParameters p = from_normal_space(nu, SyntheticOptions{}.g);
    if (p.d5_95 / p.t_mid < ratio_limit) return p;
  }
  throw std::invalid_argument("synthetic motion: the scenario gives D5-95 / t_mid >= 4.92 in 1000 draws out of 1000");
}

SyntheticRecord simulate_record(const SyntheticMotionParameters& p, const SyntheticOptions& o, RandomStream& rs) {
  const RecordLayout l = record_layout(p, o);
  std::vector<double> x(l.n_total, 0.0);
  walk_filter_bank<double>(
      p, o, l, [&](std::size_t) { return rs.normal(); },
      [&](std::size_t k, double envelope, double norm, const auto& live) {
        double sum = 0.0;
        for (const auto& m : live) {
          const double h = m.w.imag();
          sum += h * m.payload;
        }
        x[k] = norm > 0.0 ? envelope * sum / std::sqrt(norm) : 0.0;
      });
  SyntheticRecord r;
  r.parameters = p;
  r.dt = o.dt;
  r.acceleration = o.high_pass > 0.0 ? high_pass(x, o.dt, o.high_pass) : x;
  return r;
}

std::size_t for_each_unit_record(const SyntheticMotionParameters& p, const SyntheticOptions& o,
                                 const std::function<void(std::size_t, const std::vector<double>&)>& visit) {
  const RecordLayout l = record_layout(p, o);
  // terms[i][j]: the pre-filter sample i + 1 + j per unit uᵢ (an impulse
  // is live over consecutive samples from the one after it enters).
  std::vector<std::vector<double>> terms;
  walk_filter_bank<std::size_t>(
      p, o, l,
      [&](std::size_t k) {
        terms.emplace_back();
        return k - 1;
      },
      [&](std::size_t, double envelope, double norm, const auto& live) {
        const double scale = norm > 0.0 ? envelope / std::sqrt(norm) : 0.0;
        for (const auto& m : live) terms[m.payload].push_back(scale * m.w.imag());
      });
  for (std::size_t i = 0; i < terms.size(); ++i) {
    // From sample i (zero: the impulse enters there) to the record's end.
    std::vector<double> g(l.n_total - i, 0.0);
    std::copy(terms[i].begin(), terms[i].end(), g.begin() + 1);
    std::vector<double>().swap(terms[i]);
    if (o.high_pass > 0.0) g = high_pass(g, o.dt, o.high_pass);
    visit(i, g);
  }
  return l.n_total;
}

std::vector<SyntheticRecord> synthetic_suite(const EarthquakeScenario& s, int count, std::uint64_t seed,
                                             const SyntheticOptions& o, const std::string& prefix) {
  if (count < 1 || count > 100000) throw std::invalid_argument("synthetic motion: count must be in [1, 100000]");
  const std::size_t digits = std::max<std::size_t>(2, std::to_string(count).size());
  std::vector<SyntheticRecord> suite;
  for (int i = 0; i < count; ++i) {
    const std::uint64_t record_seed = mix_seed(seed, static_cast<std::uint64_t>(i));
    RandomStream rs(record_seed);
    SyntheticRecord r = simulate_record(sample_parameters(s, rs), o, rs);
    std::string number = std::to_string(i + 1);
    number.insert(0, digits - number.size(), '0');
    r.name = prefix;
    r.name += '_';
    r.name += number;
    r.seed = record_seed;
    suite.push_back(std::move(r));
  }
  return suite;
}

RecordMeasures record_measures(double dt, const std::vector<double>& a, double g) {
  RecordMeasures m;
  if (a.size() < 2) return m;
  std::vector<double> cumulative(a.size(), 0.0);
  double v = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    cumulative[i] = cumulative[i - 1] + 0.5 * dt * (a[i - 1] * a[i - 1] + a[i] * a[i]);
    v += 0.5 * dt * (a[i - 1] + a[i]);
    m.pgv = std::max(m.pgv, std::fabs(v));
  }
  for (double x : a) m.pga = std::max(m.pga, std::fabs(x));
  m.residual_velocity = v;
  const double total = cumulative.back();
  m.arias_intensity = pi / (2.0 * g) * total;
  auto time_at = [&](double share) {
    const double target = share * total;
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
    if (it == cumulative.begin()) return 0.0;
    const std::size_t i = static_cast<std::size_t>(it - cumulative.begin());
    const double span = cumulative[i] - cumulative[i - 1];
    return dt * (static_cast<double>(i - 1) + (span > 0.0 ? (target - cumulative[i - 1]) / span : 0.0));
  };
  m.t5 = time_at(0.05);
  m.t45 = time_at(0.45);
  m.t95 = time_at(0.95);
  m.d5_95 = m.t95 - m.t5;
  return m;
}

int upcrossings(double dt, const std::vector<double>& a, double t0, double t1) {
  int count = 0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    const double t = static_cast<double>(i) * dt;
    if (t < t0 || t > t1) continue;
    if (a[i - 1] < 0.0 && a[i] >= 0.0) ++count;
  }
  return count;
}

}  // namespace polydem::analytical
