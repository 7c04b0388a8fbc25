#pragma once
// Overturning of a rocking body under one-sine acceleration pulses
// a_g = a_p sin(2π t / T_p), 0 ≤ t ≤ T_p (Zhang & Makris 2001; paper 3.3,
// Fig. 5 and 7b).
//
// Collapse is not monotone in a_p: for a given T_p there is usually a closed
// Mode I region (overturning after one impact) at lower amplitudes, safe
// amplitudes above it, and Mode II (overturning without impact) from some
// higher amplitude on. So each column (one T_p) is a coarse scan of a_p
// followed by bisection of every change of outcome between neighbours; the
// transitions are then accurate to tolerance_g, but a region thinner than the
// coarse spacing can be missed.

#include <limits>
#include <utility>
#include <vector>

#include "analytical/rocking_body.hpp"
#include "analytical/rocking_response.hpp"

namespace polydem::analytical {

struct CollapseScanOptions {
  double a_min_g = -1.0;      // lowest a_p/g scanned; < 0 means tan α (no uplift below)
  double a_max_g = 8.0;       // highest a_p/g scanned
  int coarse_points = 80;     // scan points between a_min_g and a_max_g
  double tolerance_g = 1e-4;  // width of each bisected transition, in a_p/g
  double steps_per_pulse = 400.0;  // RK4 step = min(T_p, 2π/p) / steps_per_pulse
  double free_periods = 10.0;      // run at most T_p + free_periods·2π/p after the pulse starts
  RockingForm form = RockingForm::nonlinear;
  double g = standard_gravity;
  std::optional<double> restitution;  // default: the body's eq. 10 value
  OverturnRule overturn = OverturnRule::past_alpha;  // rocking_response.hpp
};

struct CollapseTransition {
  double a_g = 0.0;  // a_p/g where the outcome changes
  CollapseMode below = CollapseMode::none, above = CollapseMode::none;
};

struct CollapseColumn {
  double T_p = 0.0;          // [s]
  double omega_ratio = 0.0;  // ω_p / p = 2π / (T_p p)
  std::vector<CollapseTransition> transitions;  // increasing a_g
  double min_collapse_g = std::numeric_limits<double>::quiet_NaN();  // lowest a_p/g that overturns
  double mode2_boundary_g = std::numeric_limits<double>::quiet_NaN();  // start of the Mode II run reaching a_max_g
  std::vector<std::pair<double, double>> mode1_intervals;  // Mode I regions [lo, hi] in a_p/g
};

// Outcome of one pulse (a_p/g, T_p) on `body`.
RockingResult pulse_response(const RockingBody& body, double a_p_g, double T_p, const CollapseScanOptions& opt);

CollapseColumn collapse_column(const RockingBody& body, double T_p, const CollapseScanOptions& opt);

std::vector<CollapseColumn> collapse_diagram(const RockingBody& body, const std::vector<double>& T_p_values,
                                             const CollapseScanOptions& opt);

}  // namespace polydem::analytical
