// GroundMotion: the base velocity v_g(t) must be the integral of a_g(t), so
// that kinematic bases and inertial body forces describe the same motion.
// Each kind is checked against a numerical quadrature of acceleration_at().
#include "core/ground_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace polydem {
namespace {

// Composite trapezoid on [t0, t1] with n intervals: exact for piecewise
// linear integrands whose kinks fall on grid nodes.
double trapezoid(const std::function<double(double)>& f, double t0, double t1, int n) {
  const double h = (t1 - t0) / n;
  double s = 0.5 * (f(t0) + f(t1));
  for (int k = 1; k < n; ++k) s += f(t0 + k * h);
  return s * h;
}

// Composite Simpson on [t0, t1] with n (even) intervals: error h⁴·max|f⁗|·(t1−t0)/180.
double simpson(const std::function<double(double)>& f, double t0, double t1, int n) {
  const double h = (t1 - t0) / n;
  double s = f(t0) + f(t1);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * f(t0 + k * h);
  return s * h / 3.0;
}

GroundMotion motion(GroundMotionKind kind, double start) {
  GroundMotionSpec spec;
  spec.kind = kind;
  spec.start_time = start;
  spec.acceleration = 2.5;
  spec.rate = 3.0;
  spec.period = 0.4;
  return make_ground_motion(spec);
}

TEST(GroundMotion, NoneIsZero) {
  const GroundMotion g = motion(GroundMotionKind::none, 0.0);
  EXPECT_FALSE(g.active());
  EXPECT_EQ(g.acceleration_at(1.0), 0.0);
  EXPECT_EQ(g.velocity_at(1.0), 0.0);
}

TEST(GroundMotion, ConstantVelocityIsTheIntegral) {
  const double t0 = 0.25;
  const GroundMotion g = motion(GroundMotionKind::constant, t0);
  EXPECT_TRUE(g.active());
  auto a = [&](double t) { return g.acceleration_at(t); };
  EXPECT_EQ(g.acceleration_at(0.2), 0.0);
  EXPECT_EQ(g.velocity_at(0.2), 0.0);
  EXPECT_EQ(g.acceleration_at(0.3), 2.5);
  for (double t : {0.3, 0.7, 1.9}) {
    // Integrate from the start (a jump there) to t: the integrand is constant.
    const double v = trapezoid(a, t0, t, 7);
    EXPECT_NEAR(g.velocity_at(t), v, 1e-13) << "t = " << t;
    EXPECT_NEAR(g.velocity_at(t), 2.5 * (t - t0), 1e-15) << "t = " << t;
  }
}

TEST(GroundMotion, RampVelocityIsTheIntegral) {
  const double t0 = 0.1;
  const GroundMotion g = motion(GroundMotionKind::ramp, t0);
  auto a = [&](double t) { return g.acceleration_at(t); };
  EXPECT_EQ(g.acceleration_at(0.05), 0.0);
  EXPECT_NEAR(g.acceleration_at(0.6), 3.0 * 0.5, 1e-15);
  for (double t : {0.35, 1.0, 2.6}) {
    // Zero before t0, linear after: the trapezoid on a grid from t0 is exact.
    EXPECT_NEAR(g.velocity_at(t), trapezoid(a, t0, t, 1000), 1e-12) << "t = " << t;
    EXPECT_NEAR(g.velocity_at(t), 0.5 * 3.0 * (t - t0) * (t - t0), 1e-14) << "t = " << t;
  }
}

TEST(GroundMotion, SinePulseVelocityIsTheIntegralAndZeroAfterOneCycle) {
  const double t0 = 0.2, T = 0.4;
  const GroundMotion g = motion(GroundMotionKind::sine_pulse, t0);
  auto a = [&](double t) { return g.acceleration_at(t); };
  EXPECT_NEAR(g.acceleration_at(t0 + T / 4), 2.5, 1e-14);
  EXPECT_EQ(g.acceleration_at(t0 + 1.01 * T), 0.0);
  // Simpson with 2000 intervals on a 0.4 s sine: h⁴·|a⁗|·T/180 ≈ 1e-15.
  for (double t : {t0 + 0.1, t0 + 0.25, t0 + T}) {
    EXPECT_NEAR(g.velocity_at(t), simpson(a, t0, t, 2000), 1e-12) << "t = " << t;
  }
  // Peak base velocity a_p·T/π at mid-pulse.
  EXPECT_NEAR(g.velocity_at(t0 + T / 2), 2.5 * T / std::numbers::pi, 1e-14);
  // A full sine cycle gives the base no net velocity, and it stays at rest.
  EXPECT_NEAR(g.velocity_at(t0 + T), 0.0, 1e-15);
  EXPECT_NEAR(g.velocity_at(t0 + 3 * T), 0.0, 1e-15);
}

TEST(GroundMotion, RecordVelocityIsTheExactIntegralOfTheInterpolation) {
  GroundMotionSpec spec;
  spec.kind = GroundMotionKind::record;
  spec.start_time = 0.5;
  spec.scale = 2.0;
  const std::vector<double> time{0.0, 0.1, 0.25, 0.4, 0.7};
  const std::vector<double> acc{0.0, 1.5, -2.0, 0.5, 0.0};
  const GroundMotion g = make_ground_motion(spec, time, acc);
  // Samples are scaled; between them the acceleration is linear.
  EXPECT_NEAR(g.acceleration_at(0.5 + 0.1), 3.0, 1e-15);
  EXPECT_NEAR(g.acceleration_at(0.5 + 0.175), 0.5 * (3.0 - 4.0), 1e-14);
  EXPECT_EQ(g.acceleration_at(0.4), 0.0);   // before the start
  EXPECT_EQ(g.acceleration_at(1.3), 0.0);   // after the record
  auto a = [&](double t) { return g.acceleration_at(t); };
  // A grid of 0.005 s holds every sample (0.5 + multiples of 0.05): the
  // trapezoid is exact for the piecewise-linear record, up to round-off.
  for (double t : {0.6, 0.75, 0.9, 1.2, 1.5}) {
    const int n = static_cast<int>(std::lround(t / 0.005));
    EXPECT_NEAR(g.velocity_at(t), trapezoid(a, 0.0, t, n), 1e-12) << "t = " << t;
  }
  // Inside an interval too (quadratic in time): Simpson is exact there.
  EXPECT_NEAR(g.velocity_at(0.5 + 0.17), simpson(a, 0.5 + 0.1, 0.5 + 0.17, 2) + g.velocity_at(0.6), 1e-13);
  // After the record the base keeps its final velocity, ∫ a = 2·(sum of trapezoids).
  const double v_end = 2.0 * (0.5 * 1.5 * 0.1 + 0.5 * (1.5 - 2.0) * 0.15 + 0.5 * (-2.0 + 0.5) * 0.15 + 0.5 * 0.5 * 0.3);
  EXPECT_NEAR(g.velocity_at(1.2), v_end, 1e-14);
  EXPECT_NEAR(g.velocity_at(5.0), v_end, 1e-14);
  EXPECT_NEAR(g.record_velocity.back(), v_end, 1e-14);
}

TEST(GroundMotion, DirectionIsNormalised) {
  GroundMotionSpec spec;
  spec.kind = GroundMotionKind::constant;
  spec.direction = Vec3(3, 4, 0);
  const GroundMotion g = make_ground_motion(spec);
  EXPECT_NEAR((g.direction - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace polydem
