// The blocks' update kernel (integrators/block_update_lanes.hpp), in plain
// doubles and in AVX2 lanes where the machine has them, gives the bits of
// the update it stands for, Simulation::advance_block's Eigen expressions
// (written out below as the reference): blocks turning within the
// exponential's series and beyond it (the closed form, lane by lane), a
// full group of four and a short one (the last index repeated), and blocks
// outside the group untouched. Whole runs on either path:
// tests/verification/determinism_test.cpp.
#include "integrators/block_update_lanes.hpp"

#include "core/code_path.hpp"
#include "core/loads.hpp"
#include "geometry/polyhedron.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace polydem {
namespace {

struct Records {
  std::vector<Vec3> position, velocity, angular_momentum, angular_velocity, contact_force, contact_torque,
      inv_inertia, velocity_mid, omega_mid, position_prev;
  std::vector<Quat> orientation, orientation_prev;
  std::vector<Mat3> rotation;
  std::vector<double> mass, inv_mass, load_work;

  Records(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto vec = [&](double scale) {
      const double x = scale * u(rng), y = scale * u(rng), z = scale * u(rng);
      return Vec3(x, y, z);
    };
    for (int i = 0; i < n; ++i) {
      position.push_back(vec(1.0));
      velocity.push_back(vec(0.1));
      angular_momentum.push_back(vec(0.01));
      contact_force.push_back(vec(100.0));
      contact_torque.push_back(vec(10.0));
      const Vec3 spread = vec(0.5);
      inv_inertia.push_back(Vec3(5.0 + spread.x(), 4.0 + spread.y(), 3.0 + spread.z()));
      velocity_mid.push_back(vec(1.0));
      omega_mid.push_back(vec(1.0));
      position_prev.push_back(vec(1.0));
      orientation.push_back(Quat(u(rng), u(rng), u(rng), u(rng)).normalized());
      orientation_prev.push_back(orientation.back());
      rotation.push_back(orientation.back().toRotationMatrix());
      const Mat3 R = rotation.back();
      const Vec3 body = R.transpose() * angular_momentum.back();
      const Vec3 w = R * inv_inertia.back().cwiseProduct(body);
      angular_velocity.push_back(w);
      mass.push_back(10.0 + 5.0 * u(rng));
      inv_mass.push_back(1.0 / mass.back());
      load_work.push_back(u(rng));
    }
  }

  template <class T>
  static double* raw(std::vector<T>& v) {
    return reinterpret_cast<double*>(v.data());
  }
  block_lanes::BlockArrays arrays() {
    return {raw(position),      raw(velocity),          raw(angular_momentum), raw(angular_velocity),
            raw(orientation),   raw(rotation),          raw(contact_force),    raw(contact_torque),
            mass.data(),        inv_mass.data(),        raw(inv_inertia),      raw(velocity_mid),
            raw(omega_mid),     raw(position_prev),     raw(orientation_prev), load_work.data()};
  }
  // Every record of block i, as bytes.
  std::vector<unsigned char> bytes(int i) const {
    std::vector<unsigned char> b;
    auto put = [&](const void* p, std::size_t n) {
      const std::size_t at = b.size();
      b.resize(at + n);
      std::memcpy(b.data() + at, p, n);
    };
    put(&position[i], sizeof(Vec3));
    put(&velocity[i], sizeof(Vec3));
    put(&angular_momentum[i], sizeof(Vec3));
    put(&angular_velocity[i], sizeof(Vec3));
    put(&orientation[i], sizeof(Quat));
    put(&rotation[i], sizeof(Mat3));
    put(&velocity_mid[i], sizeof(Vec3));
    put(&omega_mid[i], sizeof(Vec3));
    put(&position_prev[i], sizeof(Vec3));
    put(&orientation_prev[i], sizeof(Quat));
    put(&load_work[i], sizeof(double));
    return b;
  }
};

// Simulation's exponential map: the series below |θ|² = 1e-6, Eigen's
// AngleAxis above.
Quat rotation_quaternion(const Vec3& w) {
  const double a2 = w.squaredNorm();
  if (a2 < 1e-6) {
    const double c = 1.0 - a2 / 8.0 + a2 * a2 / 384.0;
    const double h = 0.5 - a2 / 48.0 + a2 * a2 / 3840.0;
    return Quat(c, h * w.x(), h * w.y(), h * w.z());
  }
  const double angle = std::sqrt(a2);
  return Quat(Eigen::AngleAxisd(angle, w / angle));
}

// Simulation::advance_block for a free block without point loads, gravity
// not rising, no local damping.
void reference_update(Records& r, int i, const Vec3& gravity, const Vec3& a_ground, double dt, double dv_dt) {
  const double m = r.mass[i];
  const Vec3 force = (m * gravity + ground_inertial_force(m, a_ground)) + r.contact_force[i];
  const Vec3 torque = r.contact_torque[i];
  const Vec3& inv_I = r.inv_inertia[i];
  const Vec3 v_old = r.velocity[i];
  const Vec3 v_new = v_old + (dv_dt * r.inv_mass[i]) * force;
  const Vec3 L_new = r.angular_momentum[i] + dv_dt * torque;
  const Mat3& R0 = r.rotation[i];
  const Vec3 w0 = R0 * inv_I.cwiseProduct(R0.transpose() * L_new);
  const Mat3 Rh = (rotation_quaternion(0.5 * dt * w0) * r.orientation[i]).toRotationMatrix();
  const Vec3 w = Rh * inv_I.cwiseProduct(Rh.transpose() * L_new);
  const Vec3 w_old = r.angular_velocity[i];
  r.velocity_mid[i] = 0.5 * (v_old + v_new);
  r.omega_mid[i] = 0.5 * (w_old + w);
  r.position_prev[i] = r.position[i];
  r.orientation_prev[i] = r.orientation[i];
  r.load_work[i] += load_work(dt, ground_inertial_force(m, a_ground), r.velocity_mid[i]);
  r.velocity[i] = v_new;
  r.angular_momentum[i] = L_new;
  r.angular_velocity[i] = w;
  r.position[i] += dt * v_new;
  r.orientation[i] = (rotation_quaternion(dt * w) * r.orientation[i]).normalized();
  r.rotation[i] = r.orientation[i].toRotationMatrix();
}

std::vector<block_lanes::AdvanceFour> kernels_here() {
  std::vector<block_lanes::AdvanceFour> k{&block_lanes::advance_four_portable};
#ifdef POLYDEM_LANES_AVX2
  if (lanes_available()) k.push_back(&block_lanes::advance_four_avx2);
#endif
  return k;
}

TEST(BlockUpdateLanes, EveryKernelGivesTheReferenceUpdatesBits) {
  const Vec3 gravity(0, 0, -9.81), a_ground(0.5, -0.2, 0.1);
  const double dt = 1e-5, dv_dt = 1.1e-5;
  const block_lanes::StepConstants k{{gravity.x(), gravity.y(), gravity.z()},
                                     {a_ground.x(), a_ground.y(), a_ground.z()},
                                     dt,
                                     dv_dt};
  for (const block_lanes::AdvanceFour advance : kernels_here()) {
    std::mt19937_64 rng(2);
    Records start(7, rng);
    // Block 3 spins at 200 rad/s about its first axis: ω·dt = 2e-3 rad,
    // |θ|² = 4e-6, beyond the series; block 5 at 140 rad/s (the half step's
    // turn within it, the step's beyond).
    const Mat3& R3 = start.rotation[3];
    start.angular_momentum[3] = R3 * Vec3(200.0 / start.inv_inertia[3].x(), 0, 0);
    const Mat3& R5 = start.rotation[5];
    start.angular_momentum[5] = R5 * Vec3(0, 140.0 / start.inv_inertia[5].y(), 0);
    Records lanes = start, reference = start;
    const int four[4] = {0, 2, 3, 5};
    advance(lanes.arrays(), k, four);
    const int short_group[4] = {6, 4, 4, 4};  // two blocks, the last repeated
    advance(lanes.arrays(), k, short_group);
    for (int i : {0, 2, 3, 5, 6, 4}) reference_update(reference, i, gravity, a_ground, dt, dv_dt);
    for (int i = 0; i < 7; ++i) EXPECT_EQ(lanes.bytes(i), reference.bytes(i)) << "block " << i;
    EXPECT_EQ(lanes.bytes(1), start.bytes(1));  // not in a group: untouched
    EXPECT_NE(lanes.bytes(3), start.bytes(3));
  }
}

}  // namespace
}  // namespace polydem
