// Stiff and extreme cases (issue 5), shared by extreme_cases_test.cpp (short
// end times: the default suite) and extreme_cases_slow_test.cpp (the full
// sweep, `slow` label). Each scene is a deck generated as text; each case must
// either stay stable or stop with the guard's message naming the cause and
// the step. "Stable" is judged by
//   - the energy ledger: energy_balance_error below the case's tolerance,
//   - every final position finite,
//   - no block sunk into the base (top face z = 0) by more than 1 % of its
//     own size (cube root of volume), measured at its lowest final corner,
//   - and the case's own check (order and heights of a stack, the rebound of
//     an impact, the exact sliding distance without friction, ...).
// Each run prints one row of the table in README.md / docs/robustness.md.
#pragma once

#include "run/run_scene.hpp"
#include "core/blocks.hpp"
#include "integrators/critical_time_step.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace polydem::extreme {

constexpr double kG = 9.81;

// --- deck text ---------------------------------------------------------------

struct Header {
  double end_time = 0.1;
  double normal_stiffness = 98e9;
  double friction_angle = 30;
  double damping = 2.1e-5;
  Vec3 gravity{0, 0, -kG};
  std::string ground_motion;  // body of a [ground_motion] section, or empty
};

inline std::string header(const Header& h) {
  std::ostringstream d;
  d.precision(17);
  d << "[simulation]\nend_time = " << h.end_time << "\ngravity = [" << h.gravity.x() << ", " << h.gravity.y() << ", "
    << h.gravity.z() << "]\n[joint]\nnormal_stiffness = " << h.normal_stiffness
    << "\nfriction_angle = " << h.friction_angle << "\ndamping = " << h.damping << "\n"
    << "[output]\nhistory_interval = " << h.end_time / 400 << "\n";
  if (!h.ground_motion.empty()) d << "[ground_motion]\n" << h.ground_motion;
  return d.str();
}

inline std::string box(const std::string& name, Vec3 size, Vec3 center, double density = 2600,
                       const std::string& extra = "") {
  std::ostringstream d;
  d.precision(17);
  d << "[[block]]\nname = \"" << name << "\"\nshape = \"box\"\nsize = [" << size.x() << ", " << size.y() << ", "
    << size.z() << "]\ncenter = [" << center.x() << ", " << center.y() << ", " << center.z()
    << "]\ndensity = " << density << "\n"
    << extra;
  return d.str();
}

// A fixed base whose top face is z = 0.
inline std::string base(double width, double thickness = 0.5) {
  return box("base", {width, width, thickness}, {0, 0, -thickness / 2}, 2600, "motion = \"fixed\"\n");
}

inline std::string numbered(const char* prefix, int k) {
  std::ostringstream o;
  o << prefix << k;
  return o.str();
}

// --- cases -------------------------------------------------------------------

struct Final {
  const RunReport& report;
  Blocks blocks;  // the scene's blocks moved to the final (or last good) state
  Vec3 displacement(const std::string& name) const {
    const int i = blocks.find(name);
    return blocks.state.position[i] - blocks.initial_position[i];
  }
  Vec3 position(const std::string& name) const { return blocks.state.position[blocks.find(name)]; }
  double lowest_z(int i) const {
    double z = 1e300;
    for (std::size_t v = 0; v < blocks.props.local_shape[i].vertices.size(); ++v)
      z = std::min(z, world_vertex(blocks, i, static_cast<int>(v)).z());
    return z;
  }
};

struct Case {
  std::string name;
  std::string deck;
  // Tolerance on RunReport::energy_balance_error (max |balance − balance(0)|
  // over the recorded samples / the largest energy in play).
  double energy_tolerance = 0.01;
  // The guard must not stop this case (its physics is benign and the
  // automatic time step must cope); false: a clear stop is also accepted.
  bool must_stay_stable = true;
  std::function<void(const Final&)> check;  // the case's own assertions (stable runs)
};

inline Case named(const std::string& name, const std::string& deck) {
  Case c;
  c.name = name;
  c.deck = deck;
  return c;
}

inline std::string short_cause(const RunReport& r) {
  if (!r.unstable) return "stable";
  const std::string& m = r.instability;
  const auto a = m.find("): "), b = m.find(';');
  const auto s = m.find("step ");
  std::ostringstream o;
  o << "stopped at step ";
  if (s != std::string::npos) o << m.substr(s + 5, m.find(' ', s + 5) - s - 5);
  o << ": " << (a == std::string::npos ? m : m.substr(a + 3, b - a - 3));
  return o.str();
}

inline void print_row(const Case& c, const RunReport& r, const std::string& outcome) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "| %s | %.3g | %.3g | %d | %ld | %.2f | %.2g | %s |", c.name.c_str(),
                r.initial_time_step, r.time_step, r.time_step_reductions, r.steps, r.wall_seconds,
                r.energy_balance_error, outcome.c_str());
  std::cout << "EXTREME_ROW " << buf << std::endl;
}

inline void run_case(const Case& c) {
  SCOPED_TRACE(c.name);
  const SceneSpec spec = parse_deck(c.deck, "extreme_" + c.name + ".toml");
  RunControl control;
  control.threads = 1;  // small scenes: one thread is faster and steadier
  RunReport r;
  try {
    r = run_scene(spec, control);
  } catch (const std::exception& e) {
    // Only InstabilityError may stop a run, and run_scene turns it into
    // RunReport::unstable: anything escaping is an engine bug.
    print_row(c, r, std::string("EXCEPTION: ") + e.what());
    FAIL() << "BUG: run_scene threw instead of stopping cleanly: " << e.what();
  }
  Final f{r, build_blocks(spec.blocks)};
  for (int i = 0; i < f.blocks.count; ++i) {
    f.blocks.state.position[i] = r.final_position[i];
    f.blocks.state.orientation[i] = r.final_orientation[i];
    f.blocks.state.rotation[i] = r.final_orientation[i].toRotationMatrix();
  }

  std::ostringstream outcome;
  if (r.unstable) {
    outcome << short_cause(r);
    // The stop names the step and one of the guard's three causes.
    EXPECT_NE(r.instability.find("at step "), std::string::npos) << r.instability;
    EXPECT_TRUE(r.instability.find("non-finite") != std::string::npos ||
                r.instability.find("overlap") != std::string::npos ||
                r.instability.find("energy grew") != std::string::npos)
        << r.instability;
    EXPECT_FALSE(c.must_stay_stable) << "the guard stopped a case that must stay stable: " << r.instability;
  }
  // The final (or last good) state is finite and nothing sank into the base,
  // unstable or not: the guard keeps the last state that passed its check.
  double worst_sink = 0;  // fraction of the block's size
  for (int i : f.blocks.free_blocks) {
    ASSERT_TRUE(r.final_position[i].allFinite() && r.final_velocity[i].allFinite())
        << "BUG: non-finite state of " << f.blocks.props.name[i] << " without a stop";
    const double sink = -f.lowest_z(i) / f.blocks.props.size[i];
    worst_sink = std::max(worst_sink, sink);
    EXPECT_LT(sink, 0.01) << f.blocks.props.name[i] << " sank " << -f.lowest_z(i) << " m below the base's top";
  }
  if (!r.unstable) {
    ASSERT_TRUE(std::isfinite(r.energy.balance) && std::isfinite(r.energy_balance_error));
    EXPECT_LT(r.energy_balance_error, c.energy_tolerance);
    outcome << "stable";
    if (c.check) c.check(f);
  }
  if (testing::Test::HasFailure()) outcome << " (FAILED)";
  print_row(c, r, outcome.str());
}

// The static settlement of a column of identical boxes (height h, density
// rho) on a rigid base: joint j (from the bottom) carries the weight of the
// n − j blocks above it, so block k sinks Σ_{j≤k} (n − j) ρ g h / kn.
inline double stack_settlement(int n, int k, double rho, double h, double kn) {
  double s = 0;
  for (int j = 0; j <= k; ++j) s += (n - j) * rho * kG * h / kn;
  return s;
}

// Every block of a stack keeps its order, sits within `vertical` of its
// initial height and drifts less than `horizontal` sideways.
inline void expect_stack_intact(const Final& f, const std::vector<std::string>& names,
                                const std::function<double(int)>& vertical, double horizontal) {
  double prev = -1e300;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Vec3 d = f.displacement(names[k]);
    EXPECT_LT(std::abs(d.z()), vertical(static_cast<int>(k))) << names[k];
    EXPECT_LT(std::hypot(d.x(), d.y()), horizontal) << names[k];
    const double z = f.position(names[k]).z();
    EXPECT_GT(z, prev) << names[k] << " is no longer above the block under it";
    prev = z;
  }
}

// 1. Joint stiffness kn: a 1 x 1 x 0.5 m block resting on the base and a
// stack of three 0.6 x 0.6 x 0.3 m blocks. Tolerances: vertically 2.5 x the
// static settlement + 1 um (a load applied at once overshoots to at most
// twice the static value; the half is margin), sideways 10 um (nothing pushes
// sideways; as in the verification decks).
inline Case stiffness_case(double kn, double end_time) {
  Header h;
  h.end_time = end_time;
  h.normal_stiffness = kn;
  std::string deck = header(h) + base(4) + box("single", {1, 1, 0.5}, {-1, 0, 0.25});
  for (int k = 0; k < 3; ++k) deck += box(numbered("s", k + 1), {0.6, 0.6, 0.3}, {1, 0, 0.15 + 0.3 * k});
  char name[64];
  std::snprintf(name, sizeof name, "kn = %.0e Pa/m", kn);
  Case c = named(name, deck);
  c.check = [kn](const Final& f) {
    expect_stack_intact(f, {"single"}, [&](int) { return 2.5 * stack_settlement(1, 0, 2600, 0.5, kn) + 1e-6; }, 1e-5);
    expect_stack_intact(
        f, {"s1", "s2", "s3"}, [&](int k) { return 2.5 * stack_settlement(3, k, 2600, 0.3, kn) + 1e-6; }, 1e-5);
  };
  return c;
}

// 2. Sizes 1 cm to 10 m and densities 100 to 20 000 kg/m3 in one scene: a
// 10 x 10 x 1 m slab on a 20 m base, on it a 1 cm cube of 20 000 kg/m3 and a
// 1 m cube of 100 kg/m3. The contact margin (2 % of the smallest block) is
// 0.2 mm. Each block must stay within 1 % of its own size of where it was
// (0.1 mm for the cube: the static settlements are below 1e-6 m).
inline Case size_density_case(double end_time) {
  Header h;
  h.end_time = end_time;
  const std::string deck = header(h) + base(20, 1) + box("slab", {10, 10, 1}, {0, 0, 0.5}) +
                           box("tiny_dense", {0.01, 0.01, 0.01}, {2, 2, 1.005}, 20000) +
                           box("big_light", {1, 1, 1}, {-2, -2, 1.5}, 100);
  Case c = named("1 cm / 20000 kg/m3 and 1 m / 100 kg/m3 on a 10 m slab", deck);
  c.check = [](const Final& f) {
    EXPECT_LT(f.displacement("slab").norm(), 0.01 * 10);
    EXPECT_LT(f.displacement("tiny_dense").norm(), 0.01 * 0.01);
    EXPECT_LT(f.displacement("big_light").norm(), 0.01 * 1);
    EXPECT_GT(f.position("tiny_dense").z(), f.position("slab").z());
    EXPECT_GT(f.position("big_light").z(), f.position("slab").z());
  };
  return c;
}

inline std::string sine_pulse(double acceleration_g, double period) {
  std::ostringstream d;
  d << "kind = \"sine_pulse\"\nacceleration_g = " << acceleration_g << "\nperiod = " << period
    << "\ndirection = [1, 0, 0]\n";
  return d.str();
}

// 3. A 10 g one-sine pulse (T = 0.2 s) on a stack of three 1 x 1 x 0.5 m
// blocks, friction 30 deg: the stack slides, rocks and topples. Stability
// only (the generic checks); the blocks must also stay on the 20 m base.
inline Case pulse_stack_case(double end_time) {
  Header h;
  h.end_time = end_time;
  h.ground_motion = sine_pulse(10, 0.2);
  std::string deck = header(h) + base(20);
  for (int k = 0; k < 3; ++k) deck += box(numbered("s", k + 1), {1, 1, 0.5}, {0, 0, 0.25 + 0.5 * k});
  Case c = named("10 g sine pulse, stack of 3, phi = 30", deck);
  c.energy_tolerance = 0.02;
  c.check = [](const Final& f) {
    for (const char* n : {"s1", "s2", "s3"}) EXPECT_LT(f.position(n).head<2>().norm(), 9.0) << n << " left the base";
  };
  return c;
}

// 4a. Zero friction under the 10 g pulse: the block slides on the base by
// exactly −a·T²/(2π) in the base's frame and ends at rest (the one-sine
// pulse's ground displacement). 1 % on the distance, 1 % of the peak
// relative velocity a·T/π on the final velocity.
inline Case pulse_frictionless_case(double end_time) {
  Header h;
  h.end_time = end_time;
  h.friction_angle = 0;
  h.ground_motion = sine_pulse(10, 0.2);
  const std::string deck = header(h) + base(20) + box("stone", {1, 1, 0.5}, {0, 0, 0.25});
  Case c = named("10 g sine pulse, phi = 0 (slides)", deck);
  c.check = [](const Final& f) {
    const double a = 10 * kG, T = 0.2, pi = std::acos(-1.0);
    const double expected = -a * T * T / (2 * pi);
    EXPECT_NEAR(f.displacement("stone").x(), expected, 0.01 * std::abs(expected));
    EXPECT_LT(std::abs(f.report.final_velocity[f.blocks.find("stone")].x()), 0.01 * a * T / pi);
  };
  return c;
}

// 4b. phi = 89 deg under the 10 g pulse: no sliding, the 1 x 1 x 0.5 m block
// (b/h = 2 < 10) rocks and overturns. Stability only.
inline Case pulse_high_friction_case(double end_time) {
  Header h;
  h.end_time = end_time;
  h.friction_angle = 89;
  h.ground_motion = sine_pulse(10, 0.2);
  const std::string deck = header(h) + base(20) + box("stone", {1, 1, 0.5}, {0, 0, 0.25});
  Case c = named("10 g sine pulse, phi = 89 (rocks)", deck);
  // It overturns and lands: the numerical line is 1.7 % of the energy put
  // in over 1 s, from impacts that close and open a joint within a step or
  // two (docs/robustness.md).
  c.energy_tolerance = 0.03;
  c.check = [](const Final& f) { EXPECT_LT(f.position("stone").head<2>().norm(), 9.0); };
  return c;
}

inline Vec3 tilted_gravity(double slope_deg) {
  const double t = slope_deg * std::acos(-1.0) / 180;
  return {kG * std::sin(t), 0, -kG * std::cos(t)};
}

// 4c. phi = 0 on a 30 deg slope (gravity tilted, as slope_slide.toml): the
// block slides with a = g sin 30 exactly; x = a t²/2 within 0.1 %.
inline Case slope_frictionless_case(double end_time) {
  Header h;
  h.end_time = end_time;
  h.friction_angle = 0;
  h.gravity = tilted_gravity(30);
  const std::string deck = header(h) + base(20) + box("stone", {1, 1, 0.5}, {0, 0, 0.25});
  Case c = named("30 deg slope, phi = 0 (slides)", deck);
  c.check = [end_time](const Final& f) {
    const double expected = 0.5 * kG * 0.5 * end_time * end_time;
    EXPECT_NEAR(f.displacement("stone").x(), expected, 1e-3 * expected);
  };
  return c;
}

// 4d. phi = 89 deg on a 70 deg slope: tan 70 = 2.7 < tan 89 = 57, and the
// 1 x 1 x 0.25 m block does not tip (b/h = 4 > tan 70): it sticks. Drift
// 10 um (the elastic shear of the joint is 0.15 um).
inline Case slope_high_friction_case(double end_time) {
  Header h;
  h.end_time = end_time;
  h.friction_angle = 89;
  h.gravity = tilted_gravity(70);
  const std::string deck = header(h) + base(4) + box("stone", {1, 1, 0.25}, {0, 0, 0.125});
  Case c = named("70 deg slope, phi = 89 (sticks)", deck);
  // The energy put in is only the joint's elastic settling under the tilted
  // weight (millijoules), which rings at the highest frequency (w dt ~ 1.6);
  // the numerical line is 0.014 % of it (the default tolerance, 1 %).
  c.check = [](const Final& f) { EXPECT_LT(f.displacement("stone").norm(), 1e-5); };
  return c;
}

// 5. A 1 x 1 x 0.5 m block dropped at 10 m/s from 5 cm above the base. It
// must end above the base (generic check) with no more mechanical energy
// (kinetic + gravitational + strain) than it started with (energy from
// nowhere), and bounce as its joint's damping ratio says: at 98 GPa/m the
// contact mode has xi ~ 0.09 (restitution ~0.75): it must leave upwards at
// 5-10 m/s; at 1e13-1e14 Pa/m xi = beta*w/2 ~ 1-3, the impact is overdamped
// and the block must not rebound faster than 1 m/s.
// The ledger's damping term books the dashpot's work at the centred
// velocity (contact/joint_law.hpp) and its kinetic term is the leapfrog's
// own (integrators/energy_ledger.hpp), so the numerical line is small on
// the overdamped impact (tolerance 1 % at 1e14 Pa/m); at 98 GPa/m it is the
// stiff elastic impact itself at w*dt = 0.46 (tolerance 4 %).
inline Case impact_case(double kn, double end_time) {
  Header h;
  h.end_time = end_time;
  h.normal_stiffness = kn;
  const std::string deck =
      header(h) + base(4) + box("stone", {1, 1, 0.5}, {0, 0, 0.3}, 2600, "velocity = [0, 0, -10]\n");
  char name[64];
  std::snprintf(name, sizeof name, "10 m/s impact, kn = %.2g", kn);
  Case c = named(name, deck);
  c.energy_tolerance = kn < 1e12 ? 0.04 : 0.01;
  c.check = [kn](const Final& f) {
    const auto& e = f.report.energy;
    const double initial = 0.5 * 1300 * 100;  // m = 2600 kg/m3 x 0.5 m3
    EXPECT_LT(e.kinetic + e.gravitational + e.strain, 1.001 * initial);
    const double vz = f.report.final_velocity[f.blocks.find("stone")].z();
    if (kn < 1e12) {
      EXPECT_GT(vz, 5.0) << "did not bounce as an underdamped joint";
      EXPECT_LT(vz, 10.0) << "rebounds faster than it hit";
    } else {
      EXPECT_LT(std::abs(vz), 1.0) << "rebounds from an overdamped joint";
    }
    EXPECT_LT(f.displacement("stone").head<2>().norm(), 1e-5);
  };
  return c;
}

// 6a. Slivers (aspect 100:1): five 1 x 1 x 0.01 m plates stacked. Order
// kept, heights within 2.5 x the static settlement + 1 um, 10 um sideways.
inline Case plates_case(double end_time) {
  Header h;
  h.end_time = end_time;
  std::string deck = header(h) + base(2);
  std::vector<std::string> names;
  for (int k = 0; k < 5; ++k) {
    names.push_back(numbered("plate", k + 1));
    deck += box(names.back(), {1, 1, 0.01}, {0, 0, 0.005 + 0.01 * k});
  }
  Case c = named("5 plates 1 x 1 x 0.01 m stacked", deck);
  c.check = [names](const Final& f) {
    expect_stack_intact(f, names, [](int k) { return 2.5 * stack_settlement(5, k, 2600, 0.01, 98e9) + 1e-6; }, 1e-5);
  };
  return c;
}

// 6b. A 0.01 x 0.01 x 1 m rod standing on its end. It is an equilibrium (a
// perfectly centred load); nothing pushes it over, so it must still stand:
// top corner within 1 mm of where it was.
inline Case rod_case(double end_time) {
  Header h;
  h.end_time = end_time;
  const std::string deck = header(h) + base(4) + box("rod", {0.01, 0.01, 1}, {0, 0, 0.5});
  Case c = named("rod 0.01 x 0.01 x 1 m standing", deck);
  c.check = [](const Final& f) {
    EXPECT_LT(f.displacement("rod").norm(), 1e-3);
    EXPECT_LT(f.report.final_orientation[f.blocks.find("rod")].angularDistance(
                  f.blocks.initial_orientation[f.blocks.find("rod")]),
              1e-3);  // rad: tilt of 1 mm at the top
  };
  return c;
}

// 7. A column of 50 blocks 0.4 x 0.4 x 0.2 m (10 m tall). Order kept,
// heights within 2.5 x the static settlement + 1 um, 0.1 mm sideways.
inline Case column_case(double end_time) {
  Header h;
  h.end_time = end_time;
  std::string deck = header(h) + base(2);
  std::vector<std::string> names;
  for (int k = 0; k < 50; ++k) {
    names.push_back(numbered("c", k + 1));
    deck += box(names.back(), {0.4, 0.4, 0.2}, {0, 0, 0.1 + 0.2 * k});
  }
  Case c = named("column of 50 blocks", deck);
  c.check = [names](const Final& f) {
    expect_stack_intact(f, names, [](int k) { return 2.5 * stack_settlement(50, k, 2600, 0.2, 98e9) + 1e-6; }, 1e-4);
  };
  return c;
}

// 8. Stiffness-proportional damping beta = 1e-3 s with kn = 1e11 Pa/m: the
// damping ratio at the highest frequency is ~10, so the stable step shrinks
// about 20 x (dt = (2/w)(sqrt(1 + xi^2) − xi)). The block-and-stack scene of
// case 1; the initial step must be below that of the same scene with the
// default damping.
inline Case damping_case(double end_time) {
  Case c = stiffness_case(1e11, end_time);
  Header h;
  h.end_time = end_time;
  h.normal_stiffness = 1e11;
  h.damping = 1e-3;
  std::string deck = header(h) + base(4) + box("single", {1, 1, 0.5}, {-1, 0, 0.25});
  for (int k = 0; k < 3; ++k) deck += box(numbered("s", k + 1), {0.6, 0.6, 0.3}, {1, 0, 0.15 + 0.3 * k});
  c.name = "damping 1e-3 s, kn = 1e11";
  c.deck = deck;
  const auto resting = c.check;
  c.check = [resting, deck](const Final& f) {
    resting(f);
    // The same scene with the default damping allows a step over 5 x larger.
    const SceneSpec spec = parse_deck(deck, "damping.toml");
    JointSpec light = spec.joint;
    light.damping = 2.1e-5;
    const double undamped = critical_time_step(f.blocks, make_joint_law(light), spec.simulation.safety_factor).chosen;
    EXPECT_GT(undamped, 5 * f.report.initial_time_step);
  };
  return c;
}

inline void print_table_header() {
  std::cout << "EXTREME_ROW | case | initial dt (s) | final dt (s) | reductions | steps | wall (s) | energy "
               "balance error | outcome |\nEXTREME_ROW |---|---|---|---|---|---|---|---|"
            << std::endl;
}

}  // namespace polydem::extreme
