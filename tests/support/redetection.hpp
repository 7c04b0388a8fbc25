// How much a joint's force and moment jump when the contacts are detected
// again with the blocks where they are, under either joint model: the
// harness of the overlap model's continuity tests
// (tests/contact/overlap_joint_test.cpp) and of the benchmark that measures
// both models (benchmarks/redetection_jump.cpp).
//
// redetection_jump(): the pairs are found, the blocks given velocities and
// the law evaluated over one step of 1e-4 s (shear and twist stored), the
// free blocks moved and turned at random by a fraction of the margin, the
// law evaluated at that pose (dt = 0) with the contacts held, then the
// contacts found again at the same pose and the law evaluated once more.
// The jump is the largest change of any pair's force on either block or
// moment about either block's centroid, relative to the largest force
// (moment) before; a pair found only before or only after counts with its
// whole force.
#pragma once

#include "contact/clip_joint.hpp"
#include "contact/detection.hpp"
#include "contact/joint_law.hpp"
#include "contact/overlap_joint.hpp"
#include "core/blocks.hpp"
#include "structures/spire.hpp"
#include "tests/support/blocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace polydem::test {

inline void turn(Blocks& b, int i, double angle, const Vec3& axis) {
  b.state.orientation[i] = (Quat(Eigen::AngleAxisd(angle, axis.normalized())) * b.state.orientation[i]).normalized();
  b.state.rotation[i] = b.state.orientation[i].toRotationMatrix();
}

// Moves the free blocks by up to `step` and turns them by up to
// `step`/metre.
inline void perturb(Blocks& b, std::mt19937_64& rng, double step) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i : b.free_blocks) {
    b.state.position[i] += step * Vec3(u(rng), u(rng), u(rng));
    turn(b, i, step * std::abs(u(rng)), Vec3(u(rng), u(rng), u(rng)));
  }
}

inline void set_velocities(Blocks& b, std::mt19937_64& rng, double v) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i : b.free_blocks) {
    b.state.velocity[i] = v * Vec3(u(rng), u(rng), u(rng));
    b.state.angular_velocity[i] = v * Vec3(u(rng), u(rng), u(rng));
  }
}

// The default spire as blocks: its base fixed, every stone free (the scene
// whose joints both the tests and the benchmark re-detect).
inline Blocks default_spire_blocks() {
  const SpireModel model = build_spire(SpireSpec{});
  std::vector<BlockSpec> specs;
  for (const GeneratedBlock& g : model.blocks)
    specs.push_back(block_spec(g.name, g.shape, g.kind == BlockKind::base ? BlockMotion::fixed : BlockMotion::free));
  return build_blocks(specs);
}

// Two free 1 m cubes, the upper one turned to come down on the lower one's
// top face edge-on (about x by 45°) or corner-on (then about y by 35.26°),
// its lowest point `depth` into it.
inline Blocks cube_into_cube(bool corner, double depth) {
  Blocks b = build_blocks({block_spec("below", make_box(Vec3(1, 1, 1), Vec3(0, 0, -0.5)), BlockMotion::free),
                           block_spec("above", make_box(Vec3(1, 1, 1), Vec3(0, 0, 0)), BlockMotion::free)});
  turn(b, 1, std::numbers::pi / 4, Vec3::UnitX());
  if (corner) turn(b, 1, std::atan(1 / std::sqrt(2.0)), Vec3::UnitY());
  double lowest = 1e9;
  for (const Vec3& v : b.props.local_shape[1].vertices) lowest = std::min(lowest, (b.state.rotation[1] * v).z());
  b.state.position[1].z() = -lowest - depth;
  return b;
}

// The joint models compared: subcontacts held fixed in the incident block
// between detections (the default), subcontacts whose points follow the
// blocks (joint_sampling "step"), the joints clipped at every step
// (joint_sampling "clip"), the overlap model.
enum class JointModelKind { subcontacts, subcontacts_step, subcontacts_clip, overlap };

// A pair's wrench: the force on block b (the larger index) and the moment
// on each block about its own centroid.
struct PairWrench {
  Vec3 force_b = Vec3::Zero();
  Vec3 moment_a = Vec3::Zero(), moment_b = Vec3::Zero();
};
using PairWrenches = std::map<std::pair<int, int>, PairWrench>;

// Under "clip", the joints clipped at the blocks' poses as a step does
// (Simulation::clip_all): a pair whose polygon's vertices have changed
// re-sampled at this pose by `det`, and clipped again.
inline void clip_joints(const JointLaws& laws, const Blocks& b, ContactSet& c, ContactDetector& det,
                        std::vector<lanes::PairRest>& rest) {
  ClipScratch s;
  std::vector<std::uint8_t> stale;
  std::vector<double> dropped;
  for (int pass = 0; pass < 2; ++pass) {
    rest.assign(c.pairs.size(), lanes::PairRest{});
    stale.assign(c.pairs.size(), 0);
    dropped.assign(c.pairs.size(), 0.0);
    clip_pairs(b.props.local_shape, b.state, laws, c.pairs, det.margin(), c.sub, rest, stale, dropped, 0, c.pairs.size(),
               s);
    std::vector<int> moved;
    for (std::size_t q = 0; q < stale.size(); ++q)
      if (stale[q]) moved.push_back(static_cast<int>(q));
    if (moved.empty() || pass == 1) return;
    det.resample(b, c, moved, laws);
  }
}

// Evaluates the law over dt and returns every pair's wrench (`det`: the
// detector, which "clip" re-samples with).
inline PairWrenches pair_wrenches(JointModelKind model, const JointLaws& laws, const Blocks& b, ContactSet& c,
                                  OverlapScratch& scratch, double dt, ContactDetector* det = nullptr) {
  const BlockState& st = b.state;
  PairWrenches w;
  auto v3 = [](const double(&a)[3]) { return Vec3(a[0], a[1], a[2]); };
  if (model == JointModelKind::overlap) {
    overlap_joint_forces(laws, b.props.local_shape, st, c.pairs, c.sub, c.joints, dt, 0, c.pairs.size(), scratch);
    for (std::size_t q = 0; q < c.pairs.size(); ++q) {
      const ContactPair& p = c.pairs[q];
      const lanes::PairRest& r = c.joints.wrench[q];  // force and moment on the incident block
      const bool ref_is_b = c.joints.ref_block[q] == p.b;
      PairWrench& x = w[{p.a, p.b}];
      x.force_b = ref_is_b ? Vec3(-v3(r.force)) : v3(r.force);
      x.moment_b = ref_is_b ? v3(r.moment_ref) : v3(r.moment);
      x.moment_a = ref_is_b ? v3(r.moment) : v3(r.moment_ref);
    }
    return w;
  }
  std::vector<lanes::PairRest> rest;
  if (model == JointModelKind::subcontacts_clip)
    clip_joints(laws, b, c, *det, rest);
  else if (c.sub.moving.on)
    move_points(st, c.pairs, c.sub, 0, c.pairs.size());
  compute_pair_forces(laws, st, c.pairs, c.sub, dt, 0, c.pairs.size());
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    const ContactPair& p = c.pairs[q];
    PairWrench& x = w[{p.a, p.b}];
    if (!rest.empty()) {  // the clip's rest: force on the incident block, moments about each centroid
      const lanes::PairRest& r = rest[q];
      const bool ref_is_b = p.ref_block == p.b;
      x.force_b += ref_is_b ? Vec3(-v3(r.force)) : v3(r.force);
      x.moment_b += ref_is_b ? v3(r.moment_ref) : v3(r.moment);
      x.moment_a += ref_is_b ? v3(r.moment) : v3(r.moment_ref);
    }
    for (int k = p.first; k < p.first + p.count; ++k) {
      const Vec3 f_b = c.sub.inc_block[k] == p.b ? c.sub.force[k] : Vec3(-c.sub.force[k]);
      const Vec3& at = c.sub.point[k];
      x.force_b += f_b;
      x.moment_b += (at - st.position[p.b]).cross(f_b);
      x.moment_a += (at - st.position[p.a]).cross(Vec3(-f_b));
    }
  }
  return w;
}

// The largest change from `before` to `after`, relative to the largest
// force (moment) before; infinite when nothing was loaded.
inline double worst_jump(const PairWrenches& before, const PairWrenches& after) {
  double fmax = 0, mmax = 0;
  for (const auto& [k, x] : before) {
    fmax = std::max(fmax, x.force_b.norm());
    mmax = std::max({mmax, x.moment_a.norm(), x.moment_b.norm()});
  }
  if (!(fmax > 0 && mmax > 0)) return std::numeric_limits<double>::infinity();
  double worst = 0;
  auto consider = [&](const PairWrench& a, const PairWrench& b) {
    worst = std::max({worst, (a.force_b - b.force_b).norm() / fmax, (a.moment_a - b.moment_a).norm() / mmax,
                      (a.moment_b - b.moment_b).norm() / mmax});
  };
  const PairWrench zero;
  for (const auto& [k, x] : before) {
    const auto it = after.find(k);
    consider(x, it == after.end() ? zero : it->second);
  }
  for (const auto& [k, x] : after)
    if (!before.count(k)) consider(zero, x);
  return worst;
}

struct RedetectionJump {
  double worst = 0;
  std::size_t pairs = 0;  // the more of before and after
};

// `move`: the free blocks' random move between the detections, as a
// fraction of `margin`. `seed` seeds the velocities and the move.
inline RedetectionJump redetection_jump(JointModelKind model, Blocks& blocks, const JointLaws& laws, double margin,
                                        std::uint64_t seed, double move) {
  ContactDetector det(blocks, margin);
  det.set_pair_joints(model == JointModelKind::overlap);
  det.set_points_follow(model == JointModelKind::subcontacts_step || model == JointModelKind::subcontacts_clip);
  det.set_clipped(model == JointModelKind::subcontacts_clip);
  ContactSet c;
  OverlapScratch scratch;
  std::mt19937_64 rng(seed);
  det.detect(blocks, c, false, laws);
  set_velocities(blocks, rng, 1e-2);
  pair_wrenches(model, laws, blocks, c, scratch, 1e-4, &det);  // shear and twist stored
  perturb(blocks, rng, move * margin);
  const PairWrenches before = pair_wrenches(model, laws, blocks, c, scratch, 0.0, &det);
  det.detect(blocks, c, false, laws);
  const PairWrenches after = pair_wrenches(model, laws, blocks, c, scratch, 0.0, &det);
  return {worst_jump(before, after), std::max(before.size(), after.size())};
}

// The default spire pressed (its free blocks moved by up to 0.2 mm from
// `seed`), under one law, its jump at a re-detection after its blocks moved
// by `move` of the 3 mm margin (the continuity tests' scene).
inline double spire_redetection_jump(JointModelKind model, std::uint64_t seed, double move) {
  Blocks blocks = default_spire_blocks();
  const JointLaws laws = uniform_joint_laws(round_law(0.5), blocks.count);
  std::mt19937_64 rng(seed);
  perturb(blocks, rng, 2e-4);
  return redetection_jump(model, blocks, laws, 0.003, seed + 100, move).worst;
}

}  // namespace polydem::test
