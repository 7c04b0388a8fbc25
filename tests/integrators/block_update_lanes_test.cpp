// advance_four() (integrators/block_update_lanes.hpp): when one of the four
// blocks turns too far for the exponential's series it declines and writes
// nothing, so that the caller's portable update starts from the state as it
// was. Whole runs on both code paths: tests/verification/determinism_test.cpp.
#include "integrators/block_update_lanes.hpp"

#include "core/code_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace polydem {
namespace {

struct Records {
  std::vector<double> position, velocity, angular_momentum, angular_velocity, orientation, rotation,
      contact_force, contact_torque, mass, inv_mass, inv_inertia, velocity_mid, omega_mid, position_prev,
      orientation_prev, load_work;

  explicit Records(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto fill = [&](std::vector<double>& v, int width, double scale) {
      v.resize(static_cast<std::size_t>(n * width));
      for (double& x : v) x = scale * u(rng);
    };
    fill(position, 3, 1.0);
    fill(velocity, 3, 0.1);
    fill(angular_momentum, 3, 0.01);
    fill(angular_velocity, 3, 0.1);
    fill(contact_force, 3, 100.0);
    fill(contact_torque, 3, 10.0);
    fill(velocity_mid, 3, 1.0);
    fill(omega_mid, 3, 1.0);
    fill(position_prev, 3, 1.0);
    fill(orientation_prev, 4, 1.0);
    fill(load_work, 1, 1.0);
    orientation.resize(static_cast<std::size_t>(4 * n));
    rotation.resize(static_cast<std::size_t>(9 * n));
    for (int i = 0; i < n; ++i) {  // a unit quaternion and its matrix (identity is enough here)
      double* q = &orientation[static_cast<std::size_t>(4 * i)];
      q[0] = q[1] = q[2] = 0.0;
      q[3] = 1.0;
      double* r = &rotation[static_cast<std::size_t>(9 * i)];
      for (int k = 0; k < 9; ++k) r[k] = k % 4 == 0 ? 1.0 : 0.0;
    }
    mass.assign(static_cast<std::size_t>(n), 10.0);
    inv_mass.assign(static_cast<std::size_t>(n), 0.1);
    inv_inertia.assign(static_cast<std::size_t>(3 * n), 5.0);
  }

  block_lanes::BlockArrays arrays() {
    return {position.data(),      velocity.data(),       angular_momentum.data(), angular_velocity.data(),
            orientation.data(),   rotation.data(),       contact_force.data(),    contact_torque.data(),
            mass.data(),          inv_mass.data(),       inv_inertia.data(),      velocity_mid.data(),
            omega_mid.data(),     position_prev.data(),  orientation_prev.data(), load_work.data()};
  }
  bool operator==(const Records&) const = default;
};

TEST(BlockUpdateLanes, ATurnBeyondTheSeriesDeclinesAndWritesNothing) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 here: only the portable update runs";
  std::mt19937_64 rng(2);
  Records r(6, rng);
  block_lanes::StepConstants k{{0, 0, -9.81}, {0.5, 0, 0}, 1e-5, 1e-5};
  const int four[4] = {0, 2, 3, 5};
  // Small turns: the lanes advance the four and nothing else.
  Records small = r;
  ASSERT_TRUE(block_lanes::advance_four(small.arrays(), k, four));
  EXPECT_NE(small.position, r.position);
  for (int c = 0; c < 3; ++c) {  // blocks 1 and 4 untouched
    EXPECT_EQ(small.position[3 + c], r.position[3 + c]);
    EXPECT_EQ(small.velocity[12 + c], r.velocity[12 + c]);
  }
  // Block 3 spinning: ω·dt = 2e-3 rad, |θ|² = 4e-6 ≥ 1e-6, so the series does
  // not hold for the step's turn: nothing may change.
  Records spinning = r;
  spinning.angular_momentum[9] = 2e2 / 5.0;  // ω = I⁻¹·L = 200 rad/s about x
  const Records before = spinning;
  EXPECT_FALSE(block_lanes::advance_four(spinning.arrays(), k, four));
  EXPECT_TRUE(spinning == before);
}

}  // namespace
}  // namespace polydem
