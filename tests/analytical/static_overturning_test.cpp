#include "analytical/static_overturning.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pa = polydem::analytical;

TEST(StaticOverturning, ConeIsThreeRbOverH) {
  EXPECT_DOUBLE_EQ(pa::lambda_cone(1.0, 3.0), 1.0);
  EXPECT_NEAR(pa::lambda_cone(1.06, 9.4), 0.338298, 1e-6);
}

TEST(StaticOverturning, CrackAtZeroHeightIsEquationOne) {
  EXPECT_DOUBLE_EQ(pa::lambda_crack(1.06, 9.4, 0.0), pa::lambda_cone(1.06, 9.4));
}

TEST(StaticOverturning, CrackAtFullHeightIsTwoThirdsMinusInversePiSquared) {
  // By hand: numerator H³(1/π² − 2/π² + 2/3 − 2 + 2), denominator H³(1 − 2 + 2).
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(pa::crack_reduction_factor(1.0), 2.0 / 3.0 - 1.0 / (pi * pi), 1e-15);
  // Mid-height by hand: (1/(8π²) − (2/π² − 2/3)/4 − 1 + 2) / (1/8 − 1/2 + 2).
  const double num = 1.0 / (8.0 * pi * pi) - (2.0 / (pi * pi) - 2.0 / 3.0) / 4.0 + 1.0;
  EXPECT_NEAR(pa::crack_reduction_factor(0.5), num / 1.625, 1e-15);
}

TEST(StaticOverturning, GoverningCrackIsAtTheTopAndMatchesPaper) {
  const auto g = pa::governing_crack(1.06, 9.4);
  EXPECT_NEAR(g.h_c, 9.4, 1e-9);
  EXPECT_NEAR(g.lambda, 0.338298 * 0.565345, 1e-5);
  // Paper 3.2: λ = 0.192 from eq. 2 with 3 r_b / H ≈ 0.34.
  EXPECT_NEAR(pa::governing_crack(0.34 * 9.4 / 3.0, 9.4).lambda, 0.192, 5e-4);
  // Monotone decreasing on [0, H]: the scan never finds anything lower inside.
  for (int i = 0; i < 100; ++i)
    EXPECT_GT(pa::crack_reduction_factor(i / 100.0), pa::crack_reduction_factor((i + 1) / 100.0));
}

TEST(StaticOverturning, RejectsBadInput) {
  EXPECT_THROW(pa::lambda_cone(-1.0, 9.4), std::invalid_argument);
  EXPECT_THROW(pa::lambda_crack(1.0, 9.4, 10.0), std::invalid_argument);
}

TEST(StaticOverturning, ConeOverturningGathersEquationsOneAndTwo) {
  const auto c = pa::cone_overturning(1.06, 9.4, 5.0);
  EXPECT_EQ(c.lambda_eq1, pa::lambda_cone(1.06, 9.4));
  EXPECT_EQ(c.lambda_at_h_c, pa::lambda_crack(1.06, 9.4, 5.0));
  EXPECT_EQ(c.governing.lambda, pa::governing_crack(1.06, 9.4).lambda);
  EXPECT_EQ(c.h_c, 5.0);
  EXPECT_THROW(pa::cone_overturning(1.06, 9.4, 10.0), std::invalid_argument);  // h_c above H
}
