// Verification of the [[arch]] and [[column]] generators against classical
// results (docs/structures.md, "Arches" and "Columns").
//
// Arch: examples/verification/arch_self_weight.toml is a semicircle of 9
// voussoirs at 1.1 times the thinnest ring that can stand by the
// limit-analysis LP (t/R = 0.10152, tests/studies/arch_thickness_test.cpp).
// The DEM, with friction high enough that no joint slides, must agree with
// the LP: the arch stands at 1.02 times the LP's thickness and collapses at
// 0.98 (and at 0.9, where the deck's check must fail).
//
// Column: examples/verification/column_rocking.toml is the slender pillar
// of pulse_rocking_body_force.toml cut into four square drums. Under small
// pulses the drums rock as one body: the deck's check (the rigid rocking
// body of the four drums, 3 %) passes, and the drummed column's peak follows
// the one-piece column's (DEM against DEM) within 3 %. From about 0.5 g the
// joints between drums open and the drummed column departs from both.
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

namespace polydem {
namespace {

std::string deck(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name; }

std::vector<double> column(const HistoryTable& t, const std::string& name) {
  std::vector<double> out;
  std::size_t c = 0;
  while (c < t.columns.size() && t.columns[c] != name) ++c;
  EXPECT_LT(c, t.columns.size()) << name;
  for (std::size_t r = 0; r < t.row_count(); ++r) out.push_back(t.rows[r * t.columns.size() + c]);
  return out;
}

double peak(const std::vector<double>& v) {
  double p = 0;
  for (double x : v) p = std::max(p, std::abs(x));
  return p;
}

struct ColumnRun {
  double peak_bottom = 0, top_minus_bottom = 0, expected = 0;
  bool passed = false;
};

// The deck's column under a pulse of a_p (in g), in `drums` drums.
ColumnRun column_at(double a_g, int drums) {
  std::vector<std::string> set = {"ground_motion.acceleration_g=" + std::to_string(a_g),
                                  "column[1].drums=" + std::to_string(drums)};
  if (drums == 1) set.push_back("output.histories=[\"column_drum00.rotation\"]");
  const RunReport r = run_scene(read_deck(deck("column_rocking.toml"), set));
  ColumnRun c;
  const auto bottom = column(r.histories, "column_drum00.rotation.y");
  c.peak_bottom = peak(bottom);
  if (drums > 1) {
    const auto top = column(r.histories, "column_drum0" + std::to_string(drums - 1) + ".rotation.y");
    for (std::size_t k = 0; k < top.size(); ++k) c.top_minus_bottom = std::max(c.top_minus_bottom, std::abs(top[k] - bottom[k]));
  }
  c.expected = r.checks.at(0).expected;
  c.passed = r.checks.at(0).passed;
  return c;
}

// The deck's arch at `factor` times the LP's threshold, centre-line radius 1 m.
RunReport arch_at(double factor) {
  const double t = factor * 0.101523;
  const SceneSpec s = read_deck(deck("arch_self_weight.toml"), {"arch[1].thickness=" + std::to_string(t),
                                                                "arch[1].radius=" + std::to_string(1.0 - 0.5 * t)});
  return run_scene(s);
}

TEST(ArchSelfWeight, DemAgreesWithTheLimitAnalysisWithinTwoPercent) {
  for (double f : {0.9, 0.98, 1.02}) {
    const RunReport r = arch_at(f);
    ASSERT_EQ(r.checks.size(), 1u);
    std::cout << "  t = " << f << " x LP: keystone moved " << r.checks[0].measured << " m\n";
    if (f < 1)
      EXPECT_FALSE(r.checks[0].passed) << "the arch at " << f << " times the LP's thickness must collapse";
    else
      EXPECT_TRUE(r.checks[0].passed) << "the arch at " << f << " times the LP's thickness must stand";
  }
}

TEST(ColumnRocking, DrumsRockAsOneBodyUnderSmallPulses) {
  for (double a : {0.3, 0.4}) {
    const ColumnRun drums = column_at(a, 4), one = column_at(a, 1);
    std::cout << "  a_p = " << a << " g: rigid " << drums.expected << ", one piece " << one.peak_bottom
              << ", four drums " << drums.peak_bottom << " rad; top - bottom drum " << drums.top_minus_bottom
              << " rad\n";
    EXPECT_TRUE(drums.passed) << a;
    EXPECT_NEAR(drums.peak_bottom, one.peak_bottom, 0.03 * one.peak_bottom) << a;
  }
}

// A check that can fail: at 0.6 g the drums rock on each other (the top
// drum's rotation leaves the bottom one's by more than 0.01 rad), the
// drummed column departs from the one-piece column by more than 20 %, and
// the deck's check fails.
TEST(ColumnRocking, LargerPulsesRockTheDrumsApart) {
  const ColumnRun drums = column_at(0.6, 4), one = column_at(0.6, 1);
  std::cout << "  a_p = 0.6 g: rigid " << drums.expected << ", one piece " << one.peak_bottom << ", four drums "
            << drums.peak_bottom << " rad; top - bottom drum " << drums.top_minus_bottom << " rad\n";
  EXPECT_FALSE(drums.passed);
  EXPECT_GT(drums.top_minus_bottom, 0.01);
  EXPECT_GT(std::abs(drums.peak_bottom - one.peak_bottom), 0.2 * one.peak_bottom);
}

// Generated structures give the same bits on 1 and 2 threads (every step in
// parallel): a staggered vault on coursed piers and a column, shaken hard.
TEST(GeneratedStructures, OneAndTwoThreadsGiveTheSameBits) {
  const SceneSpec spec = parse_deck(R"([simulation]
end_time = 0.015
[ground_motion]
kind = "sine_pulse"
acceleration_g = 0.8
period = 0.05
direction = [0.6, 0.8, 0.0]
[[arch]]
rings = 4
spans = 2
supports = "piers"
pier_courses = 2
[[column]]
origin = [0, 4, 0]
capital = "frustum"
)",
                                    "generated.toml");
  ASSERT_GT(spec.blocks.size(), 80u);
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  one.parallel_threshold = 0;
  two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  const RunReport b = run_scene(spec, two);
  ASSERT_EQ(a.final_position.size(), b.final_position.size());
  EXPECT_EQ(std::memcmp(a.final_position.data(), b.final_position.data(), a.final_position.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.final_velocity.data(), b.final_velocity.data(), a.final_velocity.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  double moved = 0;
  for (const Vec3& v : a.final_velocity) moved = std::max(moved, v.norm());
  EXPECT_GT(moved, 1e-4);
}

// examples/structures/arcade.toml cut to its first 1.5 s (the record starts
// at 0.5 s): the example keeps running, its 32 blocks stand, its energy
// ledger closes.
TEST(ArcadeExample, RunsItsFirstSecondAndAHalf) {
  const SceneSpec s = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/structures/arcade.toml",
                                {"simulation.end_time=1.5"});
  ASSERT_EQ(s.blocks.size(), 2u * 11 + 3 * 3 + 1);
  const RunReport r = run_scene(s);
  EXPECT_EQ(r.assessment.status, "intact");
  EXPECT_LT(r.assessment.peak_displacement, 0.005);
  EXPECT_LT(r.energy_balance_error, 0.05);
}

}  // namespace
}  // namespace polydem
