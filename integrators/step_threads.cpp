#include "integrators/step_threads.hpp"

#include <omp.h>

#include <algorithm>

namespace polydem {

StepThreads make_step_threads(bool adaptive) {
  StepThreads t;
  t.governor = make_thread_governor(omp_get_max_threads(), adaptive);
  // One part per thread a step can take: the governor's all or, switched off, OpenMP's (never more).
  t.travel_parts.resize(static_cast<std::size_t>(std::max({1, t.governor.most, t.governor.now})));
  return t;
}

bool large_enough_for_threads(const StepThreads& t, std::size_t subcontacts, std::size_t free_blocks) {
  return subcontacts >= t.parallel_threshold || 16 * free_blocks >= t.parallel_threshold;
}

int threads_for_this_step(StepThreads& t, bool big) {
  const int threads = big ? threads_for_step(t.governor) : 1;
  // Inside a caller's parallel region the pause does nothing.
  if (threads == 1 && t.last_threads > 1) omp_pause_resource_all(omp_pause_soft);
  t.last_threads = threads;
  return threads;
}

bool detection_known_unneeded(StepThreads& t, double dt) {
  const bool known_clear = t.travel_clear && t.travel_dt == dt;
  t.travel_clear = false;
  return known_clear;
}

void settle_travel_test(StepThreads& t, const ContactDetector& detector, const Blocks& blocks, int threads,
                        double dt) {
  TravelBound all = t.travel_parts[0].bound;
  for (int k = 1; k < threads; ++k) merge_travels(all, t.travel_parts[static_cast<std::size_t>(k)].bound);
  if (!blocks.kinematic_blocks.empty()) detector.add_travels(blocks, blocks.kinematic_blocks, t.travel_ref, dt, all);
  Vec3 drift;
  t.travel_clear = detector.clearly_no_detection(all, t.travel_ref, drift);
  t.travel_ref = drift;
  t.travel_dt = dt;
}

}  // namespace polydem
