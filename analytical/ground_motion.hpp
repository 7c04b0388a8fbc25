#pragma once
// Horizontal ground acceleration a_g(t) = ü_g for the rocking models
// (positive a_g pushes the block's θ negative, eq. 7).

#include <functional>
#include <limits>
#include <vector>

namespace polydem::analytical {

struct GroundMotion {
  std::function<double(double)> acceleration;  // a_g(t) [m/s²]
  // a_g(t) = 0 for every t > quiet_after [s]; lets a run stop once the block
  // is at rest or can no longer gain the energy to overturn.
  double quiet_after = std::numeric_limits<double>::infinity();
  // Smallest time > t where a_g or its derivatives jump (pulse start and end,
  // record samples), +inf if none. The integrator ends its steps there: a
  // step across a kink would cut RK4 down to first or second order.
  std::function<double(double)> next_breakpoint;
};

// a_g(t) = a for t ≥ 0 (paper 3.2: constant acceleration).
GroundMotion constant_ground_motion(double a);

// One-sine pulse a_p sin(2π t / T_p) for 0 ≤ t ≤ T_p, zero after
// (Zhang & Makris 2001; paper 3.3, Fig. 5 and 7b).
GroundMotion sine_pulse_ground_motion(double a_p, double T_p);

// Record sampled every dt from t = 0, linear between samples, zero after.
GroundMotion sampled_ground_motion(double dt, std::vector<double> samples);

}  // namespace polydem::analytical
