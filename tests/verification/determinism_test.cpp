// Verification 6: the same deck gives bitwise-identical results on 1 and 2
// threads. The scene is large enough (a 200-stone wall) for every parallel
// loop of the step to run in parallel.
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace polydem {
namespace {

std::string big_wall_deck() {
  std::ostringstream d;
  d << "[simulation]\nend_time = 0.015\n[joint]\nnormal_stiffness = 98e9\nfriction_angle = 30.0\n"
       "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.6\nperiod = 0.05\ndirection = [0.6, 0.8, 0.0]\n"
       "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [8, 1, 0.5]\ncenter = [0, 0, -0.25]\nmotion = \"fixed\"\n";
  const double unit = 0.3, height = 0.2;
  for (int c = 0; c < 10; ++c) {
    double x = -3.0;
    const int n = c % 2 == 0 ? 20 : 21;
    for (int k = 0; k < n; ++k) {
      const double w = (c % 2 == 1 && (k == 0 || k == n - 1)) ? unit / 2 : unit;
      d << "[[block]]\nshape = \"box\"\nsize = [" << w << ", 0.3, " << height << "]\ncenter = [" << x + w / 2
        << ", 0, " << height * (c + 0.5) << "]\n";
      x += w;
    }
  }
  return d.str();
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameBits) {
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml");
  spec.simulation.adaptive_threads = false;  // two threads all the way (the governor has its own test)
  ASSERT_GT(spec.blocks.size(), 200u);
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  // Every step in parallel, whatever its size: the point is to compare.
  one.parallel_threshold = 0;
  two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  const RunReport b = run_scene(spec, two);
  EXPECT_TRUE(same_bits(a.final_position, b.final_position));
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity));
  EXPECT_EQ(std::memcmp(a.final_orientation.data(), b.final_orientation.data(),
                        a.final_orientation.size() * sizeof(Quat)),
            0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  // And the motion is not trivial.
  double moved = 0;
  for (std::size_t i = 0; i < a.final_position.size(); ++i)
    moved = std::max(moved, a.final_velocity[i].norm());
  EXPECT_GT(moved, 1e-3);
}

// The joint law's AVX2 lanes and its portable loop (contact/joint_law_lanes.hpp)
// give the same bits through a whole run: the wall under the pulse, on two
// threads, every step's law on one path or the other.
TEST(Determinism, TheJointLawsTwoCodePathsGiveTheSameBits) {
  if (!joint_law_lanes_available()) GTEST_SKIP() << "no AVX2 here: only the portable path runs";
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml");
  spec.simulation.adaptive_threads = false;
  RunControl lanes, portable;
  lanes.threads = portable.threads = 2;
  lanes.parallel_threshold = portable.parallel_threshold = 0;
  lanes.joint_law_path = JointLawPath::lanes;
  portable.joint_law_path = JointLawPath::portable;
  const RunReport a = run_scene(spec, lanes);
  const RunReport b = run_scene(spec, portable);
  EXPECT_TRUE(same_bits(a.final_position, b.final_position));
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity));
  EXPECT_EQ(std::memcmp(a.final_orientation.data(), b.final_orientation.data(),
                        a.final_orientation.size() * sizeof(Quat)),
            0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  EXPECT_GT(a.energy.slip, 0.0);  // joints slipped: the law's every branch had its say
}

}  // namespace
}  // namespace polydem
