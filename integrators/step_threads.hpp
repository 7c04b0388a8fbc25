// How the step uses its threads.
//
// One parallel region per step (a region costs more than a barrier). Small
// scenes stay on one thread, detections included, where a parallel region
// costs more than it saves: a step runs in parallel only with at least
// `parallel_threshold` subcontacts (or a sixteenth as many free blocks). The
// thread governor (thread_governor.hpp) picks all threads or one for each
// step: a competing process on a core makes the threads wait at every
// barrier. Results are the same bits on any number of threads.
//
// The half-margin test (contact/detection.hpp TravelBound) is gathered by
// the step's threads: each bounds the travels of the blocks it has just
// moved, while it holds them, and the parts merge at the step's end; the
// next step skips the test's serial passes over every block when the
// bound is clear.
#pragma once

#include "contact/detection.hpp"
#include "core/blocks.hpp"
#include "integrators/thread_governor.hpp"

#include <vector>

namespace polydem {

struct StepThreads {
  std::size_t parallel_threshold = 2048;
  ThreadGovernor governor;
  int last_threads = 0;  // threads of the last step (0: none yet)
  struct alignas(64) TravelPart {
    TravelBound bound;
  };
  std::vector<TravelPart> travel_parts;  // one per thread, each in its own cache line
  Vec3 travel_ref = Vec3::Zero();        // the drift travels are taken from
  bool travel_clear = false;             // the last step's end settled the next step's test
  double travel_dt = 0;                  // ... for a step of this length
};

// Threads OpenMP gives the run; the governor enabled as the deck says.
StepThreads make_step_threads(bool adaptive);

// Whether a scene this size runs its step on more than one thread.
bool large_enough_for_threads(const StepThreads& t, std::size_t subcontacts, std::size_t free_blocks);

// Threads for the step about to run (`big`: the scene is large enough). Going
// down from all threads to one releases the idle threads first: with
// libgomp's default wait policy they spin for milliseconds after a region,
// taking the core from a competitor and through it from this thread.
int threads_for_this_step(StepThreads& t, bool big);

// True when the last step settled that no detection is needed before a
// step of length `dt`; either way the settlement is used up.
bool detection_known_unneeded(StepThreads& t, double dt);

// The threads' parts of the half-margin test in thread order, the
// kinematic blocks (moved after the threads) added; clear only when the
// test itself would answer no (ContactDetector::clearly_no_detection).
void settle_travel_test(StepThreads& t, const ContactDetector& detector, const Blocks& blocks, int threads, double dt);

}  // namespace polydem
