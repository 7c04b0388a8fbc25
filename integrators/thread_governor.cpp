#include "integrators/thread_governor.hpp"

#include <algorithm>

namespace polydem {

namespace {

double median(std::vector<double>& v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

ThreadGovernor make_thread_governor(int most, bool enabled) {
  ThreadGovernor g;
  g.most = enabled && most > 1 ? most : 1;
  g.now = most > 1 ? most : 1;
  g.next_probe = g.first_probe;
  g.interval = g.shortest_interval;
  g.many_times.reserve(static_cast<std::size_t>(g.probe_steps));
  g.one_times.reserve(static_cast<std::size_t>(g.probe_steps));
  return g;
}

int faster_choice(int most, double many_median, double one_median) {
  return many_median < one_median ? most : 1;
}

int threads_for_step(ThreadGovernor& g, long step) {
  if (g.most <= 1) return g.now;
  if (g.probing == 0 && step >= g.next_probe) {
    g.probing = 1;
    g.many_times.clear();
    g.one_times.clear();
  }
  const int threads = g.probing == 1 ? g.most : (g.probing == 2 ? 1 : g.now);
  if (threads == 1) ++g.steps_on_one;
  return threads;
}

void record_step(ThreadGovernor& g, double seconds, long step) {
  if (g.most <= 1 || g.probing == 0) return;
  const auto n = static_cast<std::size_t>(g.probe_steps);
  if (g.probing == 1) {
    g.many_times.push_back(seconds);
    if (g.many_times.size() >= n) g.probing = 2;
    return;
  }
  g.one_times.push_back(seconds);
  if (g.one_times.size() < n) return;
  const int choice = faster_choice(g.most, median(g.many_times), median(g.one_times));
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
