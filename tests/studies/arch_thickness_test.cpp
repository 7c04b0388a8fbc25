// The thinnest semicircular arch that stands under its own weight, by the
// limit-analysis LP on the [[arch]] generator's voussoirs (studies/standing.hpp),
// against the classical result for the continuous arch with radial joints:
// t/R = 0.1075 (Milankovitch 1907; R the radius of the centre line; rigid,
// no tension, no sliding). Heyman's 0.106 is the approximate solution that
// places each element's weight on the centre line.
//
// With n voussoirs the thrust line need only stay inside the ring at the n + 1
// joints, not everywhere, so the discrete arch stands a little thinner; the
// threshold rises towards the continuous value as n grows.
#include "io/deck.hpp"
#include "studies/standing.hpp"

#include <gtest/gtest.h>

#include <fmt/core.h>

#include <chrono>
#include <cmath>

namespace polydem {
namespace {

// A semicircle of centre-line radius 1 m and thickness η on a fixed base.
SceneSpec arch(int voussoirs, double eta) {
  return parse_deck(fmt::format(R"(
[[arch]]
shape = "circular"
radius = {:.17g}
thickness = {:.17g}
voussoirs = {}
depth = 0.5
supports = "base"
)",
                                1.0 - 0.5 * eta, eta, voussoirs),
                    "<arch>");
}

LimitAnalysisOptions no_sliding() {
  LimitAnalysisOptions o;
  o.friction_angle_deg = 85.0;  // μ = 11.4: no joint slides
  o.method = LpMethod::simplex;
  return o;
}

double threshold(int n) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = thinnest_standing([n](double eta) { return arch(n, eta); }, 0.05, 0.15, 1e-5, no_sliding());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "  n = " << n << ": " << r.trials << " trials of two LPs in " << s << " s\n";
  return r.threshold();
}

TEST(ArchThickness, StandsAboveAndNotBelowTheLimit) {
  const double eta = threshold(9);
  std::cout << "  n = 9: t/R = " << eta << "\n";
  EXPECT_TRUE(can_stand(limit_model(arch(9, 1.01 * eta)), no_sliding()).stands);
  EXPECT_FALSE(can_stand(limit_model(arch(9, 0.99 * eta)), no_sliding()).stands);
}

// The mesh row of docs/structures.md: the threshold against the voussoir
// count, converging on Milankovitch's 0.1075 from below.
TEST(ArchThickness, ConvergesOnMilankovitch) {
  double previous = 0;
  for (int n : {9, 17, 33, 65}) {
    const double eta = threshold(n);
    std::cout << "  n = " << n << ": t/R = " << eta << " (" << 100 * (eta / 0.1075 - 1) << " %)\n";
    EXPECT_LT(eta, 0.1075 * 1.002) << n;
    EXPECT_GT(eta, previous - 2e-5) << n;
    previous = eta;
  }
  EXPECT_NEAR(previous, 0.1075, 0.005 * 0.1075);
}

}  // namespace
}  // namespace polydem
