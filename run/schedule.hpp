// Periodic outputs of a run (histories, snapshots, checkpoints): one small
// scheduler instead of a `next += interval` per output.
//
// An event is due when the time it is asked about has reached `next` (less
// a tolerance of 1e-12 of the run's end time, so that 0.1 + 0.1 + 0.1 still
// meets 0.3). After it fires, advance() moves `next` on by one interval
// (histories and snapshots: a step that skips past two outputs fires once
// per step until it has caught up, as the run always did), or skip_past()
// moves it beyond the current time (checkpoints: one per step at most).
// interval 0 means "every time it is asked" for histories; an event with
// `enabled` false is never due.
//
// The guard is not scheduled here: it checks the state every 256 steps
// inside Simulation::step() (integrators/simulation.hpp), because a failed
// check must put the last good state back before any output sees the bad
// one. The assessment and the energy checks sample every 16th and 8th step
// for cost, by step count, not by time.
#pragma once

namespace polydem {

struct Periodic {
  bool enabled = false;
  double interval = 0;   // s
  double next = 0;       // s, the time of the next event
  double tolerance = 0;  // s

  static Periodic every(double interval, double first, double end_time, bool enabled = true) {
    return Periodic{enabled, interval, first, 1e-12 * end_time};
  }
  bool due(double t) const { return enabled && t >= next - tolerance; }
  void advance() { next += interval > 0 ? interval : 0.0; }
  // The time of the last event is behind t: the end of a run writes one
  // more snapshot only if time has passed since the last.
  bool passed_last(double t) const { return enabled && t > next - interval + tolerance; }
  void skip_past(double t) {
    while (next <= t + tolerance) next += interval;
  }
};

}  // namespace polydem
