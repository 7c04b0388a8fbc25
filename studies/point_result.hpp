// What a study keeps of one run: its class (intact, damaged, Mode I or II
// collapse, unstable, error) and the few figures the tables show. io/summary
// reads it from a run's summary.json; studies/sweep_search tells classes
// apart with it.
#pragma once

#include "run/walking.hpp"

#include <limits>
#include <string>
#include <vector>

namespace polydem {

// What the sweep keeps of one run (io/summary.hpp reads it from summary.json).
struct PointResult {
  std::string status;         // intact | damaged | collapsed | undetermined | unstable | error
  std::string collapse_mode;  // I | II | "" (not collapsed)
  double peak_tip_displacement = 0;  // m, the monitor block's largest displacement along the motion
  double peak_displacement = 0;      // m, the largest of any block during the run
  double residual_displacement = 0;  // m, largest at the end
  double collapse_time = -1;         // s, -1 when not collapsed
  double damage_time = -1;           // s, -1 when never damaged
  int dislodged = 0;                 // stones lost: ending beyond collapse_displacement (assessment.dislodged.count)
  // Read for ensembles (studies/ensemble.hpp); NaN when the summary has none:
  // a_g at the first damage (the mechanism's acceleration under a ramp), in g,
  // and with output.walking the largest and the residual bed and vertical
  // joint openings, m.
  double ground_acceleration_at_damage_g = std::numeric_limits<double>::quiet_NaN();
  double max_bed_opening = std::numeric_limits<double>::quiet_NaN();
  double max_vertical_opening = std::numeric_limits<double>::quiet_NaN();
  double residual_bed_opening = std::numeric_limits<double>::quiet_NaN();
  double residual_vertical_opening = std::numeric_limits<double>::quiet_NaN();
  std::vector<CourseWalking> courses;  // with output.walking: per course from the bottom (run/recorder.hpp)
  double wall_seconds = 0;           // of the run itself
  long steps = 0;
  int exit_code = 0;     // of `polydem run` (0 ok, 1 check failed, 2 bad input, 3 unstable)
  bool reused = false;   // found finished on disk: a resumed sweep did not run it again
  std::string message;   // for unstable and error: why
  std::string directory; // DIR/points/<id>

  // The class a boundary search tells apart: intact, damaged, stones
  // (damaged, with stones lost but no collapse), I, II, unstable or error.
  std::string klass() const {
    if (status == "collapsed") return collapse_mode.empty() ? "collapsed" : collapse_mode;
    if (status == "damaged" && dislodged > 0) return "stones";
    return status;
  }
};

}  // namespace polydem
