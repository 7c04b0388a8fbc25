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
// then the governor probes: it times steps on one thread, then on all, and
// keeps the side with the shorter mean step (each timed without its
// detection, which is longer for another reason; steps too small to run in
// parallel are not samples). The all-threads side lasts `probe_seconds` of
// wall time: a competitor takes
// the shared core in scheduler slices of a few milliseconds, so the threads
// run many steps at full speed and then stall for a whole slice. A median
// of a few steps misses the stalls (measured: it kept two threads at half
// the speed of one); the mean over many slices counts them, and all threads
// must beat one by a margin (10 %) to be kept. One thread, which a
// competitor on the other core cannot stall, is timed first and briefly
// (`one_side_seconds`), so that the all-threads side can be called lost as
// soon as its mean over its first `lost_after_seconds` is already twice
// one thread's (`lost_ratio`): beside a competitor the steps on two threads
// wait milliseconds for the second thread to be scheduled (measured: means
// of 60-120 µs on the 52-stone wall, whose steps take 9 µs on one thread),
// and a run must not pay a whole probe of them. The side's first step and
// first `warm_up_seconds` are not samples: starting the threads took up to
// 14 ms even on a quiet machine (a second step of 8 ms, or a hundred steps
// at 3 times the speed to come, in 3 of 5 runs measured),
// and the steps after run ~1.5 times slower than the rest while they warm
// up, so the ratio is 2, not 1. The first probe
// starts at once; the wait to the next is counted in wall time of stepping
// only (a probe beside a competitor costs ~30-60 ms, so probes must come
// seconds apart whether a step takes microseconds or tens of
// milliseconds). When a probe confirms the choice, the wait doubles (up to
// `longest_wait`); when it changes it, and after the run's first probe
// whichever it keeps, the wait starts short again (`shortest_wait`): the
// first probe's all-threads side meets the erratic start above and, kept
// to one thread by it, a whole short run stayed there (1 in 40 of the
// spire's 0.3 s runs). So a competitor that comes or goes is noticed
// within seconds to half a minute while a quiet run probes a few times an
// hour.
//
// Between probes it watches the steps on all threads for stalls, since a
// competitor may come between probes that are far apart. A stall is what
// the competitor does to two threads once they run: most steps at full
// speed, then a whole scheduler slice lost at a barrier. So the watch
// compares, over windows of `watch_seconds` (a window needs two steps at
// least), the mean step with the
// window's fastest: a mean above `stall_ratio` times the fastest in
// `stalled_windows_to_drop` windows in a row drops to one thread at once
// (a single hiccup of the machine does not; on a quiet machine the ratio
// was measured at 1.01-1.25 on the spire), and the next probe, a short
// interval later, decides whether to go back. The same watch also ends a
// probe's all-threads side as lost.
//
// Results do not depend on it: every stage gives the same bits on any
// number of threads (docs/architecture.md, determinism), so switching
// changes the wall time only. `simulation.adaptive_threads = false` (or a
// run on one thread) leaves the threads as OpenMP has them.
#pragma once

namespace polydem {

inline constexpr int kProbingOne = 1;  // a probe timing one thread
inline constexpr int kProbingAll = 2;  // ... then all of them

struct ThreadGovernor {
  // Settings.
  int most = 1;                    // threads OpenMP was given; 1: the governor never acts
  double shortest_wait = 1.0;      // stepping wall time (s) between probes after a change
  double longest_wait = 16.0;      // ... once the choice has held
  double one_side_seconds = 0.02;  // wall time (s) a probe times one thread
  double probe_seconds = 0.1;      // ... and all threads, unless lost earlier:
  double warm_up_seconds = 0.01;      // the all-threads side's first step and first this long are not samples
  double lost_after_seconds = 0.005;  // all threads have lost when, after this long (s),
  double lost_ratio = 2.0;            // ... their mean step is above this times one thread's
  double margin = 0.9;            // all threads are kept only when their mean step is below this times one's
  double watch_seconds = 0.01;    // the stall watch's window of wall time (a few scheduler slices)
  double stall_ratio = 2.0;       // a window stalls when its mean step is above this times its fastest
  int stalled_windows_to_drop = 2;  // stalled windows in a row that drop to one thread

  // State.
  int now = 1;          // threads the next step uses
  double wait = 0;      // stepping wall time (s) between probes; none before the first
  double waited = 0;    // stepping wall time since the last probe (s)
  int probing = 0;      // 0: not; kProbingOne, then kProbingAll
  double warmed = 0;                         // the all-threads side's warm-up so far (s)
  long warm_steps = 0;                       // ... and its steps
  long many_steps = 0, one_steps = 0;        // the probe's samples on each side
  double many_seconds = 0, one_seconds = 0;  // ... and their wall time, s
  long window_steps = 0;         // the stall watch's current window: steps,
  double window_seconds = 0;     // ... their wall time (s)
  double window_fastest = 0;     // ... and the fastest of them (s)
  int stalled_windows = 0;       // stalled windows in a row

  // What the run reports (summary.json profile.threads).
  long probes = 0;
  long switches = 0;
  long steps_on_one = 0;  // steps run on one thread while more were available
  long stall_drops = 0;   // times the stall watch ended all threads: drops, and probes' all-threads sides
};

// A governor for `most` threads; when it governs (enabled, most > 1) the run
// starts on one thread and its first probe, at once, decides.
ThreadGovernor make_thread_governor(int most, bool enabled);

// Threads for the step about to run.
int threads_for_step(ThreadGovernor& g);

// After the step: its wall time without the detection.
void record_step(ThreadGovernor& g, double seconds);

// The stall watch's verdict on one window (exposed for tests): its mean step
// is above `ratio` times its fastest (a fastest of 0, a clock too coarse,
// is no verdict).
bool window_stalled(long steps, double seconds, double fastest, double ratio);

// The choice between the two mean step times (exposed for tests): all
// threads when their mean step is below `margin` times one thread's, one
// otherwise (a near tie included: one thread cannot be slowed by a
// competitor, and a probe's few hundred milliseconds are noisy).
int faster_choice(int most, double many_mean, double one_mean, double margin = 0.9);

}  // namespace polydem
