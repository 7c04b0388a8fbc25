#include "analytical/beam_modes.hpp"
#include "analytical/shell_sections.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pa = polydem::analytical;

TEST(BeamModes, BesselRootsReproduceNaguleswaran) {
  const auto om = pa::tapered_cantilever_omegas(3);
  ASSERT_EQ(om.size(), 3u);
  EXPECT_NEAR(om[0], 5.315, 0.005 * 5.315);
  EXPECT_NEAR(om[1], 15.21, 0.005 * 15.21);
  EXPECT_NEAR(om[2], 30.02, 0.005 * 30.02);
  // Tighter: the printed digits.
  EXPECT_NEAR(om[0], 5.315, 5e-4);
  EXPECT_NEAR(om[1], 15.21, 5e-3);
  EXPECT_NEAR(om[2], 30.02, 5e-3);
}

TEST(BeamModes, FiniteElementsAgreeWithBesselRoots) {
  const auto exact = pa::tapered_cantilever_omegas(3);
  const auto fe = pa::tapered_cantilever_omegas_fe(3, 60);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(fe[i], exact[i], 1e-5 * exact[i]) << "mode " << i + 1;
}

TEST(BeamModes, ModeShapeIsClampedAndUnitAtTip) {
  const double Om = pa::tapered_cantilever_omegas(1)[0];
  EXPECT_NEAR(pa::tapered_cantilever_mode_shape(Om, 1.0), 1.0, 1e-14);
  EXPECT_NEAR(pa::tapered_cantilever_mode_shape(Om, 0.0), 0.0, 1e-10);
  const double h = 1e-5;  // slope at the base by a one-sided difference
  EXPECT_NEAR(pa::tapered_cantilever_mode_shape(Om, h) / h, 0.0, 1e-3);
}

TEST(BeamModes, RayleighClosedFormAndMinimum) {
  // k = 2 by hand: 3·2·1·3·5 / (1·3) = 30.
  EXPECT_NEAR(pa::rayleigh_omega(2.0), std::sqrt(30.0), 1e-14);
  const auto m = pa::rayleigh_minimum();
  EXPECT_NEAR(m.k, 2.2, 0.05);  // paper: k = 2.2
  EXPECT_GT(m.Omega, pa::tapered_cantilever_omegas(1)[0]);  // Rayleigh is an upper bound
  EXPECT_LT(m.Omega, 1.01 * pa::tapered_cantilever_omegas(1)[0]);
  EXPECT_LT(m.Omega, pa::rayleigh_omega(m.k - 0.01));
  EXPECT_LT(m.Omega, pa::rayleigh_omega(m.k + 0.01));
}

TEST(BeamModes, FrequencyInHertz) {
  // Ω = 2π, EI = m = H = 1 → 1 Hz.
  EXPECT_NEAR(pa::natural_frequency_hz(2.0 * 3.14159265358979323846, 1.0, 1.0, 1.0), 1.0, 1e-15);
  EXPECT_NEAR(pa::natural_frequency_hz(5.0, 4.0, 1.0, 1.0), 5.0 / 2.0 / (2.0 * 3.14159265358979323846), 1e-15);
}

TEST(ShellSections, HollowCircleByHand) {
  const double pi = 3.14159265358979323846;
  const auto s = pa::hollow_circle_section(1.0, 0.5, 2000.0, 1e9);
  EXPECT_NEAR(s.area, pi * 0.75, 1e-14);
  EXPECT_NEAR(s.second_moment, 0.25 * pi * (1.0 - 0.0625), 1e-14);
  EXPECT_NEAR(s.mass_per_height, 2000.0 * pi * 0.75, 1e-9);
  EXPECT_NEAR(s.bending_stiffness, 1e9 * s.second_moment, 1e-3);
}

TEST(ShellSections, SolidOctagonMatchesPolygonFormula) {
  // t = apothem: a solid octagon. Square check of the same formula: side 2 → I = 16/12.
  const auto s = pa::hollow_octagon_section(1.0, 1.0, 1.0, 1.0);
  const double tan8 = std::tan(3.14159265358979323846 / 8.0);
  EXPECT_NEAR(s.area, 8.0 * tan8, 1e-14);
  // Octagon lies between its inscribed and circumscribed circles.
  const double pi = 3.14159265358979323846;
  EXPECT_GT(s.second_moment, 0.25 * pi);
  EXPECT_LT(s.second_moment, 0.25 * pi / std::pow(std::cos(pi / 8.0), 4));
}

// The spire's beam: the section's m_b and EI_b in eq. 4 for every mode.
TEST(BeamModes, SpireBeamUsesTheSectionOfItsShape) {
  pa::SpireBeam b;
  b.section = pa::SectionShape::octagon;
  b.modes = 2;
  const auto r = pa::spire_beam_modes(b);
  const auto s = pa::hollow_octagon_section(b.r_b, b.thickness, b.density, b.E);
  EXPECT_EQ(r.section.bending_stiffness, s.bending_stiffness);
  ASSERT_EQ(r.modes.size(), 2u);
  EXPECT_NEAR(r.modes[0].Omega, 5.315, 1e-3);
  EXPECT_EQ(r.modes[1].f_hz, pa::natural_frequency_hz(r.modes[1].Omega, s.mass_per_height, s.bending_stiffness, b.H));
  EXPECT_EQ(r.rayleigh_f_hz,
            pa::natural_frequency_hz(pa::rayleigh_minimum().Omega, s.mass_per_height, s.bending_stiffness, b.H));
  b.section = pa::SectionShape::circle;
  EXPECT_EQ(pa::spire_beam_modes(b).section.bending_stiffness,
            pa::hollow_circle_section(b.r_b, b.thickness, b.density, b.E).bending_stiffness);
}
