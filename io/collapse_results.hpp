// DIR/collapse.json of `polydem collapse`: per direction the bisection's and
// the ramp's collapse acceleration, runs, wall time and crack (layout in
// docs/results.md), and the lowest collapse acceleration over directions.
#pragma once

#include "studies/collapse_search.hpp"

#include <optional>
#include <string>
#include <vector>

namespace polydem {

struct CollapseDirection {
  double direction_deg = 0;
  std::optional<BisectionResult> bisection;
  std::optional<CollapseTrial> ramp;
};

struct CollapseStudy {
  std::string deck;    // the deck's path (or the default deck's name)
  std::string method;  // bisection | ramp | both
  double tolerance_g = 0, ramp_rate_g = 0;
  std::vector<CollapseDirection> directions;
  // The lowest collapse acceleration over directions (the bisection's where
  // it has one, else the ramp's); NaN when none.
  double lowest_g() const;
};

void write_collapse_json(const std::string& path, const CollapseStudy& study);

}  // namespace polydem
