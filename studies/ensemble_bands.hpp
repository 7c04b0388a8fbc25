// Bands from a grid of ensembles: the probability of damage, stones lost and
// collapse along an intensity axis, and the intensities at which it is 16,
// 50 and 84 % (docs/ensembles.md, "Bands along an intensity axis").
//
// A sweep with --replicas runs every point of its grid N times, perturbed
// (studies/ensemble.hpp). Along an intensity axis (say the pulse amplitude
// a_p) with the other axes fixed (a column: one pulse period T_p), each
// replica is one run at one intensity: the column is a multiple-stripe
// analysis, and the lognormal fragility of each outcome follows from Baker's
// binomial likelihood over all its replicas (analytical/fragility.hpp,
// fit_stripes):
//
//     P(outcome | x) = Φ( ln(x/θ) / β )
//
// θ is the intensity at which half the replicas reach the outcome (the 50 %
// boundary), θ·e^(−β) and θ·e^(β) those at 16 % and 84 % (the band). The
// outcomes are nested, as a replica's worst state (analytical::DamageState):
//   damage       not intact (damaged, stones lost or collapsed),
//   stones lost  a stone dislodged at the end, or collapsed,
//   collapse     collapsed.
// A replica without a verdict — undetermined (still moving at the end),
// unstable or in error — says nothing about any of them: it is left out and
// counted.
//
// The fit covers the column's points up to the first at which every replica
// reached the outcome: a fall above it (a Mode I region that closes before
// Mode II, a survival window) is another boundary, which fitted together
// with the first rise would only widen its band. `falls_back` names the
// first such point; the observed fractions show the rest.
//
// Where the data have no interior maximum of the likelihood there is no
// fit, and the column reports why (the status) and bounds instead: every
// replica of the column short of the outcome (none_reached: the 50 % point
// lies above the axis), every one reaching it (all_reached: below), or a
// boundary sharper than the grid (not_identified: the fractions step from
// none to all with at most one point between, where the likelihood grows
// as β → 0, or the optimiser's β falls outside [1e-4, 20]). In every case the observed fractions bracket
// the 50 % point: `below` is the largest axis value at which fewer than half
// the replicas reached the outcome under `above`, the smallest at which half
// or more did.
#pragma once

#include "analytical/fragility.hpp"
#include "studies/point_result.hpp"
#include "studies/sweep_grid.hpp"

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace polydem {

// The worst state a replica reached; nullopt when it has no verdict
// (undetermined, unstable, error).
std::optional<analytical::DamageState> replica_state(const PointResult& r);

// An outcome a band is fitted for: a replica reached `state` or a worse one.
struct BandOutcome {
  const char* name;  // "damage", "stones_lost", "collapse"
  analytical::DamageState state;
};
inline constexpr std::size_t kBandOutcomes = 3;
std::span<const BandOutcome> band_outcomes();

// The observed fraction of each outcome among the replicas of one point that
// have a verdict (`judged`); NaN when none has.
struct OutcomeFractions {
  long judged = 0;
  std::array<double, kBandOutcomes> p = {std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN()};
};
OutcomeFractions outcome_fractions(const std::vector<PointResult>& replicas);

struct OutcomeBand {
  const char* outcome = "";
  // fitted | none_reached | all_reached | not_identified (as
  // analytical::FitStatus) | no_runs (no replica of the column has a verdict)
  std::string status;
  double beta = std::numeric_limits<double>::quiet_NaN();
  // θ·e^(−β), θ, θ·e^(β): the intensity at P = 16, 50, 84 %; NaN unless fitted.
  double at16 = std::numeric_limits<double>::quiet_NaN();
  double at50 = std::numeric_limits<double>::quiet_NaN();
  double at84 = std::numeric_limits<double>::quiet_NaN();
  // The observed bracket of the 50 % point (NaN: none on that side).
  double below = std::numeric_limits<double>::quiet_NaN();
  double above = std::numeric_limits<double>::quiet_NaN();
  // Above the fit's range, the smallest value at which not every replica
  // reached the outcome again (NaN: none).
  double falls_back = std::numeric_limits<double>::quiet_NaN();
  long runs = 0;          // replicas with a verdict
  long reached = 0;       // of them, those that reached the outcome
  long undetermined = 0;  // left out: still moving at the end
  long failed = 0;        // left out: unstable or error
  // Fitted only: the largest |observed fraction − fitted P| over the
  // column's points (a step, or a column that is not monotone, shows here).
  double largest_gap = std::numeric_limits<double>::quiet_NaN();
};

struct ColumnBands {
  SweepPoint column;                 // its values of the column keys
  std::vector<OutcomeBand> outcomes;  // as band_outcomes()
};

// Groups the replicas `rows` (one per run) by their values of `column_keys`
// (columns in increasing order of them, the first key slowest) and fits each
// outcome along `axis_key`, whose values must be > 0 (std::invalid_argument
// otherwise).
std::vector<ColumnBands> fit_bands(const std::vector<std::string>& column_keys, const std::string& axis_key,
                                   const std::vector<std::pair<SweepPoint, PointResult>>& rows);

}  // namespace polydem
