#pragma once
// Rigid bodies that rock about a base corner O (paper section 2.3, Fig. 1c).
// Each is reduced to what eq. 7-10 need: the distance R from O to the
// centroid, the angle α of that line from the vertical (the block's
// slenderness), the inertia I0 about O, p = √(M g R / I0), and the
// restitution of eq. 10.

namespace polydem::analytical {

struct RockingBody {
  double mass = 0.0;   // M [kg] (1 when only the shape is known)
  double R = 0.0;      // pivot to centroid [m]
  double alpha = 0.0;  // atan(horizontal / vertical distance pivot→centroid) [rad]
  double I0 = 0.0;     // inertia about the pivot axis [kg m²]
  double p = 0.0;      // frequency parameter √(M g R / I0) [rad/s]
  double restitution = 0.0;  // c_v of eq. 10 (Housner's, from M R²/I0 and α)
};

// Eq. 10: c = 1 − (M R² / I0)(1 − cos 2α).
double restitution_eq10(double mass, double R, double I0, double alpha);

// Housner (1963) for a rectangular block (I0 = 4/3 M R²): c = 1 − 1.5 sin²α.
double restitution_housner_block(double alpha);

// Fill p and the eq. 10 restitution from M, R, α, I0.
RockingBody make_rocking_body(double mass, double R, double alpha, double I0, double g);

// Rectangular block, half-width b, half-height h [m]: R = √(b²+h²),
// α = atan(b/h), I0 = 4/3 M R².
RockingBody rectangular_block(double b, double h, double mass, double g);

// Thin conical shell (uniform wall), base radius r_b, height H: centroid at
// H/3, so R = √(r_b² + H²/9), α = atan(3 r_b / H) (tan α is eq. 1's λ), and
// eq. 8: I0 = 5/4 M r_b² + 1/6 M H² (derived in docs/analytical.md).
RockingBody conical_shell(double r_b, double H, double mass, double g);

// Solid cone (the spire's solid tip): centroid at H/4, R = √(r_b² + H²/16),
// α = atan(4 r_b / H), I0 = 23/20 M r_b² + 1/10 M H²
// (3/20 M r² + 1/10 M H² about a base diameter, plus M r_b² to the rim).
RockingBody solid_cone(double r_b, double H, double mass, double g);

}  // namespace polydem::analytical
