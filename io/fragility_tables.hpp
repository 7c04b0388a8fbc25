// The files of `polydem analytic fragility` (docs/fragility.md): the runs it
// reads and the fitted curves it writes, as CSV, and the result as JSON.
#pragma once

#include "analytical/fragility.hpp"
#include "io/json.hpp"

#include <string>
#include <vector>

namespace polydem {

// The runs of a fragility input CSV: '#' lines and blank lines skipped; a
// header line naming the columns (any order, others ignored): `im` and
// `state` (intact, damaged, stones_lost, collapsed or 0-3), and `record`
// for IDA. `has_records` tells whether the record column was there. Runs of
// state `undetermined` are counted and left out. Throws
// std::runtime_error "FILE:LINE: what" on a missing column, a bad number or
// state, an IM that is not > 0, or a file without runs.
struct FragilityInput {
  std::vector<analytical::FragilityRun> runs;
  bool has_records = false;
  long undetermined = 0;  // runs of state `undetermined` (polydem ida), left out
};
FragilityInput read_fragility_runs(const std::string& path);
FragilityInput parse_fragility_runs(const std::string& text, const std::string& name);

// Writes DIR/fragility_parameters.csv, DIR/fragility_curves.csv and
// DIR/fragility_points.csv (creating DIR), each atomically.
void write_fragility_tables(const std::string& dir, const analytical::FragilityResult& r);

// Every number of the result: options, the IM grid, and per state its
// status, θ, β, their bands, the curves and the points.
Json fragility_json(const analytical::FragilityResult& r);

}  // namespace polydem
