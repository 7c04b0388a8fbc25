#include "studies/collapse_search.hpp"

#include "core/units.hpp"
#include "run/assessment.hpp"
#include "run/equilibrium.hpp"
#include "run/scoped_threads.hpp"
#include "run/setup.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include <fmt/core.h>

#include <cmath>
#include <numbers>

namespace polydem {

namespace {

Vec3 horizontal_direction(double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  return Vec3(std::cos(a), std::sin(a), 0.0).normalized();  // as the deck reader stores a direction
}

// What a static solve that finds no equilibrium reports of the block that
// sets the unbalanced-force ratio under `load` (run/equilibrium.hpp).
std::string largest_unbalance_text(const Simulation& sim, const Vec3& load) {
  const Unbalance u = largest_unbalance(sim, load);
  if (u.block < 0) return "no free block";
  const Blocks& b = sim.blocks();
  const int w = u.block;
  return fmt::format("block '{}' ({:.3g} kg): unbalanced {} {:.3g} N, speed {:.3g} m/s, spin {:.3g} rad/s, "
                     "displaced {:.3g} m",
                     b.props.name[w], b.props.mass[w], u.moment ? "moment/radius" : "force", u.value,
                     b.state.velocity[w].norm(), b.state.angular_velocity[w].norm(),
                     (b.state.position[w] - b.initial_position[w]).norm());
}

// A static solve that found no equilibrium: is a mechanism under way? The
// fastest free block (speed plus spin times radius) moving faster than
// `speed` and displaced more than `distance` says so (a wall going over
// slowly under local damping); a block turning or rattling in place, with
// nothing moving away, does not (`what` gets that block's description).
bool mechanism_moving(const Simulation& sim, double speed, double distance, std::string& what) {
  const Blocks& b = sim.blocks();
  double fastest = -1;
  int w = -1;
  for (int i : b.free_blocks) {
    const double v = b.state.velocity[i].norm() + b.state.angular_velocity[i].norm() * b.props.radius[i];
    if (v > fastest) {
      fastest = v;
      w = i;
    }
  }
  if (w < 0) return false;
  const double moved = (b.state.position[w] - b.initial_position[w]).norm();
  what = fmt::format("the fastest block '{}' moves at {:.3g} m/s (speed plus spin times radius) and has moved "
                     "{:.3g} m",
                     b.props.name[w], fastest, moved);
  return fastest > speed && moved > distance;
}

// What every trial turns off: histories, the ledger; it stops at collapse.
void trial_output(SceneSpec& s) {
  s.assessment.stop_on_collapse = true;
  s.output.energies = false;
  s.output.histories.clear();
}

CollapseTrial run_trial(const SceneSpec& s, double deg, double a_g, const CollapseSearchOptions& o) {
  RunControl c;
  c.threads = o.threads;
  const RunReport r = run_scene(s, c);
  CollapseTrial t;
  t.direction_deg = deg;
  t.acceleration_g = a_g;
  // Under a held or rising acceleration nothing pulls a mechanism back: a
  // trial that ends still moving with the collapse fraction away from its
  // place (undetermined for a run in general) has collapsed.
  t.collapsed = r.assessment.status == "collapsed" ||
                (r.assessment.status == "undetermined" &&
                 r.assessment.dislodged_mass > 0 &&
                 r.assessment.dislodged_mass_fraction >= s.assessment.collapse_mass_fraction);
  t.steps = r.steps;
  t.wall_seconds = r.wall_seconds;
  t.assessment = r.assessment;
  return t;
}

}  // namespace

SceneSpec constant_acceleration_scene(SceneSpec s, double deg, double a_g, double rise_time, double hold_time) {
  s.ground_motion.kind = GroundMotionKind::constant;
  s.ground_motion.acceleration = a_g * kGravity;
  s.ground_motion.rise_time = rise_time;
  s.ground_motion.direction = horizontal_direction(deg);
  s.simulation.end_time = rise_time + hold_time;
  trial_output(s);
  return s;
}

SceneSpec ramp_scene(SceneSpec s, double deg, double rate_g, double a_max_g) {
  s.ground_motion.kind = GroundMotionKind::ramp;
  s.ground_motion.rate = rate_g * kGravity;
  s.ground_motion.direction = horizontal_direction(deg);
  s.simulation.end_time = a_max_g / rate_g;
  s.simulation.settle_velocity = 0;  // a slow ramp starts at rest: it must not stop as "settled"
  trial_output(s);
  return s;
}

namespace {

// Bisection on a_g with `run` deciding each trial.
template <class Run>
BisectionResult bisect(const CollapseSearchOptions& o, const char* method, const TrialObserver& observe, Run run) {
  BisectionResult b;
  auto trial = [&](double a_g) {
    CollapseTrial t = run(a_g);
    ++b.runs;
    b.wall_seconds += t.wall_seconds;
    if (observe) observe(method, t);
    if (t.no_equilibrium && !t.collapsed && b.error.empty())
      b.error = fmt::format("the static solve at {} g found no equilibrium in --static-max-steps = {} steps of an "
                            "increment and no collapse ({}); not counted either way: raise --static-max-steps{}",
                            a_g, o.static_max_steps, t.no_equilibrium_detail,
                            o.density_scaling ? ", or solve without --density-scaling" : "");
    return t;
  };
  CollapseTrial lo = trial(o.low_g);
  if (!b.error.empty()) return b;
  CollapseTrial hi = trial(o.high_g);
  if (!b.error.empty()) return b;
  if (lo.collapsed || !hi.collapsed) {
    b.error = fmt::format("the bracket [{}, {}] g does not contain the collapse acceleration "
                          "(collapsed at low: {}, at high: {})",
                          o.low_g, o.high_g, lo.collapsed, hi.collapsed);
    return b;
  }
  b.last_collapse = hi;
  while (hi.acceleration_g - lo.acceleration_g > o.tolerance_g) {
    CollapseTrial mid = trial(0.5 * (lo.acceleration_g + hi.acceleration_g));
    if (!b.error.empty()) {  // the bracket so far stays in the result
      b.low_g = lo.acceleration_g;
      b.high_g = hi.acceleration_g;
      return b;
    }
    if (mid.collapsed) {
      hi = mid;
      b.last_collapse = mid;
    } else {
      lo = mid;
    }
  }
  b.low_g = lo.acceleration_g;
  b.high_g = hi.acceleration_g;
  b.collapse_g = 0.5 * (lo.acceleration_g + hi.acceleration_g);
  return b;
}

}  // namespace

BisectionResult bisect_collapse(const SceneSpec& scene, double deg, const CollapseSearchOptions& o,
                                const TrialObserver& observe) {
  return bisect(o, "constant", observe, [&](double a_g) {
    return run_trial(constant_acceleration_scene(scene, deg, a_g, o.rise_time, o.hold_time), deg, a_g, o);
  });
}

CollapseTrial static_collapse_trial(const SceneSpec& scene, double deg, double a_g, const CollapseSearchOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  SceneSpec s = scene;
  s.ground_motion = GroundMotionSpec{};  // none: the load is the tilted gravity
  s.simulation.gravity_rise_time = 0;
  trial_output(s);
  const ScopedThreads threads(run_threads(o.threads, s));  // as a run: the option, else the deck's
  RunSetup setup;
  std::unique_ptr<Simulation> sim = build_simulation(s, setup);
  const Vec3 g = s.simulation.gravity;
  const Vec3 d = horizontal_direction(deg);

  CollapseTrial t;
  t.direction_deg = deg;
  t.acceleration_g = a_g;
  // Collapse as a run judges it: the fallen mass fraction
  // (assessment.collapse_mass_fraction), sampled every 16th step, stops the
  // trial; the blocks dislodged at the end of it count too.
  AssessmentMonitor monitor(s.assessment, *sim, g, s.simulation.overlap_tolerance);
  for (int k = 1; k <= o.static_increments && !t.collapsed && !t.no_equilibrium; ++k) {
    // A ground acceleration +a d pushes the blocks by −m a d.
    const Vec3 load = g - (a_g * k / o.static_increments) * g.norm() * d;
    sim->begin_static_stage(o.local_damping, load, o.density_scaling);
    for (long n = 0;; ++n) {
      sim->step();
      ++t.steps;
      monitor.observe(*sim);
      if (monitor.collapsed()) {
        t.collapsed = true;
        break;
      }
      if (n % 16 != 15) continue;
      if (unbalanced_force_ratio(*sim, load) <= o.static_ratio) break;
      if (n >= o.static_max_steps) {
        t.no_equilibrium = true;
        std::string fastest;
        t.collapsed = mechanism_moving(*sim, s.simulation.settle_velocity > 0 ? s.simulation.settle_velocity : 1e-3,
                                       s.assessment.damage_displacement, fastest);
        t.no_equilibrium_detail = largest_unbalance_text(*sim, load) + "; " + fastest +
                                  (t.collapsed ? ": a mechanism under way, counted as collapse" : "");
        break;
      }
    }
  }
  t.assessment = monitor.finish(*sim);
  if (t.assessment.status == "collapsed") t.collapsed = true;
  if (t.no_equilibrium) t.assessment.status = t.collapsed ? "collapsed" : "no_equilibrium";
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

BisectionResult bisect_collapse_static(const SceneSpec& scene, double deg, const CollapseSearchOptions& o,
                                       const TrialObserver& observe) {
  return bisect(o, "static", observe, [&](double a_g) { return static_collapse_trial(scene, deg, a_g, o); });
}

CollapseTrial ramp_collapse(const SceneSpec& scene, double deg, const CollapseSearchOptions& o,
                            const TrialObserver& observe) {
  const SceneSpec s = ramp_scene(scene, deg, o.ramp_rate_g, 1.2 * o.high_g);
  CollapseTrial t = run_trial(s, deg, NAN, o);
  t.acceleration_g = t.assessment.damage_time >= 0 ? t.assessment.ground_acceleration_at_damage / kGravity : NAN;
  if (observe) observe("ramp", t);
  return t;
}

}  // namespace polydem
