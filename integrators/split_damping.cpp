#include "integrators/split_damping.hpp"

#include <algorithm>
#include <cmath>

namespace polydem {

namespace {

// The least value of c0 + c1·x + c2·x² on [0, hi].
double least_on(double c0, double c1, double c2, double hi) {
  double m = std::min(c0, c0 + (c1 + c2 * hi) * hi);
  if (c2 > 0) {
    const double x = -c1 / (2.0 * c2);
    if (x > 0 && x < hi) m = std::min(m, c0 + (c1 + c2 * x) * x);
  }
  return m;
}

}  // namespace

bool split_damping_stable(double W, double xi_max, double theta) {
  if (!(W > 0)) return true;
  const double x_max = 2.0 * xi_max * W;
  // b = 1 − θ·X is least at X_max.
  if (1.0 - theta * x_max < 0) return false;
  // ab = 1 − X + θ(1 − θ)·X² within [−1, 1].
  const double q = theta * (1.0 - theta);
  if (least_on(1.0, -1.0, q, x_max) < -1.0) return false;
  if (-least_on(-1.0, 1.0, -q, x_max) > 1.0) return false;
  // 2 + 2ab − b·W² = (4 − W²) + (θW² − 2)·X + 2q·X².
  return least_on(4.0 - W * W, theta * W * W - 2.0, 2.0 * q, x_max) >= 0;
}

SplitDamping split_damping(double xi_max) {
  SplitDamping best{0.5, 0.0};
  for (int k = 1; k <= 50; ++k) {
    const double theta = 0.01 * k;
    double lo = 0, hi = 2.0;
    if (split_damping_stable(hi, xi_max, theta)) {
      lo = hi;
    } else {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (split_damping_stable(mid, xi_max, theta) ? lo : hi) = mid;
      }
    }
    if (lo > best.limit) best = {theta, lo};
  }
  return best;
}

double explicit_damping_limit(double xi_max) { return 2.0 * (std::sqrt(1.0 + xi_max * xi_max) - xi_max); }

}  // namespace polydem
