// How many threads the next step uses: all OpenMP was given, or one.
//
// Why: a step of the spire takes ~60 µs on two threads and meets its
// threads at two barriers. When another process holds one of the two cores
// (a second polydem run, a build, `polydem sweep --jobs 2`), the thread that
// shares that core runs only when the scheduler gives it a slice, and the
// other waits for it at every barrier: measured on the spire's earthquake
// deck with one single-threaded competitor, 2 threads ran 26 times slower
// than 1 (1.2e6 against 3.1e7 subcontact updates per second). More threads
// must never be slower than one.
//
// How: the step times itself (it does already, for the profile). Now and
// then the governor probes: it times steps on all the threads, then on one,
// and keeps the side with the shorter mean step (each timed without its
// detection, which is longer for another reason; steps too small to run in
// parallel are not samples). A side lasts at least `probe_steps` steps and
// `probe_seconds` of wall time: a competitor takes the shared core in
// scheduler slices of a few milliseconds, so the threads run many steps at
// full speed and then stall for a whole slice. A median of a few steps
// misses the stalls (measured: it kept two threads at half the speed of
// one); the mean over many slices counts them, and all threads must beat
// one by a margin (10 %) to be kept. The probes start after
// `first_probe` steps; when a probe confirms the choice, the wait to the
// next doubles (up to `longest_interval`), when it changes it the wait
// starts short again, so a competitor that comes or goes is noticed within
// seconds while a quiet run probes a few times per million steps; a probe of
// the slow side costs about probe_seconds of it.
//
// Results do not depend on it: every stage gives the same bits on any
// number of threads (docs/architecture.md, determinism), so switching
// changes the wall time only. `simulation.adaptive_threads = false` (or a
// run on one thread) leaves the threads as OpenMP has them.
#pragma once

namespace polydem {

struct ThreadGovernor {
  // Settings.
  int most = 1;                   // threads OpenMP was given; 1: the governor never acts
  long first_probe = 512;         // steps before the first probe
  long shortest_interval = 16384;  // steps between probes after a change
  long longest_interval = 262144;  // ... once the choice has held
  int probe_steps = 32;           // at least this many timed steps per side of a probe
  double probe_seconds = 0.1;     // ... and at least this much wall time (s)
  double margin = 0.9;            // all threads are kept only when their mean step is below this times one's
  long probe_steps_most = 20000;  // a side ends after this many steps whatever its time

  // State.
  int now = 1;          // threads the next step uses
  long next_probe = 0;  // step count at which the next probe starts
  long interval = 0;    // current wait between probes
  int probing = 0;      // 0: not; 1: timing `most` threads; 2: timing one
  long many_steps = 0, one_steps = 0;        // the probe's samples on each side
  double many_seconds = 0, one_seconds = 0;  // ... and their wall time, s

  // What the run reports (summary.json profile.threads).
  long probes = 0;
  long switches = 0;
  long steps_on_one = 0;  // steps run on one thread while more were available
};

// A governor for `most` threads; starts on all of them.
ThreadGovernor make_thread_governor(int most, bool enabled);

// Threads for the step about to run (number `step`, counting from 0).
int threads_for_step(ThreadGovernor& g, long step);

// After step number `step`: its wall time without the detection.
void record_step(ThreadGovernor& g, double seconds, long step);

// The choice between the two mean step times (exposed for tests): all
// threads when their mean step is below `margin` times one thread's, one
// otherwise (a near tie included: one thread cannot be slowed by a
// competitor, and a probe's few hundred milliseconds are noisy).
int faster_choice(int most, double many_mean, double one_mean, double margin = 0.9);

}  // namespace polydem
