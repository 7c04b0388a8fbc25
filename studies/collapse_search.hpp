// The collapse acceleration of a scene under a constant horizontal
// acceleration (paper section 3.2), found two ways for a direction:
//   bisection - runs at constant accelerations (rising over rise_time, then
//               held for hold_time or until the structure collapses),
//               halving the bracket until it is narrower than the tolerance;
//   ramp      - one run under a slowly rising acceleration; the collapse
//               acceleration is the one at which a block first moves the
//               damage displacement (the mechanism has formed);
//   static    - bisection too, but each trial is a static solve, as 3DEC's
//               `model solve` (run/equilibrium.hpp): Cundall's local damping,
//               the body load g tilted by λ·|g| horizontally (the static
//               equivalent of a constant ground acceleration λ g), applied in
//               `static_increments` equal steps, each solved until the
//               unbalanced-force ratio falls below `static_ratio`. The trial
//               stands when the last increment is solved; it collapses when
//               the blocks fallen (or, at its end, dislodged) beyond the
//               deck's collapse_displacement make up its
//               collapse_mass_fraction, or when an increment finds no
//               equilibrium in `static_max_steps` steps while a mechanism is
//               under way; an increment without equilibrium and with nothing
//               moving away stops the search (`no_equilibrium`, below).
//               Collapse under a constant acceleration is a quasi-static
//               question: no rise time to choose, no hold time to wait out.
// Each trial is the caller's scene with its ground motion, end time and
// output edited field by field (no deck text is parsed again): the
// histories and the energy ledger are off and the run stops once collapse
// is certain (run/assessment.hpp). A dynamic trial collapses when the run
// says so, or when it ends still moving with the collapse fraction of the
// free mass away from its place: under a held acceleration nothing brings it
// back.
#pragma once

#include "run/run_scene.hpp"

#include <functional>
#include <string>

namespace polydem {

struct CollapseSearchOptions {
  double low_g = 0.05, high_g = 0.5;  // initial bracket
  double tolerance_g = 0.005;         // bracket width at which bisection stops
  double rise_time = 0.5;             // s
  double hold_time = 2.5;             // s after the rise
  double ramp_rate_g = 0.1;           // g/s; the ramp runs up to 1.2·high_g
  // static: load increments, the unbalanced-force ratio that counts as
  // solved, the steps an increment may take, Cundall's α.
  int static_increments = 4;
  double static_ratio = 1e-4;
  long static_max_steps = 200000;
  double local_damping = 0.8;
  // Density scaling in the static solves (Simulation::begin_static_stage):
  // every block vibrates at the step's frequency, so heavy blocks settle
  // (or show their mechanism) in fewer steps.
  bool density_scaling = false;
  int threads = 0;
};

struct CollapseTrial {
  double direction_deg = 0;
  double acceleration_g = 0;  // constant: the trial's; ramp: at the mechanism (NaN: none)
  bool collapsed = false;
  long steps = 0;
  double wall_seconds = 0;
  Assessment assessment;
  // Static: an increment found no equilibrium in static_max_steps. A
  // collapse if a mechanism is under way (the fastest block moving faster
  // than settle_velocity, 1 mm/s when unset, and displaced more than
  // damage_displacement); otherwise neither collapse nor stand: the search
  // stops and says so. `no_equilibrium_detail` names the block whose
  // unbalanced force or moment is the largest and the fastest one.
  bool no_equilibrium = false;
  std::string no_equilibrium_detail;
};

// Called after every trial run (progress output); may be empty.
using TrialObserver = std::function<void(const char* method, const CollapseTrial&)>;

struct BisectionResult {
  std::string error;                  // the bracket does not contain the collapse acceleration, or a static
                                      // trial found no equilibrium (low_g/high_g: the bracket reached)
  double collapse_g = 0;              // the bracket's midpoint at the end
  double low_g = 0, high_g = 0;       // the final bracket
  CollapseTrial last_collapse;        // the run at high_g (its crack)
  int runs = 0;
  double wall_seconds = 0;            // Σ of the runs
};

// The scene under a constant acceleration a_g (in g) along azimuth `deg`
// (degrees from x), rising over rise_time and held for hold_time.
SceneSpec constant_acceleration_scene(SceneSpec scene, double deg, double a_g, double rise_time, double hold_time);
// The scene under a ramp of rate_g (g/s) along `deg`, up to a_max_g.
SceneSpec ramp_scene(SceneSpec scene, double deg, double rate_g, double a_max_g);

BisectionResult bisect_collapse(const SceneSpec& scene, double deg, const CollapseSearchOptions& options,
                                const TrialObserver& observe = {});
// One static trial (see above) at a_g along `deg`.
CollapseTrial static_collapse_trial(const SceneSpec& scene, double deg, double a_g, const CollapseSearchOptions& options);
BisectionResult bisect_collapse_static(const SceneSpec& scene, double deg, const CollapseSearchOptions& options,
                                       const TrialObserver& observe = {});
CollapseTrial ramp_collapse(const SceneSpec& scene, double deg, const CollapseSearchOptions& options,
                            const TrialObserver& observe = {});

}  // namespace polydem
