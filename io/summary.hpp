// summary.json: what a run found, for people and for scripts (layout in
// docs/results.md). Written here and read back here (a sweep reads each
// point's summary), so that the two never drift apart.
#pragma once

#include "io/json.hpp"
#include "run/run_scene.hpp"
#include "studies/point_result.hpp"

#include <string>

namespace polydem {

// The summary of a run of `spec` on `threads` OpenMP threads.
Json summary_json(const SceneSpec& spec, const RunReport& report, int threads);
// The crack of an assessment into `j`: moved_blocks, opened_joints,
// crack_angle_deg, crack_lowest_z_m, crack_highest_z_m (null without a crack);
// shared by summary.json and collapse.json.
void set_crack(Json& j, const Assessment& a);
// The run's profile: seconds per stage of the step and of the run's output,
// each with its share of the total.
Json profile_json(const RunProfile& profile);
// DIR/summary.json, atomically (written last: its presence marks a finished run).
void write_summary(const std::string& dir, const SceneSpec& spec, const RunReport& report, int threads);

// Parses a summary.json text into what a study keeps of the run; `what`
// names it in messages. Throws std::runtime_error when it has no status.
PointResult point_result_from_summary(const std::string& summary_text, const std::string& what);
// DIR/summary.json as a PointResult; an empty status when it is missing or
// cannot be parsed (the point is run again).
PointResult read_point_result(const std::string& dir);

// results.h5: the deck verbatim with the polydem version, the histories and
// the energy ledger (docs/results.md).
void write_results_h5(const std::string& path, const SceneSpec& spec, const RunReport& report);

}  // namespace polydem
