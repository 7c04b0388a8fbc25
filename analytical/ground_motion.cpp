#include "analytical/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "analytical/constants.hpp"

namespace polydem::analytical {

GroundMotion constant_ground_motion(double a) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {[a](double t) { return t >= 0.0 ? a : 0.0; }, inf, [](double t) { return t < 0.0 ? 0.0 : inf; }};
}

GroundMotion sine_pulse_ground_motion(double a_p, double T_p) {
  if (!(T_p > 0.0)) throw std::invalid_argument("sine pulse: T_p must be > 0");
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {[a_p, T_p](double t) { return (t >= 0.0 && t <= T_p) ? a_p * std::sin(2.0 * pi * t / T_p) : 0.0; }, T_p,
          [T_p](double t) { return t < 0.0 ? 0.0 : (t < T_p ? T_p : inf); }};
}

GroundMotion sampled_ground_motion(double dt, std::vector<double> samples) {
  if (!(dt > 0.0) || samples.empty()) throw std::invalid_argument("sampled ground motion: need dt > 0 and samples");
  const double end = dt * static_cast<double>(samples.size() - 1);
  auto fn = [dt, s = std::move(samples)](double t) {
    if (t < 0.0) return 0.0;
    const double u = t / dt;
    const auto i = static_cast<std::size_t>(u);
    if (i + 1 >= s.size()) return i + 1 == s.size() && u == static_cast<double>(i) ? s.back() : 0.0;
    const double f = u - static_cast<double>(i);
    return (1.0 - f) * s[i] + f * s[i + 1];
  };
  auto next = [dt, end](double t) {
    if (t < 0.0) return 0.0;
    if (t >= end) return std::numeric_limits<double>::infinity();
    // The first sample time strictly after t: t/dt rounds (0.29/0.01 is
    // 28.999...), so the floor alone can land on t itself.
    double k = std::floor(t / dt) + 1.0;
    while (dt * k <= t) k += 1.0;
    return std::min(end, dt * k);
  };
  return {fn, end, next};
}

}  // namespace polydem::analytical
