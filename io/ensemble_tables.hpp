// The tables of an ensemble (layout in docs/ensembles.md):
//   DIR/replicas.csv   one row per replica: its number and seed, what was
//                      drawn, the outcome (status, mode, the measured figures)
//   DIR/ensemble.csv   the distributions: the count of each status and
//                      collapse mode, and the 16th, 50th and 84th percentiles
//                      of each outcome (one row; `polydem sweep --replicas`
//                      writes one row per point of its grid, ensembles.csv)
//   DIR/courses.csv    (decks with output.walking) per point and course,
//                      the distributions of its joints' openings
//   DIR/bands.csv      (sweep --replicas --band-axis) per column of the grid
//                      and outcome, the lognormal fit along the axis: the
//                      axis values at 16, 50 and 84 %, β, the counts
// Neither holds a run time, so the same seed gives the same files bit for
// bit on any number of workers; both are written atomically.
#pragma once

#include "io/json.hpp"
#include "studies/ensemble.hpp"
#include "studies/ensemble_bands.hpp"
#include "studies/point_result.hpp"
#include "studies/sweep_grid.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace polydem {

struct ReplicaRow {
  long replica = 0;
  std::uint64_t seed = 0;
  EnsembleDraw drawn;
  PointResult result;
  std::string id;  // the replica's directory name under DIR/points
};

std::string replicas_csv(const std::vector<ReplicaRow>& rows);

// One row of distributions per point: the point's values of `keys` (none
// for a lone ensemble) and the summary of its replicas.
struct EnsemblePoint {
  SweepPoint point;
  EnsembleOutcome outcome;
  OutcomeFractions fractions;
};
// With `fractions`, each row ends with `judged` (the replicas with a verdict)
// and the observed p_damage, p_stones_lost, p_collapse among them.
std::string ensemble_csv(const std::vector<std::string>& keys, const std::vector<EnsemblePoint>& points,
                         bool fractions = false);

// With output.walking: one row per point and course (from the bottom):
// the point's values of `keys`, course, level_m, bed_joints,
// vertical_joints and, per course_quantities(), its n, p16, median and p84
// over the replicas. Empty when no point has courses.
std::string courses_csv(const std::vector<std::string>& keys, const std::vector<EnsemblePoint>& points);

// One row per column and outcome (studies/ensemble_bands.hpp): the column's
// values of `column_keys`, the outcome, the fit's status, <axis>_16, _50,
// _84, beta, <axis>_below, _above, _falls_back, runs, reached,
// undetermined, failed, largest_gap (layout in docs/ensembles.md).
std::string bands_csv(const std::vector<std::string>& column_keys, const std::string& axis_key,
                      const std::vector<ColumnBands>& bands);

// The outcome as JSON: replicas, status_counts, collapse_modes and, per
// quantity, {n, p16, median, p84} (null where no replica measured it).
Json outcome_json(const EnsembleOutcome& outcome);

// Groups the rows of a sweep with an ensemble.replica axis by their values
// of `keys` (the other axes; groups in increasing order of them, the first
// key slowest) and summarises each group.
std::vector<EnsemblePoint> ensemble_points(const std::vector<std::string>& keys,
                                           const std::vector<std::pair<SweepPoint, PointResult>>& rows);

}  // namespace polydem
