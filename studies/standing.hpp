// Can the blocks stand under their own weight, and how thin can a parameter
// (an arch's ring thickness) make them before they cannot?
//
// The limit-analysis LP (studies/limit_analysis.hpp) maximises λ, the
// horizontal body force λ m |g| d the blocks can carry in equilibrium with
// compressive joint forces inside the friction pyramid, on the joints of the
// initial mesh. The set of λ with an admissible field is an interval
// [λ_min(d), λ_max(d)] (the LP's feasible set is convex), and λ_min(d) =
// −λ_max(−d). So self-weight alone (λ = 0) has an admissible field iff
//     λ_max(d) ≥ 0  and  λ_max(−d) ≥ 0,
// two LPs; "infeasible" (no λ at all) counts as not standing. With a
// friction angle near 90° (no sliding) this is the classical question of
// Heyman's safe theorem for a rigid, no-tension, non-sliding arch: a thrust
// line inside the masonry exists iff the arch can stand. (With finite
// friction the LP's answer is only a necessary condition: see the header of
// limit_analysis.hpp, point 3.)
//
// thinnest_standing() bisects a scalar parameter p (the scene is rebuilt for
// each trial by the caller's function) between a value at which the scene
// cannot stand and one at which it can, until the bracket is narrower than
// the tolerance: the threshold p* with the blocks standing above it.
#pragma once

#include "studies/limit_analysis.hpp"

#include <functional>

namespace polydem {

struct StandingCheck {
  bool stands = false;
  LimitAnalysisResult plus, minus;  // λ_max along d and along −d
};

// The two LPs above; options.direction is d.
StandingCheck can_stand(const LimitModel& model, const LimitAnalysisOptions& options);

struct ThinnestStanding {
  double falls = 0, stands = 0;  // the final bracket: p at which it cannot, can stand
  int trials = 0;
  double threshold() const { return 0.5 * (falls + stands); }
};

// Throws std::invalid_argument if the initial bracket does not bracket
// (the scene stands at `falls`, or cannot at `stands`).
ThinnestStanding thinnest_standing(const std::function<SceneSpec(double)>& scene_at, double falls, double stands,
                                   double tolerance, const LimitAnalysisOptions& options);

// The thinnest semicircular arch of n voussoirs on a fixed base that can
// stand under its own weight (`polydem analytic arch-thickness`): the ring
// thickness over the centre-line radius, t/R, bisected in [0.001, 0.6] with
// the LP's simplex at friction angle φ (near 90°: no sliding, Heyman's
// question; Milankovitch's continuous arch needs t/R = 0.1075).
// arch_at(n, t/R) builds the arch (io/analytic_inputs.hpp).
struct ThinnestArchOptions {
  double friction_angle_deg = 85.0;
  double tolerance = 1e-5;  // of the bracket on t/R
};

struct ThinnestArch {
  int voussoirs = 0;
  ThinnestStanding bracket;  // in t/R; falls = 0 when it stands at 0.001 already
  bool stands_however_thin() const { return bracket.falls == 0.0; }
  double seconds = 0.0;      // wall time of the bisection
};

ThinnestArch thinnest_arch(int voussoirs, const std::function<SceneSpec(int, double)>& arch_at,
                           const ThinnestArchOptions& options = {});

}  // namespace polydem
