// The gather's kernels (contact/gather_lanes.hpp), in plain doubles and in
// AVX2 lanes where the machine has them, give the Eigen sums' bits, one
// block or two in turn: blocks with empty, short and long lists, reference
// and incident entries, forces from 1 N to 1e12 N and points on every side
// of the centroid. Whole runs on either path:
// tests/verification/determinism_test.cpp.
#include "contact/gather.hpp"
#include "core/code_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

namespace polydem {
namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

// A ContactSet of `blocks` blocks with random forces and points; blocks 0-3
// have no subcontact, block 4 over a hundred entries.
ContactSet random_contacts(std::mt19937_64& rng, int blocks) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ContactSet cs;
  for (int q = 0; q < 600; ++q) {
    int a = 4 + static_cast<int>(rng() % (blocks - 4)), b = 4 + static_cast<int>(rng() % (blocks - 4));
    if (q % 5 == 0) a = 4;
    if (a == b) continue;
    const std::size_t s = cs.sub.size();
    cs.sub.resize(s + 1);
    cs.sub.ref_block[s] = a;
    cs.sub.inc_block[s] = b;
    const double scale = std::pow(10.0, 6.0 * (u(rng) + 1.0));  // 1 to 1e12 N
    cs.sub.force[s] = Vec3(u(rng), u(rng), u(rng)) * scale;
    cs.sub.point[s] = Vec3(u(rng), u(rng), u(rng)) * 3.0;
  }
  std::vector<int> scratch;
  build_gather_lists(blocks, cs, scratch);
  return cs;
}

// random_contacts with random centroids, and the force and moment records
// filled with 7 (so that a record not written shows).
struct LaneScene {
  ContactSet cs;
  std::vector<Vec3> centroid, force, torque;
};
LaneScene lane_scene(std::uint64_t seed, int blocks) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  LaneScene s{random_contacts(rng, blocks), std::vector<Vec3>(blocks), std::vector<Vec3>(blocks, Vec3::Constant(7.0)),
              std::vector<Vec3>(blocks, Vec3::Constant(7.0))};
  for (Vec3& x : s.centroid) x = Vec3(u(rng), u(rng), u(rng)) * 3.0;
  return s;
}

// The kernels this machine runs: plain doubles, and AVX2 lanes where it has them.
std::vector<gather_lanes::GatherKernels> kernels_here() {
  std::vector<gather_lanes::GatherKernels> k{gather_kernels(CodePath::portable)};
  if (lanes_available()) k.push_back(gather_kernels(CodePath::lanes));
  return k;
}

// Each kernel gives the bits of the Eigen sums it stands for,
// f += s·F, m += (p − x) × (s·F), in list order; an empty list writes zero.
TEST(Gather, EveryKernelGivesTheEigenSumsBits) {
  constexpr int blocks = 40;
  for (const gather_lanes::GatherKernels& k : kernels_here()) {
    LaneScene s = lane_scene(5, blocks);
    const ContactSet& cs = s.cs;
    const gather_lanes::GatherArrays a = gather_lane_arrays(cs, s.centroid, s.force, s.torque);
    int longest = 0;
    for (int i = 0; i < blocks; ++i) {
      const int length = cs.gather_offset[i + 1] - cs.gather_offset[i];
      longest = std::max(longest, length);
      if (i < 4) {
        ASSERT_EQ(length, 0);
      }
    }
    ASSERT_GT(longest, 100);
    for (int i = 0; i < blocks; ++i) {
      Vec3 f_ref = Vec3::Zero(), m_ref = Vec3::Zero();
      for (int e = cs.gather_offset[i]; e < cs.gather_offset[i + 1]; ++e) {
        const int sc = cs.gather_sub[e];
        const Vec3 fk = cs.gather_sign[e] * cs.sub.force[sc];
        f_ref += fk;
        m_ref += (cs.sub.point[sc] - s.centroid[i]).cross(fk);
      }
      k.block(a, i);
      EXPECT_TRUE(same_bits(s.force[i], f_ref)) << "block " << i;
      EXPECT_TRUE(same_bits(s.torque[i], m_ref)) << "block " << i;
    }
    EXPECT_TRUE(same_bits(s.force[0], Vec3::Zero()));
  }
}

// Two blocks' sums taken in turn keep each block's bits: every pairing of
// an empty (0-3), a short and the longest list (4), either one first, and
// a block with itself.
TEST(GatherLanes, TwoBlocksInTurnGiveEachBlocksBits) {
  for (const gather_lanes::GatherKernels& kernel : kernels_here()) {
    constexpr int blocks = 24;
    LaneScene s = lane_scene(11, blocks);
    const ContactSet& cs = s.cs;
    std::vector<Vec3>& force = s.force;
    std::vector<Vec3>& torque = s.torque;
    std::vector<Vec3> one_force(blocks), one_torque(blocks);
    const gather_lanes::GatherArrays one = gather_lane_arrays(cs, s.centroid, one_force, one_torque);
    for (int b = 0; b < blocks; ++b) kernel.block(one, b);
    const gather_lanes::GatherArrays a = gather_lane_arrays(cs, s.centroid, s.force, s.torque);
    int unequal = 0;
    for (int i = 0; i < blocks; ++i) {
      for (int j = 0; j < blocks; ++j) {
        std::fill(force.begin(), force.end(), Vec3::Constant(7.0));
        std::fill(torque.begin(), torque.end(), Vec3::Constant(7.0));
        kernel.two(a, i, j);
        for (int b : {i, j}) {
          ASSERT_TRUE(same_bits(one_force[b], force[b])) << "blocks " << i << ", " << j << ": block " << b;
          ASSERT_TRUE(same_bits(one_torque[b], torque[b])) << "blocks " << i << ", " << j << ": block " << b;
        }
        const int k = (i + 1) % blocks;  // untouched
        if (k != i && k != j) {
          ASSERT_TRUE(same_bits(force[k], Vec3::Constant(7.0)));
        }
        unequal += cs.gather_offset[i + 1] - cs.gather_offset[i] != cs.gather_offset[j + 1] - cs.gather_offset[j];
      }
    }
    EXPECT_GT(unequal, blocks * blocks / 2);  // most pairings have lists of different lengths
  }
}

}  // namespace
}  // namespace polydem
