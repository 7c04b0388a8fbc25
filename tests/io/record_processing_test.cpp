// Baseline correction and time scaling of records (io/record_processing.hpp).
#include "io/record_processing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace polydem {
namespace {

std::vector<double> times(int n, double dt) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(i * dt);
  return t;
}

double largest(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The displacement of a constant and of a linear acceleration from rest is
// exact: a t²/2 and b t³/6.
TEST(RecordProcessing, DisplacementIsExactForLinearAcceleration) {
  const auto t = times(101, 0.01);
  std::vector<double> a;
  for (double x : t) a.push_back(2.0 + 6.0 * x);
  const auto u = record_displacement(t, a);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(u[i], t[i] * t[i] + t[i] * t[i] * t[i], 1e-13);
}

// An offset or a linear drift alone is removed entirely by a correction of
// that order: the fit of the displacement is then exact.
TEST(RecordProcessing, PolynomialDriftIsRemoved) {
  for (int order : {0, 1}) {
    auto t = times(501, 0.02);
    std::vector<double> a;
    for (double x : t) a.push_back(0.05 + (order == 1 ? -0.01 * x : 0.0));
    correct_baseline(t, a, order);
    EXPECT_LT(largest(a), 1e-12) << "order " << order;
  }
}

// A motion that starts and ends at rest (u = 0.01 sin(Ωt) sin²(πt/D)), plus
// an offset of 0.02 m/s² that walks the ground 1 m away in 10 s: the
// correction takes the walk out and leaves the motion.
TEST(RecordProcessing, CorrectionStopsTheGroundWalkingAway) {
  const double D = 10.0, W = 2 * 3.14159265358979 * 1.7, k = 3.14159265358979 / D;
  auto t = times(1001, 0.01);
  std::vector<double> motion, a;
  for (double x : t) {
    const double s = std::sin(W * x), w = std::pow(std::sin(k * x), 2);
    const double ds = W * std::cos(W * x), dw = k * std::sin(2 * k * x);
    const double dds = -W * W * s, ddw = 2 * k * k * std::cos(2 * k * x);
    motion.push_back(0.01 * (dds * w + 2 * ds * dw + s * ddw));
    a.push_back(motion.back() + 0.02);
  }
  const double drift = record_displacement(t, a).back();
  correct_baseline(t, a, 2);
  const double left = record_displacement(t, a).back();
  double change = 0;
  for (std::size_t i = 0; i < t.size(); ++i) change = std::max(change, std::abs(a[i] - motion[i]));
  EXPECT_NEAR(drift, 1.0, 1e-3);
  EXPECT_LT(std::abs(left), 1e-4);
  EXPECT_LT(change, 0.01);  // against a motion of 0.3 m/s² peak
  EXPECT_EQ(record_displacement(t, a)[0], 0.0);
}

TEST(RecordProcessing, RefusesBadOrders) {
  auto t = times(3, 0.01);
  std::vector<double> a{0, 1, 0};
  EXPECT_THROW(correct_baseline(t, a, -1), std::invalid_argument);
  EXPECT_THROW(correct_baseline(t, a, kMaxBaselineOrder + 1), std::invalid_argument);
  EXPECT_THROW(correct_baseline(t, a, 2), std::invalid_argument);  // 3 unknowns need 4 samples
  EXPECT_NO_THROW(correct_baseline(t, a, 1));
}

// λ = 1/4 (a quarter-scale model): times halve, accelerations stay.
TEST(RecordProcessing, TimeScalingBySquareRootOfLengthScale) {
  std::vector<double> t{0.0, 0.02, 0.04};
  scale_record_time(t, 0.25);
  EXPECT_DOUBLE_EQ(t[1], 0.01);
  EXPECT_DOUBLE_EQ(t[2], 0.02);
  EXPECT_THROW(scale_record_time(t, 0.0), std::invalid_argument);
  EXPECT_THROW(scale_record_time(t, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace polydem
