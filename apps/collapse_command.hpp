// `polydem collapse`: the collapse acceleration of a deck under a constant
// horizontal acceleration (paper section 3.2), found two ways for each
// direction asked:
//   bisection - runs at constant accelerations (rising over rise_time, then
//               held until the structure settles or collapses), halving the
//               bracket until it is narrower than the tolerance;
//   ramp      - one run under a slowly rising acceleration; the collapse
//               acceleration is the one at which a block first moves the
//               damage displacement (the mechanism has formed).
// Writes DIR/collapse.json and prints a table.
#pragma once

#include <string>
#include <vector>

namespace polydem {

struct CollapseOptions {
  std::string deck_path;
  bool use_default = false;
  std::string out_dir = "out/collapse";
  std::vector<double> directions_deg{0.0};  // azimuth of the ground motion, degrees from x
  std::string method = "both";              // bisection | ramp | both | static
  int static_increments = 4;                // static: load steps, ratio, steps per increment
  double static_ratio = 1e-4;
  long static_max_steps = 200000;
  bool density_scaling = false;
  double low_g = 0.05, high_g = 0.5;        // initial bracket
  double tolerance_g = 0.005;               // bracket width at which bisection stops
  double rise_time = 0.5;                   // s
  double hold_time = 2.5;                   // s after the rise
  double ramp_rate_g = 0.1;                 // g/s
  int threads = 0;
  bool quiet = false;
  std::vector<std::string> overrides;
};

int collapse_command(const CollapseOptions& options);

}  // namespace polydem
