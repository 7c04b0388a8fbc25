// Model 6 of issue 4: the frequency analysis of the DEM free vibration, and a
// short run of a coarse spire.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "apps/analytic_command.hpp"
#include "studies/dem_frequency.hpp"
#include "io/deck.hpp"

TEST(DemFrequency, FourierPeakAndZeroCrossingsOfADecayingSine) {
  std::vector<double> t, u;
  const double f = 17.3, dt = 2e-4;
  for (int k = 0; k < 2500; ++k) {  // 0.5 s, 8.65 periods
    t.push_back(0.1 + k * dt);
    // A second mode and an offset must not move the first peak much.
    u.push_back(1e-6 + 3e-6 * std::exp(-0.3 * t.back()) * std::sin(2 * std::numbers::pi * f * t.back() + 0.4) +
                3e-7 * std::sin(2 * std::numbers::pi * 61.0 * t.back()));
  }
  EXPECT_NEAR(polydem::fourier_peak_hz(t, u, 1.0, 200.0), f, 0.01 * f);
  int n = 0;
  EXPECT_NEAR(polydem::zero_crossing_hz(t, u, &n), f, 0.03 * f);
  EXPECT_GE(n, 16);
  EXPECT_EQ(polydem::fourier_peak_hz({0.0}, {1.0}, 1.0, 10.0), 0.0);
}

TEST(DemFrequency, TipBlockOfTheSpire) {
  const auto scene = polydem::parse_deck("[spire]\n", "<test>");
  EXPECT_EQ(polydem::spire_tip_block(scene), "tip");
}

// The beam estimate's kn is the laws' among the free stones: a [[joint]]
// between them overrides [joint]'s; two different stiffnesses acting among
// them have no single E_eq.
TEST(DemFrequency, JointStiffnessFromTheActingLaws) {
  auto scene = polydem::parse_deck("[spire]\ncourse_height = 1.0\nstones_per_face = 1\n", "<coarse spire>");
  EXPECT_EQ(polydem::spire_joint_normal_stiffness(scene), scene.joint.normal_stiffness);
  for (auto& b : scene.blocks) b.group = b.motion == polydem::BlockMotion::free ? "stones" : "base";
  polydem::JointPairSpec pair;
  pair.group_a = pair.group_b = "stones";
  pair.joint = scene.joint;
  pair.joint.normal_stiffness = 0.5 * scene.joint.normal_stiffness;
  scene.joint_pairs.push_back(pair);
  EXPECT_EQ(polydem::spire_joint_normal_stiffness(scene), pair.joint.normal_stiffness);
  scene.blocks.back().group = "other";
  EXPECT_THROW(polydem::spire_joint_normal_stiffness(scene), std::runtime_error);
}

// A coarse windowless spire (1 m courses, one stone per face): the DEM's first
// frequency against the beam with E = kn h.
TEST(DemFrequency, CoarseSpireFreeVibration) {
  const auto scene = polydem::parse_deck(
      "[spire]\ncourse_height = 1.0\nstones_per_face = 1\nwindow_faces = []\njoint_pattern = \"aligned\"\n",
      "<coarse spire>");
  polydem::DemFrequencyOptions o;
  // Settled for 0.1 s: after 0.02 s under gravity the tip still drifts by
  // a few µm (towards where it comes to rest, 6 µm from its start), as
  // large as the pulse's vibration, which the measurement would then miss.
  o.settle_time = 0.1;
  o.duration = 0.2;
  o.threads = 2;
  const auto r = polydem::measure_dem_frequency(scene, o);
  std::printf("coarse spire: %d blocks, %ld steps, DEM %.3f Hz (Fourier) %.3f Hz (%d zero crossings), beam %.3f Hz, "
              "amplitude %.3g m\n",
              r.blocks, r.steps, r.f_fourier_hz, r.f_zero_crossing_hz, r.zero_crossings, r.f_beam_hz, r.amplitude_m);
  EXPECT_FALSE(r.unstable);
  EXPECT_EQ(r.status, "intact");
  EXPECT_GT(r.amplitude_m, 0.0);
  EXPECT_NEAR(r.E_eq, scene.joint.normal_stiffness * r.course_height, 1e-6 * r.E_eq);
  EXPECT_NEAR(r.f_zero_crossing_hz, r.f_fourier_hz, 0.1 * r.f_fourier_hz);
  EXPECT_GT(r.f_fourier_hz, 0.5 * r.f_beam_hz);
  EXPECT_LT(r.f_fourier_hz, 1.5 * r.f_beam_hz);
}

TEST(DemFrequency, CommandRejectsADeckWithoutSpire) {
  EXPECT_EQ(run_analytic_command({"analytic", "dem-frequency", "--deck", "/nonexistent/deck.toml"}), 2);
  EXPECT_EQ(run_analytic_command({"analytic", "refined-lambda", "--bogus", "1"}), 2);
  EXPECT_EQ(run_analytic_command({"analytic", "refined-lambda", "--json"}), 0);
}
