#include "analytical/rocking_response.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace polydem::analytical {

const char* to_string(CollapseMode m) {
  switch (m) {
    case CollapseMode::none: return "none";
    case CollapseMode::mode_1: return "mode I";
    case CollapseMode::mode_2: return "mode II";
  }
  return "?";
}

double rocking_angular_acceleration(double p, double alpha, double g, RockingForm form, int side,
                                    double theta, double a_g) {
  const double sa = side * alpha;
  if (form == RockingForm::linearised) return p * p * (theta - sa - a_g / g);  // eq. 9
  return -p * p * (std::sin(sa - theta) + a_g / g * std::cos(sa - theta));     // eq. 7 / I0
}

double rocking_energy_margin(double p, double alpha, RockingForm form, int side, double theta, double omega) {
  const double d = side * alpha - theta;
  if (form == RockingForm::linearised) return 0.5 * omega * omega - 0.5 * p * p * d * d;
  return 0.5 * omega * omega - p * p * (1.0 - std::cos(d));
}

namespace {

struct State {
  double theta, omega;
};

struct Stepper {
  double p, alpha, g;
  RockingForm form;
  const GroundMotion* ground;

  double acc(int side, double t, double theta) const {
    return rocking_angular_acceleration(p, alpha, g, form, side, theta, ground->acceleration(t));
  }
  // One classical RK4 step of length h from (t, y) on pivot side `side`.
  State step(int side, double t, State y, double h) const {
    const double k1t = y.omega, k1w = acc(side, t, y.theta);
    const double k2t = y.omega + 0.5 * h * k1w, k2w = acc(side, t + 0.5 * h, y.theta + 0.5 * h * k1t);
    const double k3t = y.omega + 0.5 * h * k2w, k3w = acc(side, t + 0.5 * h, y.theta + 0.5 * h * k2t);
    const double k4t = y.omega + h * k3w, k4w = acc(side, t + h, y.theta + h * k3t);
    return {y.theta + h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t),
            y.omega + h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w)};
  }
};

// Root of f on [lo, hi] with f(lo) > 0 > f(hi) (Illinois false position,
// which keeps a bracket and converges superlinearly).
template <class F>
double locate(F&& f, double lo, double flo, double hi, double fhi) {
  const double tol = 1e-15 * (1.0 + std::abs(hi));
  int keep = 0;
  for (int it = 0; it < 200 && hi - lo > tol; ++it) {
    double x = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if (fx > 0.0) {
      lo = x; flo = fx;
      if (keep == -1) fhi *= 0.5;
      keep = -1;
    } else {
      hi = x; fhi = fx;
      if (keep == 1) flo *= 0.5;
      keep = 1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

RockingResult simulate_rocking(const RockingBody& body, const GroundMotion& ground, const RockingOptions& o) {
  if (!(o.dt > 0.0) || !(o.t_end > 0.0) || !(o.g > 0.0) || !ground.acceleration)
    throw std::invalid_argument("simulate_rocking: need dt, t_end, g > 0 and a ground motion");
  if (!(body.p > 0.0) || !(body.alpha > 0.0)) throw std::invalid_argument("simulate_rocking: body needs p > 0 and alpha > 0");
  const double c = o.restitution.value_or(body.restitution);
  if (!(c >= 0.0) || !(c <= 1.0)) throw std::invalid_argument("simulate_rocking: restitution must be in [0, 1]");
  if (std::abs(o.theta0) >= body.alpha) throw std::invalid_argument("simulate_rocking: |theta0| must be < alpha");

  const Stepper st{body.p, body.alpha, o.g, o.form, &ground};
  const double threshold = o.g * std::tan(body.alpha);  // rocking onset |a_g| > g tan α
  RockingResult r;
  double t = 0.0;
  State y{o.theta0, o.omega0};
  int side = 0;  // 0: at rest on the base
  if (o.theta0 != 0.0) side = o.theta0 > 0.0 ? 1 : -1;
  else if (o.omega0 != 0.0) side = o.omega0 > 0.0 ? 1 : -1;
  if (side != 0) { r.uplifted = true; r.t_uplift = 0.0; }
  double past_alpha_time = -1.0;  // OverturnRule::no_return: the last passage over α
  CollapseMode past_alpha_mode = CollapseMode::none;

  auto record = [&] {
    if (o.record_history) r.history.push_back({t, y.theta, y.omega, ground.acceleration(t)});
  };
  record();

  while (t < o.t_end) {
    double h = std::min(o.dt, o.t_end - t);
    double t_hit = -1.0;
    if (ground.next_breakpoint) {
      // End the step on the next kink of a_g; skip one closer than rounding.
      double bp = ground.next_breakpoint(t);
      if (bp - t <= 1e-12 * (1.0 + std::abs(t))) bp = ground.next_breakpoint(bp);
      if (bp - t < h) {
        h = bp - t;
        t_hit = bp;  // land on it exactly, not on t + (bp − t)
      }
    }
    const double t_next = t_hit >= 0.0 ? t_hit : t + h;
    if (side == 0) {
      if (t >= ground.quiet_after && o.stop_when_safe) break;
      const double a0 = ground.acceleration(t);
      if (std::abs(a0) > threshold) {  // uplift now
        side = a0 > 0.0 ? -1 : 1;
        if (!r.uplifted) { r.uplifted = true; r.t_uplift = t; }
        continue;
      }
      const double a1 = ground.acceleration(t + h);
      if (std::abs(a1) > threshold) {
        // Onset inside the step: bisect |a_g| − g tan α (a_g need not be smooth).
        double lo = t, hi = t + h;
        for (int it = 0; it < 200 && hi - lo > 1e-15 * (1.0 + hi); ++it) {
          const double m = 0.5 * (lo + hi);
          if (std::abs(ground.acceleration(m)) > threshold) hi = m; else lo = m;
        }
        t = hi;
      } else {
        t = t_next;
      }
      ++r.steps;
      record();
      continue;
    }

    const State y1 = st.step(side, t, y, h);
    ++r.steps;
    if (o.overturn == OverturnRule::no_return) {
      if (side * y.theta <= body.alpha && side * y1.theta > body.alpha) {  // over α: note when, and the mode
        past_alpha_time = t + h;
        past_alpha_mode = r.impacts > 0 ? CollapseMode::mode_1 : CollapseMode::mode_2;
      }
      const bool still = t + h >= ground.quiet_after;
      const bool beyond = side * y1.theta > body.alpha;
      const bool no_way_back =
          side * y1.omega >= 0.0 || rocking_energy_margin(body.p, body.alpha, o.form, side, y1.theta, y1.omega) <= 0.0;
      if (beyond && (side * y1.theta >= 0.5 * std::numbers::pi || (still && no_way_back))) {
        y = y1;
        t = t_next;
        r.overturned = true;
        r.t_overturn = past_alpha_time;
        r.mode = past_alpha_mode;
        r.max_abs_theta = std::max(r.max_abs_theta, std::abs(y.theta));
        record();
        break;
      }
    } else if (side * y1.theta > body.alpha) {  // overturning inside this step
      auto f = [&](double tau) { return body.alpha - side * st.step(side, t, y, tau).theta; };
      const double tau = locate(f, 0.0, body.alpha - side * y.theta, h, body.alpha - side * y1.theta);
      y = st.step(side, t, y, tau);
      t += tau;
      r.overturned = true;
      r.t_overturn = t;
      r.mode = r.impacts > 0 ? CollapseMode::mode_1 : CollapseMode::mode_2;
      r.max_abs_theta = std::max(r.max_abs_theta, std::abs(y.theta));
      record();
      break;
    }
    if (side * y1.theta < 0.0) {  // impact inside this step
      auto f = [&](double tau) { return side * st.step(side, t, y, tau).theta; };
      double lo = 0.0, flo = side * y.theta;
      if (!(flo > 0.0)) {
        // The step starts on the base (just lifted or just bounced): find a
        // point where the body is up, else it never really left the base.
        for (double tau = 0.5 * h; tau > 1e-12 * h; tau *= 0.5) {
          const double v = f(tau);
          if (v > 0.0) { lo = tau; flo = v; break; }
        }
      }
      if (!(flo > 0.0)) {  // stays on the base this step
        y = {0.0, 0.0};
        side = 0;
        t = t_next;
        record();
        continue;
      }
      const double tau = locate(f, lo, flo, h, side * y1.theta);
      const State yi = st.step(side, t, y, tau);
      t += tau;
      y = {0.0, c * yi.omega};
      side = -side;
      ++r.impacts;
      r.impact_times.push_back(t);
      if (std::abs(y.omega) < o.rest_velocity * body.p) {
        y = {0.0, 0.0};
        side = 0;
      }
      record();
      continue;
    }
    y = y1;
    t = t_next;
    r.max_abs_theta = std::max(r.max_abs_theta, std::abs(y.theta));
    record();
    if (o.stop_when_safe && t >= ground.quiet_after &&
        rocking_energy_margin(body.p, body.alpha, o.form, side, y.theta, y.omega) < 0.0)
      break;
  }
  r.t_final = t;
  r.theta_final = y.theta;
  r.omega_final = y.omega;
  return r;
}

}  // namespace polydem::analytical
