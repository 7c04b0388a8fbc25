#include "analytical/rocking_body.hpp"

#include <cmath>
#include <stdexcept>

namespace polydem::analytical {

double restitution_eq10(double mass, double R, double I0, double alpha) {
  return 1.0 - mass * R * R / I0 * (1.0 - std::cos(2.0 * alpha));
}

double restitution_housner_block(double alpha) {
  const double s = std::sin(alpha);
  return 1.0 - 1.5 * s * s;
}

RockingBody make_rocking_body(double mass, double R, double alpha, double I0, double g) {
  if (!(mass > 0.0) || !(R > 0.0) || !(I0 > 0.0) || !(g > 0.0) || !(alpha > 0.0) || !(alpha < 1.5707963267948966))
    throw std::invalid_argument("rocking body: need mass, R, I0, g > 0 and 0 < alpha < pi/2");
  RockingBody b;
  b.mass = mass;
  b.R = R;
  b.alpha = alpha;
  b.I0 = I0;
  b.p = std::sqrt(mass * g * R / I0);
  b.restitution = restitution_eq10(mass, R, I0, alpha);
  return b;
}

RockingBody rectangular_block(double b, double h, double mass, double g) {
  if (!(b > 0.0) || !(h > 0.0)) throw std::invalid_argument("rectangular_block: b and h must be > 0");
  const double R = std::hypot(b, h);
  return make_rocking_body(mass, R, std::atan2(b, h), 4.0 / 3.0 * mass * R * R, g);
}

RockingBody conical_shell(double r_b, double H, double mass, double g) {
  if (!(r_b > 0.0) || !(H > 0.0)) throw std::invalid_argument("conical_shell: r_b and H must be > 0");
  const double zc = H / 3.0;
  const double I0 = 1.25 * mass * r_b * r_b + mass * H * H / 6.0;  // eq. 8
  return make_rocking_body(mass, std::hypot(r_b, zc), std::atan2(r_b, zc), I0, g);
}

RockingBody solid_cone(double r_b, double H, double mass, double g) {
  if (!(r_b > 0.0) || !(H > 0.0)) throw std::invalid_argument("solid_cone: r_b and H must be > 0");
  const double zc = H / 4.0;
  const double I0 = 23.0 / 20.0 * mass * r_b * r_b + 0.1 * mass * H * H;
  return make_rocking_body(mass, std::hypot(r_b, zc), std::atan2(r_b, zc), I0, g);
}

}  // namespace polydem::analytical
