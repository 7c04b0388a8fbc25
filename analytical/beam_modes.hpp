#pragma once
// Elastic bending modes of the spire as a tapered Euler–Bernoulli cantilever
// (paper section 2.2, eq. 3-6).
//
// With ξ = y/H and s = 1 − ξ (distance from the tip over H), eq. 3 gives
// m = s m_b, EI = s^3 EI_b, and the mode equation (EI X'')'' = ω² m X becomes
//   (s^3 X_ss)_ss = Ω² s X,   Ω² = ω² m_b H^4 / EI_b   (eq. 4).
// s = 0 is a regular singular point (indicial roots 0, 0, 1, −1). The two
// solutions bounded there are s^{-1/2} J1(2√(Ω s)) and s^{-1/2} I1(2√(Ω s))
// (their power series obey a_j j²(j²−1) = Ω² a_{j−2}, which is the Bessel
// series with ν = 1). Clamping X = X' = 0 at the base s = 1, z = 2√Ω, gives
//   J1(z) I2(z) + J2(z) I1(z) = 0,
// whose roots are Naguleswaran's Ω_n (5.315, 15.21, 30.02). A Hermite finite
// element model is kept alongside as an independent numerical check.

#include <vector>

#include "analytical/shell_sections.hpp"

namespace polydem::analytical {

// Left side of the frequency equation, divided by I1(z) so it stays O(1).
double tapered_cantilever_frequency_function(double Omega);

// First n roots Ω_1 < Ω_2 < ... of the frequency equation (dimensionless).
std::vector<double> tapered_cantilever_omegas(int n_modes);

// Mode n shape at height y/H ∈ [0, 1], scaled to 1 at the tip.
double tapered_cantilever_mode_shape(double Omega, double y_over_H);

// The same Ω_n from n_elements cubic Hermite beam elements (clamped at y = 0,
// properties of eq. 3 integrated exactly by Gauss quadrature).
std::vector<double> tapered_cantilever_omegas_fe(int n_modes, int n_elements);

// Eq. 5-6 with x(y) = (y/H)^k, in the units of eq. 4:
//   Ω̄(k)² = k²(k−1)² B(2k−3, 4) / B(2k+1, 2) = 3k(k−1)(k+1)(2k+1) / ((2k−3)(2k−1)).
// Finite only for k > 3/2 (the curvature energy at the root diverges below).
double rayleigh_omega(double k);

struct RayleighMinimum {
  double k = 0.0;
  double Omega = 0.0;
};
// Minimiser of rayleigh_omega over k > 3/2 (paper: k ≈ 2.2).
RayleighMinimum rayleigh_minimum();

// ω_n / 2π from eq. 4 [Hz]. m_b [kg/m], EI_b [N m²], H [m].
double natural_frequency_hz(double Omega, double m_b, double EI_b, double H);

// The spire as a tapered cantilever on a hollow base section, as `polydem
// analytic beam` reports it: m_b and EI_b of the section, the first modes'
// Ω_n and frequencies, and Rayleigh's estimate (eq. 5-6).
enum class SectionShape { circle, octagon };
const char* to_string(SectionShape s);

struct SpireBeam {
  double H = 9.4;           // height [m]
  double r_b = 1.06;        // base: outer radius (circle) or outer apothem (octagon) [m]
  double thickness = 0.25;  // wall [m]
  double E = 30e9;          // [Pa]
  double density = 2600.0;  // [kg/m³]
  SectionShape section = SectionShape::circle;
  int modes = 3;
};

struct BeamMode {
  double Omega = 0.0;  // eq. 4's Ω_n
  double f_hz = 0.0;
};

struct SpireBeamModes {
  SpireBeam beam;        // the inputs
  ShellSection section;  // at the base
  std::vector<BeamMode> modes;
  RayleighMinimum rayleigh;
  double rayleigh_f_hz = 0.0;
};

SpireBeamModes spire_beam_modes(const SpireBeam& beam);

}  // namespace polydem::analytical
