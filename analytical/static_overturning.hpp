#pragma once
// Static overturning of a conical shell under a horizontal body force λ·g
// (paper section 2.1, eq. 1 and 2; Heyman's ultimate-load assumptions: no
// tension, infinite compressive strength, no sliding).

namespace polydem::analytical {

// Eq. 1: the uncracked shell tips about its base rim. Its centroid is at H/3,
// so λ = r_b / (H/3) = 3 r_b / H.  r_b base radius [m], H height [m].
double lambda_cone(double r_b, double H);

// Eq. 2 exactly as printed: a diagonal crack of height h_c (0 ≤ h_c ≤ H)
// lets only part of the shell resist. At h_c = 0 it reduces to eq. 1.
double lambda_crack(double r_b, double H, double h_c);

// Eq. 2 divided by eq. 1 (dimensionless, depends on h_c/H only).
double crack_reduction_factor(double h_c_over_H);

struct GoverningCrack {
  double lambda = 0.0;  // minimum of eq. 2 over h_c in [0, H]
  double h_c = 0.0;     // crack height where it occurs [m]
};

// Minimum of eq. 2 over h_c ∈ [0, H] (grid scan, then golden section around
// the best grid point; the minimum turns out to be at the end h_c = H where
// the factor is 2/3 − 1/π², see docs/analytical.md).
GoverningCrack governing_crack(double r_b, double H);

// Eq. 1 and eq. 2 for one cone, as `polydem analytic lambda` reports them.
struct ConeOverturning {
  double r_b = 0.0, H = 0.0, h_c = 0.0;  // the inputs [m]
  double lambda_eq1 = 0.0;               // eq. 1
  double lambda_at_h_c = 0.0;            // eq. 2 at h_c
  GoverningCrack governing;              // eq. 2's minimum over the crack height
};
ConeOverturning cone_overturning(double r_b, double H, double h_c);

}  // namespace polydem::analytical
