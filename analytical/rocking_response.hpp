#pragma once
// Rocking of a rigid body on a rigid base under horizontal ground
// acceleration (Housner 1963; paper eq. 7, small-angle form eq. 9, impact
// eq. 10).
//
//   θ > 0 (pivot on one corner):  θ̈ = −p² [ sin(α − θ) + (a_g/g) cos(α − θ) ]
//   θ < 0 (the other corner):     θ̈ = −p² [ sin(−α − θ) + (a_g/g) cos(−α − θ) ]
//   eq. 9 (small angles):         θ̈ =  p² [ θ − s α − a_g/g ],  s = sign θ
//
// The integrator is classical RK4 at a fixed step with events located inside
// the step (Illinois false position on the RK4 step of variable length, so the
// event time keeps the method's fourth order):
//   - uplift: a body at rest starts to rock only once |a_g| > g tan α, on the
//     side s = −sign(a_g);
//   - impact: θ crosses 0; θ̇ ← c θ̇ and the pivot changes side; once the
//     rebound |θ̇| falls below rest_velocity·p the body is put back at rest
//     (the impact sequence is otherwise infinite in finite time);
//   - overturning: |θ| > α (the centroid passes over the pivot). Mode I if at
//     least one impact came first, Mode II if none (Zhang & Makris 2001).
//     Under OverturnRule::no_return the body is followed past α (eq. 7
//     holds there too): a pulse still acting can pull it back, as it does a
//     block that passes α early in a strong pulse's first half. It has
//     overturned once it is past α with the ground still for good and
//     cannot come back (moving outward, or too slowly to climb back over
//     α), or once |θ| reaches π/2 (on its side). The time and the mode are
//     those of its last passage over α. This is the judgement a DEM run
//     makes from where the blocks end up (run/assessment.hpp).

#include <optional>
#include <vector>

#include "analytical/constants.hpp"
#include "analytical/ground_motion.hpp"
#include "analytical/rocking_body.hpp"

namespace polydem::analytical {

enum class RockingForm { nonlinear, linearised };  // eq. 7 / eq. 9
enum class CollapseMode { none, mode_1, mode_2 };
// When a rocking body has overturned: at |θ| > α (the convention of the
// collapse diagrams, Zhang & Makris 2001), or past α with no return.
enum class OverturnRule { past_alpha, no_return };

const char* to_string(CollapseMode m);

struct RockingOptions {
  double dt = 1e-3;       // RK4 step [s]
  double t_end = 20.0;    // [s]
  double g = standard_gravity;
  RockingForm form = RockingForm::nonlinear;
  std::optional<double> restitution;  // default: the body's eq. 10 value
  double rest_velocity = 1e-9;        // rest once |θ̇| after impact < this · p
  // Stop early once a_g has gone quiet for good and the body can no longer
  // reach |θ| = α (rocking_energy_margin < 0) or is at rest.
  bool stop_when_safe = true;
  OverturnRule overturn = OverturnRule::past_alpha;
  bool record_history = false;
  double theta0 = 0.0;  // initial rotation [rad]; nonzero starts rocking on its side
  double omega0 = 0.0;  // initial θ̇ [rad/s] (with theta0 = 0, rocks on its side)
};

struct RockingSample {
  double t, theta, omega, a_g;
};

struct RockingResult {
  bool uplifted = false;
  double t_uplift = -1.0;  // first uplift [s], −1 if never
  bool overturned = false;
  CollapseMode mode = CollapseMode::none;
  double t_overturn = -1.0;  // [s], −1 if never
  int impacts = 0;
  std::vector<double> impact_times;  // [s]
  double max_abs_theta = 0.0;        // [rad]
  double t_final = 0.0, theta_final = 0.0, omega_final = 0.0;
  int steps = 0;
  std::vector<RockingSample> history;  // when record_history
};

// θ̈ for pivot side s = ±1 (eq. 7 or eq. 9).
double rocking_angular_acceleration(double p, double alpha, double g, RockingForm form, int side,
                                    double theta, double a_g);

// Energy per unit I0 above the overturning threshold with a_g = 0:
// ½θ̇² − p²(1 − cos(sα − θ)) (eq. 7) or ½θ̇² − ½p²(θ − sα)² (eq. 9). It is
// conserved between impacts; while it is < 0 the free body cannot reach |θ| = α.
double rocking_energy_margin(double p, double alpha, RockingForm form, int side, double theta, double omega);

RockingResult simulate_rocking(const RockingBody& body, const GroundMotion& ground, const RockingOptions& options);

}  // namespace polydem::analytical
