#include "studies/ensemble_bands.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace polydem {

namespace {

using analytical::DamageState;

constexpr BandOutcome kOutcomes[kBandOutcomes] = {
    {"damage", DamageState::damaged},
    {"stones_lost", DamageState::stones_lost},
    {"collapse", DamageState::collapsed},
};

// The 50 % bracket from the observed fractions (points in increasing order).
void bracket(OutcomeBand& band, const std::vector<analytical::FragilityPoint>& points) {
  std::size_t first_half = points.size();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (2 * points[i].reached >= points[i].runs) {
      first_half = i;
      break;
    }
  if (first_half < points.size()) band.above = points[first_half].im;
  for (std::size_t i = first_half; i-- > 0;)
    if (2 * points[i].reached < points[i].runs) {
      band.below = points[i].im;
      break;
    }
}

// A step at most one point wide: the fractions rise from all-nothing to
// all-reached with at most one point between. The likelihood then grows
// without bound as β → 0 (θ slides to that point): a boundary sharper than
// the grid, which a finite β from the optimiser would only pretend to measure.
bool step_within_one_point(const std::vector<analytical::FragilityPoint>& points) {
  int partial = 0;
  double last = 0.0;
  for (const analytical::FragilityPoint& p : points) {
    const double f = static_cast<double>(p.reached) / p.runs;
    if (f < last) return false;
    if (p.reached > 0 && p.reached < p.runs) ++partial;
    last = f;
  }
  return partial <= 1;
}

// The column's points for one outcome, in increasing order of the axis.
std::vector<analytical::FragilityPoint> points_of(const std::vector<analytical::FragilityRun>& runs,
                                                  DamageState state) {
  std::map<double, analytical::FragilityPoint> by_value;
  for (const analytical::FragilityRun& r : runs) {
    analytical::FragilityPoint& p = by_value.try_emplace(r.im, analytical::FragilityPoint{"", r.im, 0, 0}).first->second;
    ++p.runs;
    p.reached += r.state >= state ? 1 : 0;
  }
  std::vector<analytical::FragilityPoint> points;
  for (const auto& [x, p] : by_value) points.push_back(p);
  return points;
}

OutcomeBand band_of(const std::vector<analytical::FragilityRun>& runs, std::size_t index) {
  const BandOutcome& outcome = kOutcomes[index];
  const std::vector<analytical::FragilityPoint> points = points_of(runs, outcome.state);
  OutcomeBand band;
  band.outcome = outcome.name;
  for (const analytical::FragilityPoint& p : points) band.runs += p.runs, band.reached += p.reached;
  bracket(band, points);
  // The fit's range: up to the first point at which every replica reached
  // the outcome. A fall above it is another boundary (a Mode I region that
  // closes before Mode II): fitted with the rise, it would widen the band
  // of the first.
  double top = std::numeric_limits<double>::infinity();
  for (const analytical::FragilityPoint& p : points) {
    if (p.im > top && p.reached < p.runs) {
      band.falls_back = p.im;
      break;
    }
    if (p.reached == p.runs && p.im < top) top = p.im;
  }
  std::vector<analytical::FragilityRun> range;
  for (const analytical::FragilityRun& r : runs)
    if (r.im <= top) range.push_back(r);
  analytical::FragilityOptions options;
  options.method = analytical::FragilityMethod::stripes;
  options.bootstrap = 0;
  options.points = 2;
  const analytical::FragilityCurveFit fit = analytical::fit_fragility(range, options).states[index];
  band.status = analytical::to_string(fit.status);
  if (fit.status != analytical::FitStatus::fitted) return band;
  if (step_within_one_point(fit.points)) {
    band.status = analytical::to_string(analytical::FitStatus::not_identified);
    return band;
  }
  const double theta = fit.curve.theta, beta = fit.curve.beta;
  band.beta = beta;
  band.at16 = theta * std::exp(-beta);
  band.at50 = theta;
  band.at84 = theta * std::exp(beta);
  band.largest_gap = 0.0;
  for (const analytical::FragilityPoint& p : fit.points) {
    const double observed = static_cast<double>(p.reached) / p.runs;
    band.largest_gap = std::max(band.largest_gap, std::fabs(observed - analytical::fragility_probability(fit.curve, p.im)));
  }
  return band;
}

}  // namespace

std::optional<DamageState> replica_state(const PointResult& r) {
  if (r.status == "intact") return DamageState::intact;
  if (r.status == "collapsed") return DamageState::collapsed;
  if (r.status == "damaged") return r.dislodged > 0 ? DamageState::stones_lost : DamageState::damaged;
  return std::nullopt;
}

std::span<const BandOutcome> band_outcomes() { return kOutcomes; }

OutcomeFractions outcome_fractions(const std::vector<PointResult>& replicas) {
  OutcomeFractions f;
  std::array<long, kBandOutcomes> reached{};
  for (const PointResult& r : replicas) {
    const std::optional<DamageState> s = replica_state(r);
    if (!s) continue;
    ++f.judged;
    for (std::size_t i = 0; i < kBandOutcomes; ++i) reached[i] += *s >= kOutcomes[i].state ? 1 : 0;
  }
  if (f.judged > 0)
    for (std::size_t i = 0; i < kBandOutcomes; ++i) f.p[i] = static_cast<double>(reached[i]) / f.judged;
  return f;
}

std::vector<ColumnBands> fit_bands(const std::vector<std::string>& column_keys, const std::string& axis_key,
                                   const std::vector<std::pair<SweepPoint, PointResult>>& rows) {
  struct Column {
    std::vector<analytical::FragilityRun> runs;
    long undetermined = 0, failed = 0;
  };
  std::map<std::vector<double>, Column> columns;
  for (const auto& [point, result] : rows) {
    const double x = value_of(point, axis_key);
    if (!(x > 0.0) || !std::isfinite(x))
      throw std::invalid_argument("bands along " + axis_key + " need its values finite and > 0");
    std::vector<double> at;
    for (const auto& key : column_keys) at.push_back(value_of(point, key));
    Column& c = columns[at];
    if (const std::optional<DamageState> s = replica_state(result))
      c.runs.push_back({"", x, *s});
    else if (result.status == "undetermined")
      ++c.undetermined;
    else
      ++c.failed;
  }

  std::vector<ColumnBands> out;
  for (const auto& [at, c] : columns) {
    ColumnBands bands;
    for (std::size_t k = 0; k < column_keys.size(); ++k) bands.column.values.emplace_back(column_keys[k], at[k]);
    for (std::size_t i = 0; i < kBandOutcomes; ++i) {
      OutcomeBand band;
      if (c.runs.empty()) {
        band.outcome = kOutcomes[i].name;
        band.status = "no_runs";
      } else {
        band = band_of(c.runs, i);
      }
      band.undetermined = c.undetermined;
      band.failed = c.failed;
      bands.outcomes.push_back(std::move(band));
    }
    out.push_back(std::move(bands));
  }
  return out;
}

}  // namespace polydem
