#include "integrators/thread_governor.hpp"

#include <algorithm>

namespace polydem {

ThreadGovernor make_thread_governor(int most, bool enabled) {
  ThreadGovernor g;
  g.most = enabled && most > 1 ? most : 1;
  g.now = most > 1 ? most : 1;
  g.next_probe = g.first_probe;
  g.interval = g.shortest_interval;
  return g;
}

int faster_choice(int most, double many_mean, double one_mean, double margin) {
  return many_mean < margin * one_mean ? most : 1;
}

int threads_for_step(ThreadGovernor& g, long step) {
  if (g.most <= 1) return g.now;
  if (g.probing == 0 && step >= g.next_probe) {
    g.probing = 1;
    g.many_steps = g.one_steps = 0;
    g.many_seconds = g.one_seconds = 0;
  }
  const int threads = g.probing == 1 ? g.most : (g.probing == 2 ? 1 : g.now);
  if (threads == 1) ++g.steps_on_one;
  return threads;
}

namespace {

bool side_done(const ThreadGovernor& g, long steps, double seconds) {
  return steps >= g.probe_steps_most || (steps >= g.probe_steps && seconds >= g.probe_seconds);
}

}  // namespace

void record_step(ThreadGovernor& g, double seconds, long step) {
  if (g.most <= 1 || g.probing == 0) return;
  if (g.probing == 1) {
    ++g.many_steps;
    g.many_seconds += seconds;
    if (side_done(g, g.many_steps, g.many_seconds)) g.probing = 2;
    return;
  }
  ++g.one_steps;
  g.one_seconds += seconds;
  if (!side_done(g, g.one_steps, g.one_seconds)) return;
  const int choice = faster_choice(g.most, g.many_seconds / static_cast<double>(g.many_steps),
                                   g.one_seconds / static_cast<double>(g.one_steps), g.margin);
  ++g.probes;
  if (choice != g.now) {
    ++g.switches;
    g.interval = g.shortest_interval;
  } else {
    g.interval = std::min(2 * g.interval, g.longest_interval);
  }
  g.now = choice;
  g.probing = 0;
  g.next_probe = step + g.interval;
}

}  // namespace polydem
