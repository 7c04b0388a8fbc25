// The thread governor (integrators/thread_governor.hpp): it keeps whichever
// of all threads and one is faster, notices when that changes, probes
// rarely once the choice holds, and never changes a result.
#include "integrators/thread_governor.hpp"
#include "io/deck.hpp"
#include "run/setup.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <sstream>

namespace polydem {
namespace {

// Runs the governor over `steps` steps whose time is `many` on all threads
// and `one` on one thread; returns the threads of the last step.
int drive(ThreadGovernor& g, long& step, long steps, double many, double one) {
  int last = 0;
  for (long end = step + steps; step < end; ++step) {
    last = threads_for_step(g, step);
    record_step(g, last > 1 ? many : one, step);
  }
  return last;
}

TEST(ThreadGovernor, KeepsTheFasterAndNoticesWhenItChanges) {
  ThreadGovernor g = make_thread_governor(2, true);
  EXPECT_EQ(g.now, 2);
  long step = 0;
  // A quiet machine: two threads 1.7 times faster. The first probe keeps
  // them, and the wait to the next probe doubles each time it holds.
  EXPECT_EQ(drive(g, step, g.first_probe + 2 * g.probe_steps + 1, 60e-6, 100e-6), 2);
  EXPECT_EQ(g.probes, 1);
  EXPECT_EQ(g.switches, 0);
  EXPECT_EQ(g.interval, 2 * g.shortest_interval);
  // A competing process: two threads 26 times slower. The next probe drops
  // to one thread, and probes come back at the short interval.
  drive(g, step, g.interval + 2 * g.probe_steps, 2.6e-3, 100e-6);
  EXPECT_EQ(g.now, 1);
  EXPECT_EQ(g.switches, 1);
  EXPECT_EQ(g.interval, g.shortest_interval);
  const long on_one = g.steps_on_one;
  EXPECT_GT(on_one, 0);
  // Still loaded: the choice holds and the probes thin out to the longest wait.
  for (int k = 0; k < 8; ++k) drive(g, step, g.interval + 2 * g.probe_steps, 2.6e-3, 100e-6);
  EXPECT_EQ(g.now, 1);
  EXPECT_EQ(g.interval, g.longest_interval);
  // The competitor ends: back to two threads at the next probe.
  drive(g, step, g.interval + 2 * g.probe_steps, 60e-6, 100e-6);
  EXPECT_EQ(g.now, 2);
  EXPECT_EQ(g.switches, 2);
}

TEST(ThreadGovernor, OneThreadOrSwitchedOffNeverProbes) {
  for (const auto& g0 : {make_thread_governor(1, true), make_thread_governor(2, false)}) {
    ThreadGovernor g = g0;
    long step = 0;
    drive(g, step, 100000, 1.0, 1e-6);
    EXPECT_EQ(g.probes, 0);
    EXPECT_EQ(g.switches, 0);
  }
  EXPECT_EQ(make_thread_governor(2, false).now, 2);  // switched off: the threads OpenMP was given
}

TEST(ThreadGovernor, FasterChoice) {
  EXPECT_EQ(faster_choice(4, 1.0, 2.0), 4);
  EXPECT_EQ(faster_choice(4, 2.0, 1.0), 1);
  EXPECT_EQ(faster_choice(4, 1.0, 1.0), 1);  // a tie: one thread, which cannot be slowed by a competitor
}

// A 120-stone wall under a pulse, every step parallel, the governor probing
// every few steps (so that the run keeps switching between two threads and
// one): the same bits as with the governor off.
TEST(ThreadGovernor, SwitchingThreadsChangesNoBits) {
  std::ostringstream d;
  d << "[simulation]\nend_time = 1\n[joint]\nnormal_stiffness = 1e9\n[ground_motion]\nkind = \"sine_pulse\"\n"
       "acceleration_g = 0.6\nperiod = 0.05\n[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [8, 1, 0.5]\n"
       "center = [0, 0, -0.25]\nmotion = \"fixed\"\n";
  for (int c = 0; c < 6; ++c)
    for (int k = 0; k < 20; ++k)
      d << "[[block]]\nshape = \"box\"\nsize = [0.3, 0.3, 0.2]\ncenter = [" << -3.0 + 0.3 * k + 0.15 * (c % 2)
        << ", 0, " << 0.2 * c + 0.1 << "]\n";
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  auto run = [&](bool adaptive) {
    SceneSpec spec = parse_deck(d.str(), "wall.toml");
    spec.simulation.adaptive_threads = adaptive;
    RunSetup setup;
    auto sim = build_simulation(spec, setup);
    sim->set_parallel_threshold(0);
    sim->set_thread_probing(3, 5, 9, 2);
    for (int n = 0; n < 400; ++n) sim->step();
    return sim;
  };
  const auto a = run(false), b = run(true);
  omp_set_num_threads(before);
  EXPECT_EQ(a->thread_governor().probes, 0);
  EXPECT_GT(b->thread_governor().probes, 20);
  EXPECT_GT(b->thread_governor().steps_on_one, 40);
  const auto& sa = a->blocks().state;
  const auto& sb = b->blocks().state;
  EXPECT_EQ(std::memcmp(sa.position.data(), sb.position.data(), sa.position.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(sa.velocity.data(), sb.velocity.data(), sa.velocity.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(sa.angular_momentum.data(), sb.angular_momentum.data(), sa.angular_momentum.size() * sizeof(Vec3)), 0);
  double fastest = 0;
  for (const Vec3& v : sa.velocity) fastest = std::max(fastest, v.norm());
  EXPECT_GT(fastest, 1e-3) << "the wall must move";
}

}  // namespace
}  // namespace polydem
