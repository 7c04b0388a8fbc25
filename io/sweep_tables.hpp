// The result tables of a sweep (layout in docs/results.md):
//   DIR/sweep.csv        one row per point: the varied values, status,
//                        collapse mode, peak tip displacement, run time, ...
//   DIR/boundaries.csv   boundary search only: one row per column, the
//                        damage and collapse thresholds and every transition
//   DIR/sweep.h5         both tables as datasets with units, and the deck
// All three are written atomically and rewritten after every batch, so an
// interrupted sweep leaves tables of what had finished.
#pragma once

#include "studies/point_result.hpp"
#include "studies/sweep_grid.hpp"
#include "studies/sweep_search.hpp"

#include <string>
#include <vector>

namespace polydem {

struct SweepRow {
  SweepPoint point;
  PointResult result;
  std::string id;  // the point's directory name under DIR/points
};

struct SweepTables {
  std::vector<std::string> keys;  // varied keys, the search key last
  std::vector<SweepRow> rows;
  const SearchReport* search = nullptr;  // boundary search only
  const SearchAxis* axis = nullptr;
  std::string deck_text;
  std::string deck_path;
};

void write_sweep_tables(const std::string& out_dir, const SweepTables& t);

// A number in a CSV cell: its shortest round-trip text, empty for "none" (NaN).
std::string csv_number(double x);

// The text a CSV cell / the tables use for transitions: "0.61:intact>damaged;0.86:damaged>I"
// (each the first value of the new class).
std::string transitions_text(const std::vector<Transition>& transitions);

}  // namespace polydem
