// Verification of the [[arch]] and [[column]] generators against classical
// results (docs/structures.md, "Arches" and "Columns").
//
// Arch: examples/verification/arch_self_weight.toml is a semicircle of 9
// voussoirs at 1.1 times the thinnest ring that can stand by the
// limit-analysis LP (t/R = 0.10152, tests/studies/arch_thickness_test.cpp).
// The DEM, with friction high enough that no joint slides, must agree with
// the LP: the arch stands at 1.02 times the LP's thickness and collapses at
// 0.98 (and at 0.9, where the deck's check must fail).
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace polydem {
namespace {

std::string deck(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name; }

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

}  // namespace
}  // namespace polydem
