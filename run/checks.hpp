// Verification checks a deck asks for ([[check]]), each comparing what the
// run measured with an exact or analytical result:
//   resting_weight       joint forces carrying block = m·g                 (N, relative tol)
//   no_drift             largest displacement of the block during the run  (m, absolute tol)
//   slide_acceleration   a = g(sin θ − cos θ·tan φ) down the slope          (m/s², relative tol)
//   stick                displacement down the slope when tan θ < tan φ     (m, absolute tol)
//   rocking_onset        a_g/g when the heel of the block first opens = b/h (-, relative tol)
//   housner_restitution  ω after/ω before each impact = 1 − (mR²/I0)(1 − cos 2α) (-, relative tol)
//   rocking_first_impact time from release to first impact, exact eq. 7    (s, relative tol)
//   energy_conservation  max |energy balance drift| / reference energy     (-, absolute tol)
//   energy_no_growth     max growth of mechanical energy beyond the load work / reference (-, absolute tol)
//   pulse_peak_rotation  peak rotation under a one-sine pulse against the rigid rocking body, eq. 7/10 (rad, relative tol)
// The slope is the base plane z = const under a gravity vector tilted by θ
// (the deck tilts gravity, which is exact and keeps the base axis-aligned).
// Rocking checks take the rocking plane from the block's initial tilt (free
// rocking) or the ground-motion direction (onset).
#pragma once

#include "core/byte_stream.hpp"
#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"

#include <memory>

namespace polydem {

struct CheckResult {
  std::string name;
  std::string unit;
  double measured = 0, expected = 0, tolerance = 0;
  bool passed = false;
  std::string note;
};

class CheckMonitor {
 public:
  virtual ~CheckMonitor() = default;
  // Called after every step.
  virtual void observe(const Simulation& sim) = 0;
  virtual CheckResult finish(const Simulation& sim) = 0;
  // Checkpoints: what observe() has accumulated. What the constructor took
  // from the scene at t = 0 is not saved: a restart builds the monitors on
  // the scene at t = 0 and then loads.
  virtual void save(ByteWriter& w) const = 0;
  virtual void load(ByteReader& r) = 0;
};

// Throws SceneError naming the check's deck line for a check that cannot be
// evaluated on this scene (unknown block, block not free, ...).
std::unique_ptr<CheckMonitor> make_check(const CheckSpec& check, const SceneSpec& spec, const Simulation& sim);

}  // namespace polydem
