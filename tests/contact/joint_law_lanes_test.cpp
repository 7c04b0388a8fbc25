// The joint law's kernel in its lane types, AVX2 (and AVX-512VL) and plain doubles
// (joint_law_kernels.hpp), give the same bits: every array the law writes is
// compared bit for bit, on random pairs that reach every branch of the law
// (open, closed, bonded in tension, the bond lost — in tension, on opening
// or by slip — slipping, sticking, zero area, no shear stiffness, no
// damping), with pairs of 1 to 9 subcontacts (full and partial groups of
// four lanes). Whole runs on either path:
// tests/verification/determinism_test.cpp.
#include "contact/joint_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>

namespace polydem {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}
bool same_bits(const Vec3Array& a, const Vec3Array& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

// Every array the law writes, bit for bit.
void expect_same_bits(const Subcontacts& a, const Subcontacts& b, int trial) {
  EXPECT_TRUE(same_bits(a.force, b.force)) << trial;
  EXPECT_TRUE(same_bits(a.point, b.point)) << trial;
  EXPECT_TRUE(same_bits(a.overlap, b.overlap)) << trial;
  EXPECT_TRUE(same_bits(a.normal_force, b.normal_force)) << trial;
  EXPECT_TRUE(same_bits(a.shear_force, b.shear_force)) << trial;
  EXPECT_TRUE(same_bits(a.damping_force, b.damping_force)) << trial;
  EXPECT_TRUE(same_bits(a.slip_energy, b.slip_energy)) << trial;
  EXPECT_TRUE(same_bits(a.damping_energy, b.damping_energy)) << trial;
  EXPECT_EQ(a.bonded, b.bonded) << trial;
}

Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
}

Vec3 random_vec(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

struct Scene {
  BlockState st;
  std::vector<ContactPair> pairs;
  Subcontacts sub;
};
int blocks_of(const Scene& s) { return static_cast<int>(s.st.position.size()); }

// `blocks` blocks at random poses and motions, pairs between neighbours with
// 1..9 subcontacts each, overlaps of both signs, random stored forces.
Scene random_scene(std::mt19937_64& rng, int blocks, double spin = 0.2) {
  Scene s;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < blocks; ++i) {
    s.st.position.push_back(random_vec(rng, 2.0));
    s.st.orientation.push_back(random_rotation(rng));
    s.st.rotation.push_back(s.st.orientation.back().toRotationMatrix());
    s.st.velocity.push_back(random_vec(rng, 0.05));
    s.st.angular_velocity.push_back(random_vec(rng, spin));
  }
  std::uniform_int_distribution<int> count(1, 9);
  for (int a = 0; a + 1 < blocks; ++a) {
    ContactPair cp;
    cp.a = a;
    cp.b = a + 1;
    cp.ref_block = u(rng) < 0.5 ? a : a + 1;
    cp.first = static_cast<int>(s.sub.size());
    cp.count = count(rng);
    const int ref = cp.ref_block, inc = ref == a ? a + 1 : a;
    const Vec3 n_local = random_vec(rng, 1.0).normalized();
    for (int k = 0; k < cp.count; ++k) {
      const std::size_t i = s.sub.size();
      s.sub.resize(i + 1);
      s.sub.pair[i] = static_cast<int>(s.pairs.size());
      s.sub.ref_block[i] = ref;
      s.sub.inc_block[i] = inc;
      s.sub.ref_normal_local[i] = n_local;
      s.sub.inc_point_local.set(i, random_vec(rng, 0.3));
      // The plane through the incident point, shifted by up to ±1 mm (or
      // ±0.1 µm, where a bond holds the tension): half the subcontacts
      // closed, half open.
      const Vec3 n = s.st.rotation[ref] * n_local;
      const Vec3 p = s.st.position[inc] + s.st.rotation[inc] * s.sub.inc_point_local[i];
      const double un = (u(rng) - 0.5) * (u(rng) < 0.3 ? 2e-7 : 2e-3);
      s.sub.ref_offset_local[i] = n.dot(p) - n.dot(s.st.position[ref]) + un;
      s.sub.area[i] = u(rng) < 0.05 ? 0.0 : 0.01 + 0.05 * u(rng);
      s.sub.bonded[i] = u(rng) < 0.4 ? 1 : 0;
      // Stored shear from nothing to well past the cap (slip).
      s.sub.shear_force.set(i, random_vec(rng, u(rng) < 0.5 ? 1e3 : 1e7));
      s.sub.damping_force.set(i, u(rng) < 0.3 ? Vec3::Zero() : random_vec(rng, 1e4));
      s.sub.slip_energy[i] = u(rng);
      s.sub.damping_energy[i] = u(rng);
    }
    s.pairs.push_back(cp);
  }
  return s;
}

struct Branches {
  int open = 0, closed = 0, tension = 0, broken = 0, slipping = 0, sticking = 0;
};

// Which branches the law took (read from the portable path's results).
void count_branches(const Subcontacts& before, const Subcontacts& after, Branches& b) {
  for (std::size_t s = 0; s < after.size(); ++s) {
    const bool was_bonded = before.bonded[s] != 0;
    if (after.normal_force[s] == 0 && after.shear_force[s].isZero(0.0)) {
      ++b.open;
    } else {
      ++b.closed;
      if (after.overlap[s] <= 0) ++b.tension;
    }
    if (was_bonded && after.bonded[s] == 0) ++b.broken;
    if (after.slip_energy[s] != before.slip_energy[s] && after.normal_force[s] != 0) ++b.slipping;
    else if (after.normal_force[s] != 0) ++b.sticking;
  }
}

TEST(JointLawLanes, SameBitsAsThePortableLoopOnEveryBranch) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 on this machine or build: only the portable path runs";
  std::mt19937_64 rng(12);
  // Laws: Table 1's dry joint, a bonded one with tension and cohesion, one
  // with no shear stiffness, one without damping, the bonded one with
  // friction on the spring's and the dashpot's force.
  std::vector<JointLaw> laws(5);
  laws[0].kn = 1e10, laws[0].ks = 4e9, laws[0].tan_phi = std::tan(0.6), laws[0].beta = 2.1e-5;
  laws[1] = laws[0], laws[1].cohesion = 1e5, laws[1].tensile_strength = 5e4;
  laws[2] = laws[0], laws[2].ks = 0;
  laws[3] = laws[1], laws[3].beta = 0;
  laws[4] = laws[1], laws[4].friction_on_total = true;  // friction on the spring's and dashpot's force
  Branches seen;
  int trial = 0;
  for (const JointLaw& law : laws) {
    for (int t = 0; t < 25; ++t, ++trial) {
      Scene s = random_scene(rng, 12);
      const Subcontacts before = s.sub;
      // The AVX2 kernel, and where the CPU has AVX-512VL the copy compiled
      // for it (CodePath::lanes takes it there).
      Subcontacts lanes = s.sub, avx2 = s.sub, portable = s.sub;
      for (const double dt : {1e-5, 0.0}) {
        compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, lanes, dt, 0, s.pairs.size(), CodePath::lanes);
        compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, avx2, dt, 0, s.pairs.size(), CodePath::lanes_avx2);
        compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, portable, dt, 0, s.pairs.size(), CodePath::portable);
        expect_same_bits(lanes, portable, trial);
        expect_same_bits(avx2, portable, trial);
      }
      count_branches(before, portable, seen);
    }
  }
  // The random scenes reach every branch (the comparison above means
  // something only if they do).
  EXPECT_GT(seen.open, 100);
  EXPECT_GT(seen.closed, 100);
  EXPECT_GT(seen.tension, 10);
  EXPECT_GT(seen.broken, 10);
  EXPECT_GT(seen.slipping, 100);
  EXPECT_GT(seen.sticking, 10);
}

// Joints turning beyond rotation_matrix's series in a step (|θ|² ≥ 1e-6:
// blocks spinning at hundreds of rad/s) take rotation_matrix's closed form
// on the lanes path too: the same bits, and such pairs occur.
TEST(JointLawLanes, JointsTurningBeyondTheSeriesGiveTheSameBits) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 on this machine or build";
  std::mt19937_64 rng(21);
  JointLaw law;
  law.kn = 1e10, law.ks = 4e9, law.tan_phi = 0.7, law.beta = 2e-5;
  const double dt = 1e-5;
  int beyond = 0, within = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Scene s = random_scene(rng, 12, trial % 2 == 0 ? 400.0 : 50.0);
    for (const ContactPair& cp : s.pairs) {
      const int r = cp.ref_block, c = r == cp.a ? cp.b : cp.a;
      const Vec3 n = s.st.rotation[r] * s.sub.ref_normal_local[cp.first];
      const Vec3& wr = s.st.angular_velocity[r];
      const Vec3 t = dt * (wr + (0.5 * (s.st.angular_velocity[c] - wr).dot(n)) * n);
      (t.squaredNorm() < 1e-6 ? within : beyond) += 1;
    }
    for (const CodePath path : {CodePath::lanes, CodePath::lanes_avx2}) {
      Subcontacts lanes = s.sub, portable = s.sub;
      compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, lanes, dt, 0, s.pairs.size(), path);
      compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, portable, dt, 0, s.pairs.size(), CodePath::portable);
      expect_same_bits(lanes, portable, trial);
    }
  }
  EXPECT_GT(beyond, 50);
  EXPECT_GT(within, 10);
}

// A pair's range split across two calls (two threads' halves) gives the
// same bits as one call.
TEST(JointLawLanes, PairRangesSplitAnywhereGiveTheSameBits) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 on this machine or build";
  std::mt19937_64 rng(5);
  JointLaw law;
  law.kn = 1e10, law.ks = 4e9, law.tan_phi = 0.7, law.beta = 2e-5;
  Scene s = random_scene(rng, 30);
  Subcontacts whole = s.sub;
  compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, whole, 1e-5, 0, s.pairs.size(), CodePath::lanes);
  for (std::size_t cut = 0; cut <= s.pairs.size(); cut += 7) {
    Subcontacts split = s.sub;
    compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, split, 1e-5, cut, s.pairs.size(), CodePath::lanes);
    compute_pair_forces(uniform_joint_laws(law, blocks_of(s)), s.st, s.pairs, split, 1e-5, 0, cut, CodePath::lanes);
    expect_same_bits(whole, split, static_cast<int>(cut));
  }
}

}  // namespace
}  // namespace polydem

namespace polydem {
namespace {

// The split damping scheme's two parts on both paths: the law with part
// 1 − θ of each dashpot, writing each subcontact's DashpotState, and the
// rest pass (apply_dashpot_rest) from predicted velocities, on the same
// random scenes: every array either writes and each pair's rest force and
// moments, bit for bit, with the rest's
// clamp (an unbonded joint's normal force held at zero), bonded joints,
// shear dashpots on and off (slipping) and subcontacts with no dashpot
// (open) all reached. A wrong state bit, association or lane mask fails it.
TEST(JointLawLanes, TheSplitSchemesPartsGiveTheSameBits) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 on this machine or build";
  std::mt19937_64 rng(33);
  JointLaw law;
  law.kn = 1e10, law.ks = 4e9, law.tan_phi = std::tan(0.6), law.beta = 2.1e-3;
  law.cohesion = 1e5, law.tensile_strength = 5e4;
  const double theta = 0.32, dt = 1e-5;
  int none = 0, normal_only = 0, both = 0, clamped = 0, bonded_acting = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Scene s = random_scene(rng, 12);
    const JointLaws laws = uniform_joint_laws(law, blocks_of(s));
    std::vector<Vec3> v_next(s.st.velocity.size()), w_next(s.st.velocity.size());
    for (std::size_t i = 0; i < v_next.size(); ++i) {
      v_next[i] = s.st.velocity[i] + random_vec(rng, 0.5);
      w_next[i] = s.st.angular_velocity[i] + random_vec(rng, 2.0);
    }
    std::vector<Subcontacts> results;
    std::vector<std::vector<std::uint8_t>> states;
    std::vector<std::vector<lanes::PairRest>> rests;
    std::vector<Vec3Array> rest_forces;
    for (const CodePath path : {CodePath::portable, CodePath::lanes, CodePath::lanes_avx2}) {
      Subcontacts sub = s.sub;
      std::vector<std::uint8_t> state(sub.size(), 9);
      std::vector<lanes::PairRest> rest(s.pairs.size());
      for (lanes::PairRest& p : rest) std::fill(&p.force[0], &p.force[0] + 9, 7.0);  // a slot not written shows
      compute_pair_forces(laws, s.st, s.pairs, sub, dt, 0, s.pairs.size(), path, SplitPart{1.0 - theta, state.data()});
      const std::vector<double> law_normal = sub.normal_force;
      Vec3Array rest_force;
      rest_force.assign(sub.size(), Vec3::Constant(7.0));
      apply_dashpot_rest(laws, theta, s.st, v_next, w_next, s.pairs, state.data(), sub, rest, rest_force, 0,
                         s.pairs.size(), path);
      if (path == CodePath::portable) {
        for (std::size_t k = 0; k < sub.size(); ++k) {
          none += state[k] == 0;
          normal_only += state[k] == kNormalDashpot;
          both += state[k] == (kNormalDashpot | kShearDashpot);
          clamped += state[k] != 0 && sub.normal_force[k] == 0 && law_normal[k] > 0;
          bonded_acting += state[k] != 0 && sub.bonded[k] != 0;
        }
      }
      results.push_back(sub);
      states.push_back(state);
      rests.push_back(rest);
      rest_forces.push_back(rest_force);
    }
    for (std::size_t p = 1; p < results.size(); ++p) {
      expect_same_bits(results[p], results[0], trial);
      EXPECT_EQ(states[p], states[0]) << trial;
      EXPECT_EQ(std::memcmp(rests[p].data(), rests[0].data(), rests[0].size() * sizeof(lanes::PairRest)), 0) << trial;
      EXPECT_TRUE(same_bits(rest_forces[p], rest_forces[0])) << trial;
    }
  }
  EXPECT_GT(none, 100);
  EXPECT_GT(normal_only, 20);
  EXPECT_GT(both, 100);
  EXPECT_GT(clamped, 5);
  EXPECT_GT(bonded_acting, 10);
}

}  // namespace
}  // namespace polydem
