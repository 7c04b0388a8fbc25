#include "analytical/static_overturning.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analytical/constants.hpp"

namespace polydem::analytical {

double lambda_cone(double r_b, double H) {
  if (!(r_b > 0.0) || !(H > 0.0)) throw std::invalid_argument("lambda_cone: r_b and H must be > 0");
  return 3.0 * r_b / H;  // eq. 1
}

double crack_reduction_factor(double x) {
  if (!(x >= 0.0) || !(x <= 1.0)) throw std::invalid_argument("crack_reduction_factor: h_c/H must be in [0, 1]");
  // Eq. 2 with h_c = x H; every term carries H^3, which cancels.
  const double inv_pi2 = 1.0 / (pi * pi);
  const double num = inv_pi2 * x * x * x - (2.0 * inv_pi2 - 2.0 / 3.0) * x * x - 2.0 * x + 2.0;
  const double den = x * x * x - 2.0 * x * x + 2.0;  // ≥ 1 on [0,1]: never zero
  return num / den;
}

double lambda_crack(double r_b, double H, double h_c) {
  return lambda_cone(r_b, H) * crack_reduction_factor(h_c / H);
}

GoverningCrack governing_crack(double r_b, double H) {
  // A scan first: nothing promises eq. 2 is unimodal, so golden section alone
  // could stop at a local minimum.
  constexpr int n = 400;
  int best = 0;
  double best_f = crack_reduction_factor(0.0);
  for (int i = 1; i <= n; ++i) {
    const double f = crack_reduction_factor(static_cast<double>(i) / n);
    if (f < best_f) { best_f = f; best = i; }
  }
  double a = std::max(0.0, (best - 1.0) / n), b = std::min(1.0, (best + 1.0) / n);
  const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 100 && b - a > 1e-14; ++it) {
    const double c = b - gr * (b - a), d = a + gr * (b - a);
    if (crack_reduction_factor(c) <= crack_reduction_factor(d)) b = d; else a = c;
  }
  double x = 0.5 * (a + b);
  // The ends are candidates too (the interval search never evaluates them).
  for (double end : {0.0, 1.0})
    if (crack_reduction_factor(end) <= crack_reduction_factor(x)) x = end;
  return {lambda_cone(r_b, H) * crack_reduction_factor(x), x * H};
}

ConeOverturning cone_overturning(double r_b, double H, double h_c) {
  ConeOverturning c;
  c.r_b = r_b;
  c.H = H;
  c.h_c = h_c;
  c.lambda_eq1 = lambda_cone(r_b, H);
  c.governing = governing_crack(r_b, H);
  c.lambda_at_h_c = lambda_crack(r_b, H, h_c);
  return c;
}

}  // namespace polydem::analytical
