#include "integrators/thread_governor.hpp"

#include <algorithm>

namespace polydem {

ThreadGovernor make_thread_governor(int most, bool enabled) {
  ThreadGovernor g;
  g.most = enabled && most > 1 ? most : 1;
  g.now = g.most > 1 ? 1 : std::max(most, 1);  // governed: one thread until a probe shows all are faster
  return g;
}

int faster_choice(int most, double many_mean, double one_mean, double margin) {
  return many_mean < margin * one_mean ? most : 1;
}

bool window_stalled(long steps, double seconds, double fastest, double ratio) {
  return fastest > 0 && seconds > ratio * static_cast<double>(steps) * fastest;
}

namespace {

void restart_watch(ThreadGovernor& g) {
  g.window_steps = 0;
  g.window_seconds = 0;
  g.window_fastest = 0;
  g.stalled_windows = 0;
}

// One step on all threads into the stall watch; true when the watch has
// seen `stalled_windows_to_drop` stalled windows in a row.
bool stalls(ThreadGovernor& g, double seconds) {
  if (g.window_steps == 0 || seconds < g.window_fastest) g.window_fastest = seconds;
  ++g.window_steps;
  g.window_seconds += seconds;
  if (g.window_seconds < g.watch_seconds || g.window_steps < 2) return false;
  const bool stalled = window_stalled(g.window_steps, g.window_seconds, g.window_fastest, g.stall_ratio);
  const int in_a_row = stalled ? g.stalled_windows + 1 : 0;
  restart_watch(g);
  g.stalled_windows = in_a_row;
  return in_a_row >= g.stalled_windows_to_drop;
}

void wait_short(ThreadGovernor& g) {
  g.wait = g.shortest_wait;
  g.waited = 0;
}

void end_probe(ThreadGovernor& g, int choice) {
  ++g.probes;
  // The run's first probe decides, it does not confirm: its all-threads
  // side meets the threads' erratic start, which now and then loses it on
  // a quiet machine (measured: 1 run in 40 of the spire's 0.3 s on two
  // threads, which then all ran on one). So the next probe comes as soon as
  // after a change, not twice as late.
  if (choice != g.now) ++g.switches;
  if (choice != g.now || g.probes == 1) {
    wait_short(g);
  } else {
    g.wait = std::min(2 * std::max(g.wait, g.shortest_wait), g.longest_wait);
    g.waited = 0;
  }
  g.now = choice;
  g.probing = 0;
  restart_watch(g);
}

}  // namespace

int threads_for_step(ThreadGovernor& g) {
  if (g.most <= 1) return g.now;
  if (g.probing == 0 && g.waited >= g.wait) {
    g.probing = kProbingOne;
    g.many_steps = g.one_steps = 0;
    g.many_seconds = g.one_seconds = 0;
  }
  const int threads = g.probing == kProbingOne ? 1 : (g.probing == kProbingAll ? g.most : g.now);
  if (threads == 1) ++g.steps_on_one;
  return threads;
}

void record_step(ThreadGovernor& g, double seconds) {
  if (g.most <= 1) return;
  if (g.probing == kProbingAll && (g.warmed < g.warm_up_seconds || g.warm_steps == 0)) {
    // Starting the threads: not samples, for the probe nor for the watch.
    g.warmed += seconds;
    ++g.warm_steps;
    if (g.warmed >= g.warm_up_seconds) restart_watch(g);
    return;
  }
  const bool on_all = g.probing == kProbingAll || (g.probing == 0 && g.now == g.most);
  if (on_all && stalls(g, seconds)) {
    ++g.stall_drops;
    if (g.probing == kProbingAll) {  // the probe's all-threads side has lost
      end_probe(g, 1);
    } else {  // drop now; the next probe decides whether to come back
      ++g.switches;
      g.now = 1;
      wait_short(g);
      restart_watch(g);
    }
    return;
  }
  if (g.probing == 0) g.waited += seconds;
  if (g.probing == kProbingOne) {
    ++g.one_steps;
    g.one_seconds += seconds;
    if (g.one_seconds >= g.one_side_seconds) {
      g.probing = kProbingAll;
      g.warmed = 0;
      g.warm_steps = 0;
      restart_watch(g);
    }
    return;
  }
  if (g.probing != kProbingAll) return;
  ++g.many_steps;
  g.many_seconds += seconds;
  const double one_mean = g.one_seconds / static_cast<double>(g.one_steps);
  // Lost early: clearly slower than one thread, at any point of the side
  // once it has lost_after_seconds of samples.
  if (g.many_seconds >= g.lost_after_seconds &&
      g.many_seconds > g.lost_ratio * static_cast<double>(g.many_steps) * one_mean) {
    end_probe(g, 1);
    return;
  }
  if (g.many_seconds >= g.probe_seconds)
    end_probe(g, faster_choice(g.most, g.many_seconds / static_cast<double>(g.many_steps), one_mean, g.margin));
}

}  // namespace polydem
