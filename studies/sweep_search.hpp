// Boundary search: the damage and collapse thresholds of a deck along one key
// (the pulse amplitude a_p) for each point of an outer grid (the periods
// T_p), with far fewer runs than the full grid at the same resolution.
//
// For each column the search axis is a lattice START + (STOP − START)·k/K,
// K = round((STOP − START)/resolution). A coarse scan runs N lattice points;
// every pair of neighbours whose classes differ (intact, damaged, Mode I,
// Mode II, unstable, error) is then bisected on the lattice. A bisection
// point of a third class splits its interval in two and both halves go on,
// so every change of class the coarse scan brackets is found — collapse is
// not monotone in a_p: the Mode I loop (collapse at low amplitude, survival
// above it, Mode II higher still) shows as collapse → damage → collapse.
// A change of class that starts and ends between two coarse points is not
// seen: the coarse step must be finer than the narrowest loop sought.
//
// The search runs in rounds: the coarse scan of every column is one batch,
// then each round is one batch holding the midpoints of every open interval
// of every column, so local processes or MPI ranks stay busy.
#pragma once

#include "studies/sweep_grid.hpp"
#include "studies/point_result.hpp"

#include <functional>
#include <string>
#include <vector>

namespace polydem {

struct SearchAxis {
  std::string key;
  double start = 0, stop = 0;
  long coarse = 0;          // points of the coarse scan, ends included
  double resolution = 0;    // lattice step asked for (the actual one divides the range evenly)
  long lattice_points() const;  // K + 1
  double value(long k) const;
};

// Parses "KEY=START:STOP:N" for --search; throws std::invalid_argument.
SearchAxis parse_search_axis(const std::string& arg, double resolution);

struct Transition {
  double below = 0, above = 0;  // neighbouring lattice values with different classes
  std::string from, to;         // class at below, at above
};

struct ColumnResult {
  SweepPoint outer;                                      // the column's values of the --vary keys
  std::vector<std::pair<double, PointResult>> runs;      // by value of the search key
  std::vector<Transition> transitions;                   // in order of the search key
  // Smallest value of the search key that is not intact / that lost a stone
  // or collapsed ("first stones lost") / that collapsed (NaN: none in the
  // range; START: already at START).
  double damage_threshold = 0, stones_threshold = 0, collapse_threshold = 0;
  std::string collapse_mode;  // of the run at collapse_threshold
  double wall_seconds = 0;    // Σ of its runs' own times
};

struct SearchReport {
  std::vector<ColumnResult> columns;
  long runs = 0;        // distinct points evaluated (finished earlier or now)
  long full_grid = 0;   // runs of the full grid at the same resolution
  int rounds = 0;
};

using BatchRunner = std::function<std::vector<PointResult>(const std::vector<SweepPoint>&)>;

SearchReport boundary_search(const std::vector<SweepPoint>& outer, const SearchAxis& axis, const BatchRunner& run);

}  // namespace polydem
