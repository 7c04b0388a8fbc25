// Incremental dynamic analysis (IDA) and multiple-stripe analysis of a deck
// under the records of a suite (core/record_suite.hpp).
//
// Each run is the deck with its ground motion replaced by one record of the
// suite (every component with its direction and suite scale, times one
// factor) and the IM is a number per record: its peak ground acceleration
// or its 5 %-damped pseudo-spectral acceleration Sa(T₁) (in g =
// 9.80665 m/s², the records' g), of its horizontal components (their
// geometric mean when there are two). A run at intensity x scales the
// record by x / IM(record).
//
// IDA by hunt-and-fill (Vamvatsikos & Cornell 2002, "Incremental dynamic
// analysis", section 5): for each record
//   - hunt: IMs x₁ = first, x_{k+1} = x_k + step + (k − 1)·growth, until the
//     first run that collapses;
//   - bracket: the gap between the highest IM that did not collapse below
//     it (0 if none) and the lowest that did is bisected until it is
//     narrower than the tolerance;
//   - fill: the runs left of the record's budget go to the midpoints of the
//     widest gaps between the IMs run below the collapse (0 included), while
//     a gap is wider than the tolerance.
// A record that has not collapsed when its budget is spent is censored at
// its largest IM. The records advance together: each round is one batch
// holding the next run of every record still searching, so local processes
// or MPI ranks stay busy (the rounds are the sweep's: studies/sweep_search.hpp's
// BatchRunner). The IMs depend only on the runs' outcomes, so the search is
// the same whatever runs them.
//
// A multiple-stripe analysis runs every record at each of a few IMs; a
// fixed-factor IDA every record at each of a few scale factors.
//
// A run's damage state (damage_state) is the worst it reached: intact,
// damaged, stones_lost (a stone dislodged, no collapse), collapsed, or
// undetermined (a run whose assessment could not decide, or unstable or
// failed runs): the fragility fit leaves undetermined runs out.
#pragma once

#include "core/record_suite.hpp"
#include "core/scene_spec.hpp"
#include "studies/point_result.hpp"
#include "studies/sweep_search.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace polydem {

enum class IntensityMeasure { pga, sa };

struct IntensitySpec {
  IntensityMeasure measure = IntensityMeasure::pga;
  double period = 0.0;    // T₁, s (Sa only), > 0
  double damping = 0.05;  // ξ (Sa only), in [0, 1)
  std::string name() const;  // "pga" or "sa(1.2 s, 5 %)"
};

// The IM of the record as the suite gives it (its components' suite scales
// applied), in g. Throws std::invalid_argument when the record has no
// horizontal component (direction with z = 0) or its IM is not > 0.
double record_intensity(const SuiteRecord& record, const IntensitySpec& im);

// The deck's ground motion replaced by the record: one override
// "ground_motion={...}" (a TOML inline table) holding every component (the
// first as the section's own, the others as [[ground_motion.component]]),
// with the suite's baseline correction and time scaling, and the deck's
// applied_as, start time and tower filter kept from `deck`. The factor
// goes in the point's values (record_point).
std::string record_motion_override(const SuiteRecord& record, const RecordSuite& suite, const GroundMotionSpec& deck);

// The run of `record` scaled by `factor`: the override above as the point's
// fixed part, then each component's scale (factor × suite scale) as
// ground_motion.scale, ground_motion.component[k].scale.
SweepPoint record_point(const SuiteRecord& record, const std::string& motion_override, double factor);

// intact | damaged | stones_lost | collapsed | undetermined, from what a
// study keeps of a run. The one place that maps a run's assessment to a
// damage state.
std::string damage_state(const PointResult& r);
int damage_rank(const std::string& state);  // 0-3, -1 for undetermined

struct HuntAndFill {
  double first = 0.05;      // IM of the first run, g
  double step = 0.05;       // the hunt's first increment
  double growth = 0.05;     // added to the increment at each further step
  double tolerance = 0.01;  // the collapse bracket and the fill stop below this width
  long max_runs = 12;       // per record
};

struct IdaRun {
  double im = 0;      // g
  double factor = 0;  // the record's scale factor (im / record IM)
  PointResult result;
  std::string state;  // damage_state(result)
};

struct IdaRecord {
  std::string name;
  double record_im = 0;     // IM of the record as the suite gives it
  std::vector<IdaRun> runs;  // by IM
  // The lowest IM run that reached each state (NaN: none did).
  double damage_im = std::numeric_limits<double>::quiet_NaN();
  double stones_im = std::numeric_limits<double>::quiet_NaN();
  double collapse_im = std::numeric_limits<double>::quiet_NaN();
  // The highest IM below collapse_im that did not collapse (0: none run);
  // without a collapse, the largest IM run (where the record is censored).
  double below_collapse_im = 0;
  long undetermined = 0;  // runs whose state is undetermined
};

struct IdaReport {
  std::vector<IdaRecord> records;
  long runs = 0;
  int rounds = 0;
};

// The run of record r at IM x (r indexes the records).
using IdaPointOf = std::function<SweepPoint(std::size_t record, double im, double factor)>;

// Called after each round with the report so far (e.g. to write the tables).
using IdaProgress = std::function<void(const IdaReport&)>;

// Hunt-and-fill for every record (names and IMs as given), through `run`.
// Throws std::invalid_argument for settings that are not > 0 (max_runs ≥ 1).
IdaReport hunt_and_fill(const std::vector<std::string>& names, const std::vector<double>& record_ims,
                        const HuntAndFill& settings, const IdaPointOf& point_of, const BatchRunner& run,
                        const IdaProgress& after_round = {});

// Every record at every IM of `ims` (stripes) or, with `factors`, at every
// scale factor: one batch.
IdaReport run_stripes(const std::vector<std::string>& names, const std::vector<double>& record_ims,
                      const std::vector<double>& ims, bool factors, const IdaPointOf& point_of,
                      const BatchRunner& run);

}  // namespace polydem
