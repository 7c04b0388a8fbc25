#include "analytical/free_rocking.hpp"
#include "analytical/rocking_response.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pa = polydem::analytical;

namespace {

const double g = 9.81;
// A block with p = 2 rad/s (R = 3g/16) and α = 0.25 rad.
pa::RockingBody test_block() {
  const double R = 3.0 * g / 16.0;
  return pa::rectangular_block(R * std::sin(0.25), R * std::cos(0.25), 1.0, g);
}

pa::RockingResult free_release(double theta0, double dt, double t_end, double c, pa::RockingForm form,
                               bool history = false) {
  pa::RockingOptions o;
  o.dt = dt;
  o.t_end = t_end;
  o.theta0 = theta0;
  o.restitution = c;
  o.form = form;
  o.stop_when_safe = false;
  o.record_history = history;
  return pa::simulate_rocking(test_block(), pa::constant_ground_motion(0.0), o);
}

}  // namespace

TEST(FreeRocking, QuadratureAgainstLinearisedForSmallAngles) {
  // For θ0, α → 0 the exact time tends to Housner's acosh form.
  const double p = 2.0;
  EXPECT_NEAR(pa::free_rocking_time_to_impact(p, 1e-3, 0.5e-3), pa::free_rocking_time_to_impact_linear(p, 1e-3, 0.5e-3),
              1e-6);
  EXPECT_NEAR(pa::free_rocking_time_to_impact_linear(p, 0.2, 0.1), std::acosh(2.0) / p, 1e-15);
  // The exact fall is slower (sin(α−θ) < α−θ).
  EXPECT_GT(pa::free_rocking_time_to_impact(p, 0.3, 0.2), pa::free_rocking_time_to_impact_linear(p, 0.3, 0.2));
}

TEST(FreeRocking, IntegratorFirstImpactMatchesQuadrature) {
  const auto b = test_block();
  ASSERT_NEAR(b.p, 2.0, 1e-12);
  for (double ratio : {0.2, 0.6, 0.95}) {
    const double th0 = ratio * b.alpha;
    const auto r = free_release(th0, 1e-3, 10.0, 1.0, pa::RockingForm::nonlinear);
    ASSERT_GE(r.impacts, 1);
    const double exact = pa::free_rocking_time_to_impact(b.p, b.alpha, th0);
    EXPECT_NEAR(r.impact_times[0], exact, 1e-10 * exact) << "theta0/alpha = " << ratio;
    const auto rl = free_release(th0, 1e-3, 10.0, 1.0, pa::RockingForm::linearised);
    const double lin = pa::free_rocking_time_to_impact_linear(b.p, b.alpha, th0);
    EXPECT_NEAR(rl.impact_times[0], lin, 1e-10 * lin);
  }
}

TEST(FreeRocking, RestitutionScalesTheImpactVelocity) {
  const auto b = test_block();
  const double th0 = 0.5 * b.alpha, c = 0.8;
  pa::RockingOptions o;
  o.dt = 1e-3;
  o.theta0 = th0;
  o.restitution = c;
  o.record_history = true;
  o.t_end = pa::free_rocking_time_to_impact(b.p, b.alpha, th0) + 1e-4;
  o.stop_when_safe = false;
  const auto r = pa::simulate_rocking(b, pa::constant_ground_motion(0.0), o);
  ASSERT_EQ(r.impacts, 1);
  // The sample recorded at the impact holds the rebound velocity.
  double after = 0.0;
  for (const auto& s : r.history)
    if (s.t == r.impact_times[0]) after = s.omega;
  EXPECT_NEAR(after, c * pa::free_rocking_impact_velocity(b.p, b.alpha, th0), 1e-9);
}

TEST(RockingResponse, EnergyIsConservedBetweenImpacts) {
  const auto b = test_block();
  const double c = 0.9;
  const auto r = free_release(0.8 * b.alpha, 2e-3, 6.0, c, pa::RockingForm::nonlinear, true);
  ASSERT_GE(r.impacts, 3);
  int side = 1;
  double e_ref = pa::rocking_energy_margin(b.p, b.alpha, pa::RockingForm::nonlinear, 1, r.history[0].theta, 0.0);
  std::size_t k = 0;
  double worst = 0.0;
  for (const auto& s : r.history) {
    if (k < r.impact_times.size() && s.t == r.impact_times[k]) {  // rebound sample: new side, new energy
      ++k;
      side = -side;
      e_ref = pa::rocking_energy_margin(b.p, b.alpha, pa::RockingForm::nonlinear, side, s.theta, s.omega);
      continue;
    }
    if (s.theta == 0.0) continue;
    const double e = pa::rocking_energy_margin(b.p, b.alpha, pa::RockingForm::nonlinear, side, s.theta, s.omega);
    worst = std::max(worst, std::abs(e - e_ref));
  }
  EXPECT_LT(worst, 1e-9 * b.p * b.p);
}

TEST(RockingResponse, ObservedOrderIsFour) {
  // A pulse, an uplift, impacts: compare θ at a fixed time after two impacts
  // with a much finer run. RK4 with located events keeps order 4.
  const auto b = test_block();
  auto theta_at = [&](double dt) {
    pa::RockingOptions o;
    o.dt = dt;
    o.t_end = 4.0;
    o.stop_when_safe = false;
    const auto r = pa::simulate_rocking(b, pa::sine_pulse_ground_motion(0.3 * g, 1.0), o);
    EXPECT_FALSE(r.overturned);
    EXPECT_GE(r.impacts, 2);
    return r.theta_final;
  };
  const double ref = theta_at(0.02 / 64.0);
  const double e1 = std::abs(theta_at(0.02) - ref), e2 = std::abs(theta_at(0.01) - ref), e3 = std::abs(theta_at(0.005) - ref);
  const double order1 = std::log2(e1 / e2), order2 = std::log2(e2 / e3);
  EXPECT_GT(order1, 3.5);
  EXPECT_LT(order1, 4.6);
  EXPECT_GT(order2, 3.5);
  EXPECT_LT(order2, 4.6);
}

TEST(RockingResponse, OnsetAtGTanAlpha) {
  const auto b = test_block();
  pa::RockingOptions o;
  o.t_end = 10.0;  // a push 0.1% over the threshold needs ~4 s to throw it over
  const double a_crit = g * std::tan(b.alpha);
  auto below = pa::simulate_rocking(b, pa::constant_ground_motion(0.999 * a_crit), o);
  EXPECT_FALSE(below.uplifted);
  EXPECT_EQ(below.max_abs_theta, 0.0);
  auto above = pa::simulate_rocking(b, pa::constant_ground_motion(1.001 * a_crit), o);
  EXPECT_TRUE(above.uplifted);
  EXPECT_EQ(above.t_uplift, 0.0);
  EXPECT_TRUE(above.overturned);  // a constant push past the threshold never lets go
  EXPECT_EQ(above.mode, pa::CollapseMode::mode_2);
  EXPECT_LT(above.theta_final, 0.0);  // positive a_g rocks the body to θ < 0 (eq. 7)
  // Pulse: uplift when a_p sin(2πt/T) first reaches g tan α.
  const double ap = 2.0 * a_crit, T = 0.7;
  auto pulse = pa::simulate_rocking(b, pa::sine_pulse_ground_motion(ap, T), o);
  EXPECT_NEAR(pulse.t_uplift, std::asin(0.5) * T / (2.0 * 3.14159265358979323846), 1e-12);
}

TEST(RockingResponse, ModeClassification) {
  const auto b = test_block();
  pa::RockingOptions o;
  o.dt = 2e-3;
  o.t_end = 10.0;
  // A long strong pulse throws the block over on its first excursion.
  auto m2 = pa::simulate_rocking(b, pa::sine_pulse_ground_motion(3.0 * g, 2.0), o);
  EXPECT_TRUE(m2.overturned);
  EXPECT_EQ(m2.mode, pa::CollapseMode::mode_2);
  EXPECT_EQ(m2.impacts, 0);
  // A weak pulse only rocks it.
  auto none = pa::simulate_rocking(b, pa::sine_pulse_ground_motion(0.3 * g, 1.0), o);
  EXPECT_TRUE(none.uplifted);
  EXPECT_FALSE(none.overturned);
  EXPECT_EQ(none.mode, pa::CollapseMode::none);
}

TEST(RockingResponse, SampledRecordInterpolates) {
  const auto gm = pa::sampled_ground_motion(0.1, {0.0, 1.0, -1.0});
  EXPECT_DOUBLE_EQ(gm.acceleration(0.05), 0.5);
  EXPECT_NEAR(gm.acceleration(0.15), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(gm.acceleration(0.5), 0.0);
  EXPECT_DOUBLE_EQ(gm.quiet_after, 0.2);
}

// The next sample time after t is strictly after t for every t, also where
// t/dt rounds below an integer (0.29/0.01 = 28.999...), so a rocking run on
// a record ends its steps on the samples and never stalls on one.
TEST(RockingResponse, NextSampleOfARecordIsAlwaysLater) {
  const auto gm = pa::sampled_ground_motion(0.01, std::vector<double>(101, 0.0));
  for (int k = 0; k < 100; ++k) {
    const double t = 0.01 * k;
    EXPECT_GT(gm.next_breakpoint(t), t) << k;
    EXPECT_LE(gm.next_breakpoint(t) - t, 0.01 + 1e-15) << k;
  }
  std::vector<double> a(101, 0.0);
  for (int k = 0; k < 101; ++k) a[k] = 0.3 * 9.81 * std::sin(2 * M_PI * 2.0 * 0.01 * k);
  pa::RockingOptions o;
  o.t_end = 1.0;
  const auto r = pa::simulate_rocking(test_block(), pa::sampled_ground_motion(0.01, a), o);
  EXPECT_TRUE(r.uplifted);
  EXPECT_GT(r.t_final, 0.29);
}
