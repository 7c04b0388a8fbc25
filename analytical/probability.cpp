#include "analytical/probability.hpp"

#include "analytical/constants.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace polydem::analytical {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double sqrt_half = 0.70710678118654752440;

// Acklam's coefficients for Φ⁻¹: a rational function in the central region
// (|p − 0.5| ≤ 0.475), another in √(−2 ln p) in the tails.
constexpr double acklam_a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                               1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
constexpr double acklam_b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                               6.680131188771972e+01,  -1.328068155288572e+01};
constexpr double acklam_c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                               -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
constexpr double acklam_d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};

double tail_rational(double q) {
  const double* c = acklam_c;
  const double* d = acklam_d;
  return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
         ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
}

// Bisection of an increasing function f on [lo, hi] for f(x) = p, to the
// last bit (or 200 halvings).
template <typename F>
double bisect(F f, double p, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Lentz's evaluation of the continued fraction of I_x(a, b) (converges for
// x < (a + 1) / (a + b + 2); the caller uses the symmetry otherwise).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 1000; ++m) {
    const double m2 = 2.0 * m;
    double num = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    for (int half = 0; half < 2; ++half) {
      d = 1.0 + num * d;
      if (std::fabs(d) < tiny) d = tiny;
      c = 1.0 + num / c;
      if (std::fabs(c) < tiny) c = tiny;
      d = 1.0 / d;
      h *= d * c;
      num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    }
    if (std::fabs(d * c - 1.0) < 1e-16) break;
  }
  return h;
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x * sqrt_half); }

double log_normal_cdf(double x) {
  if (x > -5.0) return std::log1p(-0.5 * std::erfc(x * sqrt_half));
  if (x > -20.0) return std::log(0.5 * std::erfc(-x * sqrt_half));
  // Far in the tail erfc underflows: the asymptotic series
  // Φ(x) = φ(x)/(−x) (1 − 1/x² + 3/x⁴ − 15/x⁶ + 105/x⁸ ...), error < 1e-10.
  const double r = 1.0 / (x * x);
  return -0.5 * x * x - std::log(-x) - 0.5 * std::log(2.0 * pi) +
         std::log1p(r * (-1.0 + r * (3.0 + r * (-15.0 + r * 105.0))));
}

double log_normal_sf(double x) { return log_normal_cdf(-x); }

double normal_quantile(double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("normal_quantile: p must be in [0, 1]");
  if (p == 0.0) return -inf;
  if (p == 1.0) return inf;
  double x;
  const double p_low = 0.02425;
  if (p < p_low) {
    x = tail_rational(std::sqrt(-2.0 * std::log(p)));
  } else if (p > 1.0 - p_low) {
    x = -tail_rational(std::sqrt(-2.0 * std::log1p(-p)));
  } else {
    const double q = p - 0.5, r = q * q;
    const double* a = acklam_a;
    const double* b = acklam_b;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  }
  // One Halley step on e = Φ(x) − p.
  const double e = normal_cdf(x) - p;
  const double u = e * std::sqrt(2.0 * pi) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

double gamma_cdf(double k, double x) {
  if (!(k > 0.0) || !(x >= 0.0)) throw std::invalid_argument("gamma_cdf: needs k > 0, x >= 0");
  if (x == 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  const double log_prefactor = k * std::log(x) - x - std::lgamma(k);
  if (x < k + 1.0) {
    // Series: γ(k, x) = x^k e^−x Σ x^n / (k (k+1) ... (k+n)).
    double term = 1.0 / k, sum = term;
    for (int n = 1; n < 10000; ++n) {
      term *= x / (k + n);
      sum += term;
      if (std::fabs(term) < std::fabs(sum) * 1e-17) break;
    }
    return std::min(1.0, sum * std::exp(log_prefactor));
  }
  // Continued fraction for Γ(k, x) (Lentz).
  const double tiny = 1e-300;
  double b = x + 1.0 - k, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - k);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-16) break;
  }
  return std::max(0.0, 1.0 - std::exp(log_prefactor) * h);
}

double gamma_quantile(double k, double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("gamma_quantile: p must be in [0, 1]");
  if (p == 0.0) return 0.0;
  if (p == 1.0) return inf;
  double hi = std::max(1.0, k);
  while (gamma_cdf(k, hi) < p) hi *= 2.0;
  double lo = hi;
  while (lo > 1e-300 && gamma_cdf(k, lo) > p) lo *= 0.5;
  const double log_x = bisect([k](double t) { return gamma_cdf(k, std::exp(t)); }, p, std::log(lo), std::log(hi));
  return std::exp(log_x);
}

double beta_cdf(double a, double b, double x) {
  if (!(a > 0.0 && b > 0.0)) throw std::invalid_argument("beta_cdf: needs a, b > 0");
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) * beta_fraction(a, b, x) / a;
  return 1.0 - std::exp(log_front) * beta_fraction(b, a, 1.0 - x) / b;
}

double beta_quantile(double a, double b, double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("beta_quantile: p must be in [0, 1]");
  if (p == 0.0) return 0.0;
  if (p == 1.0) return 1.0;
  return bisect([a, b](double x) { return beta_cdf(a, b, x); }, p, 0.0, 1.0);
}

std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

RandomStream::RandomStream(std::uint64_t seed) : engine_(seed) {}

double RandomStream::uniform() {
  return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53;
}

double RandomStream::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * pi * uniform();
  spare_ = r * std::sin(angle);
  has_spare_ = true;
  return r * std::cos(angle);
}

std::size_t RandomStream::index(std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(uniform() * static_cast<double>(n)));
}

double percentile(std::vector<double>& values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (pos - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

}  // namespace polydem::analytical
