#include "core/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polydem {

namespace {

// Index of the record interval [t_k, t_k+1] that holds t (t inside the record).
std::size_t interval(const std::vector<double>& time, double t) {
  auto it = std::upper_bound(time.begin(), time.end(), t);
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - time.begin()) - 1));
}

}  // namespace

double GroundMotion::acceleration_at(double t) const {
  const double s = t - start_time;
  if (s < 0) return 0.0;
  switch (kind) {
    case GroundMotionKind::none: return 0.0;
    case GroundMotionKind::constant: return s < rise_time ? acceleration * s / rise_time : acceleration;
    case GroundMotionKind::ramp: return rate * s;
    case GroundMotionKind::sine_pulse:
      return s <= period ? acceleration * std::sin(2.0 * std::numbers::pi * s / period) : 0.0;
    case GroundMotionKind::record: {
      if (record_time.empty() || s < record_time.front() || s > record_time.back()) return 0.0;
      const std::size_t k = interval(record_time, s);
      if (k + 1 >= record_time.size()) return record_acceleration.back();
      const double w = (s - record_time[k]) / (record_time[k + 1] - record_time[k]);
      return (1 - w) * record_acceleration[k] + w * record_acceleration[k + 1];
    }
  }
  return 0.0;
}

double GroundMotion::velocity_at(double t) const {
  const double s = t - start_time;
  if (s < 0) return 0.0;
  switch (kind) {
    case GroundMotionKind::none: return 0.0;
    case GroundMotionKind::constant:
      return s < rise_time ? 0.5 * acceleration * s * s / rise_time : acceleration * (s - 0.5 * rise_time);
    case GroundMotionKind::ramp: return 0.5 * rate * s * s;
    case GroundMotionKind::sine_pulse: {
      const double w = 2.0 * std::numbers::pi / period;
      const double tt = std::min(s, period);
      return acceleration / w * (1.0 - std::cos(w * tt));  // zero again after one cycle
    }
    case GroundMotionKind::record: {
      if (record_time.empty() || s < record_time.front()) return 0.0;
      if (s >= record_time.back()) return record_velocity.back();
      const std::size_t k = interval(record_time, s);
      const double a0 = record_acceleration[k];
      const double h = s - record_time[k];
      const double slope = (record_acceleration[k + 1] - a0) / (record_time[k + 1] - record_time[k]);
      return record_velocity[k] + a0 * h + 0.5 * slope * h * h;
    }
  }
  return 0.0;
}

Vec3 GroundMotion::acceleration_vector(double t) const {
  if (components.empty()) return Vec3(acceleration_at(t) * direction);
  bool first = true;
  Vec3 a = Vec3::Zero();
  auto add = [&](const GroundMotion& g) {
    if (!g.active()) return;
    const Vec3 term = g.acceleration_at(t) * g.direction;
    a = first ? term : Vec3(a + term);
    first = false;
  };
  add(*this);
  for (const GroundMotion& g : components) add(g);
  return a;
}

Vec3 GroundMotion::velocity_vector(double t) const {
  if (components.empty()) return Vec3(velocity_at(t) * direction);
  bool first = true;
  Vec3 v = Vec3::Zero();
  auto add = [&](const GroundMotion& g) {
    if (!g.active()) return;
    const Vec3 term = g.velocity_at(t) * g.direction;
    v = first ? term : Vec3(v + term);
    first = false;
  };
  add(*this);
  for (const GroundMotion& g : components) add(g);
  return v;
}

std::vector<double> oscillator_absolute_acceleration(const std::vector<double>& time,
                                                     const std::vector<double>& ag, double f_hz, double zeta) {
  const double w = 2.0 * std::numbers::pi * f_hz;
  std::vector<double> out(ag.size(), 0.0);
  if (ag.empty()) return out;
  // Relative displacement u, velocity v, acceleration a of the oscillator:
  // a + 2ζω v + ω² u = −a_g; the absolute acceleration is a + a_g = −2ζω v − ω² u.
  double u = 0, v = 0, a = -ag[0];
  out[0] = -2 * zeta * w * v - w * w * u;
  constexpr int kSub = 20;
  for (std::size_t k = 1; k < ag.size(); ++k) {
    const double h = (time[k] - time[k - 1]) / kSub;
    const double keff = w * w + 2 * zeta * w * 2 / h + 4 / (h * h);
    for (int j = 1; j <= kSub; ++j) {
      const double x = static_cast<double>(j) / kSub;
      const double p = -((1 - x) * ag[k - 1] + x * ag[k]);
      // Newmark β = 1/4, γ = 1/2, solved for the new displacement.
      const double rhs = p + (4 / (h * h)) * u + (4 / h) * v + a + 2 * zeta * w * ((2 / h) * u + v);
      const double u1 = rhs / keff;
      const double v1 = (2 / h) * (u1 - u) - v;
      const double a1 = (4 / (h * h)) * (u1 - u) - (4 / h) * v - a;
      u = u1;
      v = v1;
      a = a1;
    }
    out[k] = -2 * zeta * w * v - w * w * u;
  }
  return out;
}

GroundMotion make_ground_motion(const GroundMotionSpec& spec, std::vector<double> record_time,
                                std::vector<double> record_acceleration) {
  GroundMotion g;
  g.kind = spec.kind;
  g.applied_as = spec.applied_as;
  g.direction = spec.direction.normalized();
  g.start_time = spec.start_time;
  g.acceleration = spec.acceleration;
  g.rate = spec.rate;
  g.period = spec.period;
  g.rise_time = spec.rise_time;
  if (spec.kind == GroundMotionKind::record) {
    g.record_time = std::move(record_time);
    g.record_acceleration = std::move(record_acceleration);
    for (double& a : g.record_acceleration) a *= spec.scale;
    if (spec.tower_frequency > 0)
      g.record_acceleration =
          oscillator_absolute_acceleration(g.record_time, g.record_acceleration, spec.tower_frequency, spec.tower_damping);
    g.record_velocity.assign(g.record_time.size(), 0.0);
    for (std::size_t k = 1; k < g.record_time.size(); ++k)
      g.record_velocity[k] = g.record_velocity[k - 1] + 0.5 * (g.record_acceleration[k - 1] + g.record_acceleration[k]) *
                                                           (g.record_time[k] - g.record_time[k - 1]);
  }
  for (const GroundMotionSpec& c : spec.components) {
    if (c.kind == GroundMotionKind::none) continue;
    GroundMotion m = make_ground_motion(c, c.record_time, c.record_acceleration);
    m.applied_as = spec.applied_as;
    g.components.push_back(std::move(m));
  }
  return g;
}

}  // namespace polydem
