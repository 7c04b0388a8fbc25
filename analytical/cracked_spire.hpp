#pragma once
// The "cracked cone" of paper section 2.3 (last paragraph) and Fig. 7a: the
// part of the spire above a diagonal crack rocks about the crack's upper end O.
//
// Geometry (all explicit inputs, SpireGeometry): the spire is a cone of height
// H and outer base radius r_b (radius r(y) = r_b (1 − y/H)); its top
// tip_height is solid, the rest a thin shell of wall thickness t. The crack
// starts just below the solid tip on the uplifting (tension) face, at
// A = (−r(y_A), y_A), y_A = H − tip_height, and runs down in a plane whose
// normal lies in the rocking plane to the pivot O = (r(y_O), y_O) on the
// opposite face, y_O = H − H̄. The rocking body is the solid tip plus the
// shell above that plane; it rocks about O, as the whole cone does about its
// base corner in Fig. 1(b)-(c). H̄ (apex to O) is the "cracked height";
// H̄ = tip_height is the tip alone, H̄ = H a crack from the tip to the base.
//
// What this model gives (docs/analytical.md): p falls monotonically with H̄
// (the wedge added below the tip is close to O but makes the body larger, and
// p ∝ 1/√size for a fixed shape), so its maximum is the tip alone; the paper's
// maximum at H̄ = 4.1 m (Fig. 7a) is not reproduced by this reading. Variants
// tried (pivot at the crack's upper end, a shell tip) are monotone as well.

#include <vector>

#include "analytical/rocking_body.hpp"

namespace polydem::analytical {

struct SpireGeometry {
  double H = 9.4;            // modelled spire height, base to apex [m] (paper 3.1)
  double r_b = 1.06;         // outer radius at its base [m]
  double tip_height = 3.4;   // solid top part [m] (paper 3.1)
  double wall_thickness = 0.25;  // shell wall below the tip [m] (not given in the paper)
  double density = 2600.0;   // [kg/m³] (paper Table 1)
};

void validate(const SpireGeometry& s);

// Mass properties of the body above the crack, rocking about O (eq. 7-10
// inputs). Requires tip_height ≤ H_bar ≤ H. The eq. 10 restitution it carries
// is only indicative: the paper notes the impact of a cracked cone needs its
// own formulation.
RockingBody cracked_spire_body(const SpireGeometry& s, double H_bar, double g);

struct CrackedSpireMaximum {
  double H_bar = 0.0;  // [m]
  double p = 0.0;      // [rad/s]
};
// The H̄ that maximises p (shifts the collapse curve furthest left; paper: 4.1 m).
CrackedSpireMaximum cracked_spire_p_max(const SpireGeometry& s, double g);

// The body against the cracked height (paper Fig. 7a), as `polydem analytic
// cracked-cone-p` reports it: `count` ≥ 2 values of H̄ evenly from
// tip_height to H, and the maximum of p.
struct CrackedSpirePoint {
  double H_bar = 0.0;  // [m]
  RockingBody body;
};
struct CrackedSpireCurve {
  SpireGeometry spire;  // the inputs
  double g = 0.0;
  CrackedSpireMaximum p_max;
  std::vector<CrackedSpirePoint> points;
};
CrackedSpireCurve cracked_spire_curve(const SpireGeometry& s, int count, double g);

}  // namespace polydem::analytical
