#include "analytical/free_rocking.hpp"

#include <cmath>
#include <stdexcept>

namespace polydem::analytical {
namespace {

void check(double p, double alpha, double theta0) {
  if (!(p > 0.0) || !(alpha > 0.0) || !(theta0 > 0.0) || !(theta0 < alpha))
    throw std::invalid_argument("free rocking: need p > 0 and 0 < theta0 < alpha");
}

template <class F>
double simpson(const F& f, double a, double b, double fa, double fm, double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double diff = left + right - whole;
  if (depth <= 0 || std::abs(diff) <= 15.0 * tol) return left + right + diff / 15.0;
  return simpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
         simpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

}  // namespace

double free_rocking_time_to_impact(double p, double alpha, double theta0) {
  check(p, alpha, theta0);
  const double a = alpha - theta0;
  // dθ = −2w dw; integrand 2w / (p √(4 sin(a + w²/2) sin(w²/2))), → 2/(p√(2 sin a)) at w = 0.
  auto g = [&](double w) {
    if (w == 0.0) return 2.0 / (p * std::sqrt(2.0 * std::sin(a)));
    const double h = 0.5 * w * w;
    return 2.0 * w / (p * std::sqrt(4.0 * std::sin(a + h) * std::sin(h)));
  };
  const double wb = std::sqrt(theta0);
  const double fa = g(0.0), fm = g(0.5 * wb), fb = g(wb);
  const double whole = wb / 6.0 * (fa + 4.0 * fm + fb);
  const double scale = free_rocking_time_to_impact_linear(p, alpha, theta0);
  return simpson(g, 0.0, wb, fa, fm, fb, whole, 1e-14 * scale, 50);
}

double free_rocking_time_to_impact_linear(double p, double alpha, double theta0) {
  check(p, alpha, theta0);
  return std::acosh(alpha / (alpha - theta0)) / p;
}

double free_rocking_impact_velocity(double p, double alpha, double theta0) {
  check(p, alpha, theta0);
  // cos(α − θ0) − cos α = 2 sin(α − θ0/2) sin(θ0/2)
  return -p * std::sqrt(4.0 * std::sin(alpha - 0.5 * theta0) * std::sin(0.5 * theta0));
}

}  // namespace polydem::analytical
