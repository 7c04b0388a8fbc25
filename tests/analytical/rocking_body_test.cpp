#include "analytical/cracked_spire.hpp"
#include "analytical/rocking_body.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pa = polydem::analytical;

TEST(RockingBody, RectangularBlockByHand) {
  const auto b = pa::rectangular_block(0.3, 0.4, 2.0, 9.81);
  EXPECT_NEAR(b.R, 0.5, 1e-15);
  EXPECT_NEAR(b.alpha, std::atan(0.75), 1e-15);
  EXPECT_NEAR(b.I0, 4.0 / 3.0 * 2.0 * 0.25, 1e-15);
  EXPECT_NEAR(b.p, std::sqrt(3.0 * 9.81 / (4.0 * 0.5)), 1e-14);
  // Eq. 10 with M R²/I0 = 3/4 is Housner's 1 − 1.5 sin²α: sin α = 0.6 → 0.46.
  EXPECT_NEAR(b.restitution, 0.46, 1e-14);
  EXPECT_NEAR(pa::restitution_housner_block(b.alpha), 0.46, 1e-14);
}

TEST(RockingBody, ConicalShellIsEquationEight) {
  const auto c = pa::conical_shell(1.06, 9.4, 3.0, 9.81);
  EXPECT_NEAR(std::tan(c.alpha), 3.0 * 1.06 / 9.4, 1e-14);  // same as eq. 1's λ
  EXPECT_NEAR(c.R, std::hypot(1.06, 9.4 / 3.0), 1e-14);
  EXPECT_NEAR(c.I0, 3.0 * (1.25 * 1.06 * 1.06 + 9.4 * 9.4 / 6.0), 1e-12);
  EXPECT_NEAR(c.p, 1.4183, 1e-4);
  EXPECT_NEAR(c.restitution, 1.0 - 3.0 * c.R * c.R / c.I0 * (1.0 - std::cos(2.0 * c.alpha)), 1e-14);
}

TEST(RockingBody, SolidConeByHand) {
  // r = 1, H = 4: I0 = 23/20 + 16/10 = 2.75, centroid at 1, R = √2, α = 45°.
  const auto c = pa::solid_cone(1.0, 4.0, 1.0, 9.81);
  EXPECT_NEAR(c.I0, 2.75, 1e-14);
  EXPECT_NEAR(c.R, std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(c.alpha, std::atan(1.0), 1e-14);
}

TEST(CrackedSpire, TipAloneIsTheSolidCone) {
  pa::SpireGeometry s;
  const auto body = pa::cracked_spire_body(s, s.tip_height, 9.81);
  const double r_tip = s.r_b * s.tip_height / s.H;
  const auto cone = pa::solid_cone(r_tip, s.tip_height, 1.0, 9.81);
  EXPECT_NEAR(body.p, cone.p, 1e-12);
  EXPECT_NEAR(body.alpha, cone.alpha, 1e-12);
  EXPECT_NEAR(body.mass, s.density * 3.14159265358979323846 * r_tip * r_tip * s.tip_height / 3.0, 1e-9);
}

TEST(CrackedSpire, ShellMassOfFullCrackIsHalfTheShellOrMore) {
  // H̄ = H: the plane cuts the shell from the tip's base on one side to the
  // base on the other; by symmetry of the cut the shell part lies between
  // none and all of the shell, and more mass joins as H̄ grows.
  pa::SpireGeometry s;
  double last = 0.0;
  for (double hb = s.tip_height; hb <= s.H + 1e-12; hb += 0.5) {
    const auto b = pa::cracked_spire_body(s, std::min(hb, s.H), 9.81);
    EXPECT_GT(b.mass, last);
    last = b.mass;
  }
}

TEST(CrackedSpire, PMaximumIsReportedWithItsHeight) {
  pa::SpireGeometry s;
  const auto m = pa::cracked_spire_p_max(s, 9.81);
  EXPECT_GE(m.H_bar, s.tip_height);
  EXPECT_LE(m.H_bar, s.H);
  for (double hb = s.tip_height; hb <= s.H; hb += 0.25) EXPECT_LE(pa::cracked_spire_body(s, hb, 9.81).p, m.p + 1e-9);
  // This geometry's p falls with H̄ (see cracked_spire.hpp): the tip governs.
  EXPECT_NEAR(m.H_bar, s.tip_height, 1e-6);
  EXPECT_NEAR(m.p, 2.6275, 1e-4);
}
