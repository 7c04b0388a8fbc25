#pragma once
// Base section of a hollow spire, for eq. 3-4 (m_b and EI_b).
// Eq. 3's taper (m ∝ r, EI ∝ r^3 with r ∝ 1 − y/H) is exact for a thin wall
// of constant thickness; these give the thick-wall values at the base.

namespace polydem::analytical {

struct ShellSection {
  double area = 0.0;               // [m²]
  double second_moment = 0.0;      // I_b about a centroidal horizontal axis [m⁴]
  double mass_per_height = 0.0;    // m_b [kg/m]
  double bending_stiffness = 0.0;  // E I_b [N m²]
};

// Hollow circle: outer radius r_b, wall thickness t (0 < t ≤ r_b).
ShellSection hollow_circle_section(double r_b, double t, double density, double E);

// Hollow regular octagon: outer apothem (centre to flat face) a_b, wall
// thickness t normal to the faces. Uses I = A(6R² − s²)/24 for a regular
// polygon (circumradius R, side s), the same about every centroidal axis.
ShellSection hollow_octagon_section(double a_b, double t, double density, double E);

}  // namespace polydem::analytical
