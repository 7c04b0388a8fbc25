// ContactDetector: subcontact persistence across detections, and the
// half-margin rule that decides when detection has to run again.
//
// Scene: a fixed 3 × 3 × 1 base with its top at z = 0 and a free unit cube
// resting on it (bottom at z = 0). Margin 0.02 m.
#include "contact/detection.hpp"
#include "contact/joint_law.hpp"

#include "tests/support/blocks.hpp"
#include "tests/support/redetection.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <algorithm>
#include <random>
#include <numbers>
#include <numeric>

namespace polydem {
namespace {

constexpr double kMargin = 0.02;
// The joint law's stiffnesses price what a detection re-samples.
const JointLaw kLaw = test::round_law(0.0);

using test::block_spec;

Blocks resting_cube() {
  return build_blocks({block_spec("base", make_box(Vec3(3, 3, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                       block_spec("cube", make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5)), BlockMotion::free)});
}

void translate(Blocks& b, int i, const Vec3& d) { b.state.position[i] += d; }

void turn(Blocks& b, int i, double angle, const Vec3& axis) {
  b.state.orientation[i] = (Quat(Eigen::AngleAxisd(angle, axis)) * b.state.orientation[i]).normalized();
  b.state.rotation[i] = b.state.orientation[i].toRotationMatrix();
}

TEST(ContactDetector, FindsTheRestingPatch) {
  Blocks b = resting_cube();
  ContactDetector det(b, kMargin);
  EXPECT_EQ(det.margin(), kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_EQ(cs.detections, 1);
  ASSERT_EQ(cs.pairs.size(), 1u);
  EXPECT_EQ(cs.pairs[0].a, 0);
  EXPECT_EQ(cs.pairs[0].b, 1);
  EXPECT_EQ(cs.pairs[0].count, 4);
  EXPECT_NEAR(cs.pairs[0].patch_area, 1.0, 1e-12);
  ASSERT_EQ(cs.sub.size(), 4u);
  double area = 0;
  for (std::size_t s = 0; s < cs.sub.size(); ++s) {
    area += cs.sub.area[s];
    EXPECT_NEAR(cs.sub.overlap[s], 0.0, 1e-12);  // just touching
    EXPECT_EQ(cs.sub.bonded[s], 0);
    EXPECT_NE(cs.sub.ref_block[s], cs.sub.inc_block[s]);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  // Gather lists: each subcontact appears once for each of its two blocks,
  // +1 on the incident block and −1 on the reference block.
  ASSERT_EQ(cs.gather_offset.size(), 3u);
  EXPECT_EQ(cs.gather_offset[1] - cs.gather_offset[0], 4);
  EXPECT_EQ(cs.gather_offset[2] - cs.gather_offset[1], 4);
  for (int i = 0; i < 2; ++i)
    for (int k = cs.gather_offset[i]; k < cs.gather_offset[i + 1]; ++k) {
      const int s = cs.gather_sub[k];
      EXPECT_EQ(cs.gather_sign[k], cs.sub.inc_block[s] == i ? 1.0 : -1.0);
    }
  // Bonded when asked, under a law with a strength (cohesion or tension at
  // t = 0); a law without one bonds nothing.
  JointLaw strong = kLaw;
  strong.cohesion = 1e5;
  ContactDetector det2(b, kMargin);
  ContactSet cs2;
  det2.detect(b, cs2, true, uniform_joint_laws(strong, b.count));
  for (std::size_t s = 0; s < cs2.sub.size(); ++s) EXPECT_EQ(cs2.sub.bonded[s], 1);
  ContactDetector det3(b, kMargin);
  ContactSet cs3;
  det3.detect(b, cs3, true, uniform_joint_laws(kLaw, b.count));
  for (std::size_t s = 0; s < cs3.sub.size(); ++s) EXPECT_EQ(cs3.sub.bonded[s], 0);
}

TEST(ContactDetector, SubcontactsKeepTheirHistoryAcrossDetections) {
  Blocks b = resting_cube();
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, true, uniform_joint_laws(kLaw, b.count));
  ASSERT_EQ(cs.sub.size(), 4u);
  // Give every subcontact its own history, remembered by key.
  std::map<std::uint64_t, Vec3> shear;
  std::map<std::uint64_t, double> slip, damp;
  for (std::size_t s = 0; s < cs.sub.size(); ++s) {
    cs.sub.shear_force.set(s, Vec3(100.0 * (s + 1), -7.0 * s, 0));
    cs.sub.slip_energy[s] = 0.5 + s;
    cs.sub.damping_energy[s] = 0.25 * s;
    cs.sub.bonded[s] = s % 2;
    shear[cs.sub.key[s]] = cs.sub.shear_force[s];
    slip[cs.sub.key[s]] = cs.sub.slip_energy[s];
    damp[cs.sub.key[s]] = cs.sub.damping_energy[s];
  }
  ASSERT_EQ(shear.size(), 4u) << "keys must be distinct";
  std::map<std::uint64_t, int> bonded;
  for (std::size_t s = 0; s < cs.sub.size(); ++s) bonded[cs.sub.key[s]] = cs.sub.bonded[s];
  // The cube slides a little (less than the margin, same features): detect again.
  translate(b, 1, Vec3(0.004, -0.003, 0));
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_EQ(cs.detections, 2);
  ASSERT_EQ(cs.sub.size(), 4u);
  for (std::size_t s = 0; s < cs.sub.size(); ++s) {
    const std::uint64_t k = cs.sub.key[s];
    ASSERT_EQ(shear.count(k), 1u) << "key " << k << " is new";
    EXPECT_EQ(cs.sub.shear_force[s], shear[k]);
    EXPECT_EQ(cs.sub.slip_energy[s], slip[k]);
    EXPECT_EQ(cs.sub.damping_energy[s], damp[k]);
    EXPECT_EQ(cs.sub.bonded[s], bonded[k]);
  }
  EXPECT_EQ(cs.retired_slip_energy, 0.0);
}

TEST(ContactDetector, LostSubcontactsRetireTheirDissipation) {
  Blocks b = resting_cube();
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  ASSERT_EQ(cs.sub.size(), 4u);
  for (std::size_t s = 0; s < cs.sub.size(); ++s) {
    cs.sub.slip_energy[s] = 1.0 + s;      // 1+2+3+4 = 10 J
    cs.sub.damping_energy[s] = 0.5 * s;  // 0+0.5+1+1.5 = 3 J
  }
  translate(b, 1, Vec3(0, 0, 0.1));  // lifted beyond the margin
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_TRUE(cs.pairs.empty());
  EXPECT_EQ(cs.sub.size(), 0u);
  EXPECT_EQ(cs.retired_slip_energy, 10.0);
  EXPECT_EQ(cs.retired_damping_energy, 3.0);
}

TEST(ContactDetector, RedetectsOnlyAfterHalfTheMargin) {
  Blocks b = resting_cube();
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_FALSE(det.needs_detection(b));
  // Translation (the threshold is margin/2): 0.49·margin no, 0.51·margin yes.
  translate(b, 1, Vec3(0.49 * kMargin, 0, 0));
  EXPECT_FALSE(det.needs_detection(b));
  translate(b, 1, Vec3(0.02 * kMargin, 0, 0));
  EXPECT_TRUE(det.needs_detection(b));
  // After detection the reference is the new position.
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_FALSE(det.needs_detection(b));
  // Rotation counts as angle × bounding radius (√3/2 for the unit cube).
  const double radius = b.props.radius[1];
  EXPECT_NEAR(radius, std::sqrt(3.0) / 2.0, 1e-12);
  turn(b, 1, 0.49 * kMargin / radius, Vec3::UnitZ());  // corners travel 0.49·margin
  EXPECT_FALSE(det.needs_detection(b));
  turn(b, 1, 0.02 * kMargin / radius, Vec3::UnitZ());  // 0.51·margin in all
  EXPECT_TRUE(det.needs_detection(b));
  // Fixed blocks are ignored however far they are moved (they never move).
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  translate(b, 0, Vec3(1, 0, 0));
  EXPECT_FALSE(det.needs_detection(b));
}

// Relative approach: two free blocks each moving 0.3·margin towards each
// other close their gap by 0.6·margin, more than half the margin, though
// neither moved half the margin: detection must run. The same motion of
// both in the same direction closes nothing (a common drift does not
// count); and the coming step at the current speed counts.
TEST(ContactDetector, RedetectsOnTheRelativeApproachOfTwoBlocks) {
  Blocks b = build_blocks({block_spec("left", make_box(Vec3(1, 1, 1), Vec3(-0.51, 0, 0.5)), BlockMotion::free),
                           block_spec("right", make_box(Vec3(1, 1, 1), Vec3(0.51, 0, 0.5)), BlockMotion::free)});
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  translate(b, 0, Vec3(0.3 * kMargin, 0, 0));
  translate(b, 1, Vec3(-0.3 * kMargin, 0, 0));
  EXPECT_TRUE(det.needs_detection(b));
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  translate(b, 0, Vec3(0.6 * kMargin, 0, 0));
  translate(b, 1, Vec3(0.6 * kMargin, 0, 0));
  EXPECT_FALSE(det.needs_detection(b));
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  b.state.velocity[0] = Vec3(1.0, 0, 0);
  EXPECT_FALSE(det.needs_detection(b, 0.4 * kMargin));  // the step moves it 0.4·margin
  EXPECT_TRUE(det.needs_detection(b, 0.6 * kMargin));
}

TEST(ContactDetector, NeverPairsTwoBlocksThatCannotMove) {
  Blocks b = build_blocks({block_spec("fixed", make_box(Vec3(1, 1, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                           block_spec("moving", make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5)), BlockMotion::kinematic)});
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(kLaw, b.count));
  EXPECT_TRUE(cs.pairs.empty());
}


// A block dragged over the edge of the block below it in small steps while
// the joint sticks (friction far above the shear): the joint's elastic shear
// displacement is the distance dragged, d, everywhere on the patch, so its
// shear stress is ks·d. The drag, three margins, re-detects the joint five
// times; from the third on, the two corners past the lower block's edge are
// clipped into two crossings on that edge (a clip topology the detection
// before did not have) and the patch shrinks. The shear stress must be continuous
// across each re-detection (it halved when the crossings started without
// history), and the strain energy of the area lost is booked as dropped.
TEST(ContactDetector, ShearStressIsContinuousAcrossReDetectionWhileStuck) {
  const double overlap = 1e-4;  // m: the joint is closed
  Blocks b = build_blocks(
      {block_spec("below", make_box(Vec3(1, 1, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
       block_spec("above", make_box(Vec3(0.8, 0.8, 0.5), Vec3(0.08, 0.05, 0.25 - overlap)), BlockMotion::free)});
  JointLaw law;
  law.kn = 1e10;
  law.ks = 1e9;
  law.tan_phi = 1e3;  // stuck
  ContactDetector det(b, kMargin);
  ContactSet cs;
  det.detect(b, cs, false, uniform_joint_laws(law, b.count));
  const double dt = 1e-4, v = 0.5;  // m/s along x: 50 µm a step
  b.state.velocity[1] = Vec3(v, 0, 0);
  auto total = [&](double& area) {
    Vec3 f = Vec3::Zero();
    area = 0;
    for (std::size_t s = 0; s < cs.sub.size(); ++s) {
      f += cs.sub.shear_force[s];
      area += cs.sub.area[s];
    }
    return f;
  };
  int redetections = 0, crossings = 0;
  double worst_jump = 0, dropped_expected = 0;
  for (int step = 0; step < 1200; ++step) {  // 6 cm, three margins
    const double dragged = step * v * dt;   // since the first detection
    if (det.needs_detection(b, dt)) {
      double area_before = 0, area_after = 0;
      const Vec3 before = total(area_before);
      det.detect(b, cs, false, uniform_joint_laws(law, b.count));
      const Vec3 after = total(area_after);
      ++redetections;
      for (std::size_t s = 0; s < cs.sub.size(); ++s) crossings += (cs.sub.key[s] & 0x80000000u) ? 1 : 0;
      // Stress before and after, against ks·d.
      const double expected = law.ks * dragged;
      worst_jump = std::max(worst_jump, (after / area_after - before / area_before).norm() / expected);
      EXPECT_NEAR(after.norm() / area_after, expected, 1e-9 * expected) << "re-detection " << redetections;
      dropped_expected += 0.5 * law.ks * dragged * dragged * (area_before - area_after);
    }
    compute_pair_forces(uniform_joint_laws(law, b.count), b.state, cs.pairs, cs.sub, dt, 0, cs.pairs.size());
    translate(b, 1, Vec3(v * dt, 0, 0));
  }
  std::printf("dragged 6 cm: %d re-detections, %d crossing subcontacts, worst stress jump %.2e of ks*d, dropped %.4g J "
              "(expected %.4g J)\n",
              redetections, crossings, worst_jump, cs.dropped_shear_energy, dropped_expected);
  EXPECT_GE(redetections, 5);
  EXPECT_GT(crossings, 0) << "the clip's topology must change (the test's premise)";
  EXPECT_LT(worst_jump, 1e-9);
  EXPECT_NEAR(cs.dropped_shear_energy, dropped_expected, 1e-9 * dropped_expected);
}

// Pair by pair (simulation.detection_trigger = "pair"): two cubes resting on
// one base, 3 m apart, travel 2 mm, margin 20 mm.
Blocks two_resting_cubes() {
  return build_blocks({block_spec("base", make_box(Vec3(6, 3, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                       block_spec("left", make_box(Vec3(1, 1, 1), Vec3(-1.5, 0, 0.5)), BlockMotion::free),
                       block_spec("right", make_box(Vec3(1, 1, 1), Vec3(1.5, 0, 0.5)), BlockMotion::free)});
}

// The subcontacts of pair q, every array, as bytes: what "taken over whole"
// must leave bit for bit.
std::string pair_bytes(const ContactSet& c, std::size_t q) {
  ContactSet one;
  const ContactPair& p = c.pairs[q];
  one.pairs.push_back(p);
  one.pairs.back().first = 0;
  one.sub.resize(static_cast<std::size_t>(p.count));
  for (int k = 0; k < p.count; ++k) {
    const std::size_t s = static_cast<std::size_t>(p.first + k), d = static_cast<std::size_t>(k);
    one.sub.pair[d] = 0;
    one.sub.ref_block[d] = c.sub.ref_block[s];
    one.sub.inc_block[d] = c.sub.inc_block[s];
    one.sub.key[d] = c.sub.key[s];
    one.sub.ref_normal_local[d] = c.sub.ref_normal_local[s];
    one.sub.ref_offset_local[d] = c.sub.ref_offset_local[s];
    one.sub.inc_point_local.set(d, c.sub.inc_point_local[s]);
    one.sub.area[d] = c.sub.area[s];
    one.sub.crush[d] = c.sub.crush[s];
    one.sub.shear_force.set(d, c.sub.shear_force[s]);
    one.sub.bonded[d] = c.sub.bonded[s];
    one.sub.slip_energy[d] = c.sub.slip_energy[s];
    one.sub.damping_energy[d] = c.sub.damping_energy[s];
  }
  std::string out;
  ByteWriter w(out);
  w.put(one.pairs[0].ref_block);
  w.put(one.pairs[0].ref_face);
  w.put(one.pairs[0].patch_area);
  w.put(one.sub.ref_normal_local);
  w.put(one.sub.ref_offset_local);
  w.put(one.sub.inc_point_local);
  w.put(one.sub.area);
  w.put(one.sub.crush);
  w.put(one.sub.shear_force);
  w.put(one.sub.slip_energy);
  return out;
}

// The cube that moved by more than the travel is re-sampled, as a
// scene-wide detection would re-sample it (its shear carried by position);
// the one that did not is taken over bit for bit; no scene-wide detection
// runs while no two blocks may have closed by half the margin.
TEST(PairTrigger, OnlyTheMovedPairIsResampled) {
  const JointLaws laws = uniform_joint_laws(kLaw, 3);
  Blocks b = two_resting_cubes(), s = two_resting_cubes();
  ContactDetector pairwise(b, kMargin, 0.002), scene(s, kMargin, 0.002);
  pairwise.set_pair_trigger(true);
  EXPECT_DOUBLE_EQ(pairwise.scene_threshold(), 0.5 * kMargin);
  EXPECT_DOUBLE_EQ(scene.scene_threshold(), 0.002);
  ContactSet cp, cs;
  pairwise.detect(b, cp, false, laws);
  scene.detect(s, cs, false, laws);
  ASSERT_EQ(cp.pairs.size(), 2u);
  EXPECT_EQ(pairwise.pairs_resampled(), 2);
  // Shear on both joints, the same in both sets.
  for (std::size_t k = 0; k < cp.sub.size(); ++k) {
    const Vec3 f(10.0 + k, -5.0, 0.0);
    cp.sub.shear_force.set(k, f);
    cs.sub.shear_force.set(k, f);
    cp.sub.slip_energy[k] = cs.sub.slip_energy[k] = 0.25 * k;
  }
  const std::string right_before = pair_bytes(cp, 1);
  std::vector<int> moved;
  EXPECT_FALSE(pairwise.moved_pairs(b, cp, 0.0, moved));

  // The left cube slides 5 mm and turns a little: more than the travel,
  // less than half the margin.
  translate(b, 1, Vec3(0.005, 0, 0));
  turn(b, 1, 1e-3, Vec3::UnitZ());
  translate(s, 1, Vec3(0.005, 0, 0));
  turn(s, 1, 1e-3, Vec3::UnitZ());
  EXPECT_FALSE(pairwise.needs_detection(b));
  EXPECT_TRUE(scene.needs_detection(s));
  ASSERT_TRUE(pairwise.moved_pairs(b, cp, 0.0, moved));
  ASSERT_EQ(moved, std::vector<int>{0});
  // The coming step counts: the right cube about to move by the travel.
  b.state.velocity[2] = Vec3(1.0, 0, 0);
  std::vector<int> ahead;
  pairwise.moved_pairs(b, cp, 0.0021, ahead);
  EXPECT_EQ(ahead, (std::vector<int>{0, 1}));
  b.state.velocity[2] = Vec3::Zero();

  pairwise.resample(b, cp, moved, laws);
  scene.detect(s, cs, false, laws);
  EXPECT_EQ(cp.detections, 1) << "a re-sampling is not a scene-wide detection";
  EXPECT_EQ(pairwise.pairs_resampled(), 3);
  ASSERT_EQ(cp.pairs.size(), 2u);
  EXPECT_EQ(pair_bytes(cp, 1), right_before) << "the unmoved pair, taken over whole";
  // The moved pair as the scene-wide detection samples it.
  const ContactPair &a = cp.pairs[0], &c = cs.pairs[0];
  ASSERT_EQ(a.count, c.count);
  EXPECT_NEAR(a.patch_area, c.patch_area, 1e-12);
  for (int k = 0; k < a.count; ++k) {
    const std::size_t i = static_cast<std::size_t>(a.first + k), j = static_cast<std::size_t>(c.first + k);
    EXPECT_NEAR((cp.sub.point[i] - cs.sub.point[j]).norm(), 0.0, 1e-12) << k;
    EXPECT_NEAR(cp.sub.area[i], cs.sub.area[j], 1e-12) << k;
    EXPECT_NEAR((cp.sub.shear_force[i] - cs.sub.shear_force[j]).norm(), 0.0, 1e-9) << k;
  }
  // Its shear carried, and the ledger's books as the scene's: dissipation
  // handed on, nothing retired twice.
  EXPECT_GT(cp.sub.shear_force[static_cast<std::size_t>(a.first)].norm(), 1.0);
  double slip_p = cp.retired_slip_energy, slip_s = cs.retired_slip_energy;
  for (std::size_t k = 0; k < cp.sub.size(); ++k) slip_p += cp.sub.slip_energy[k];
  for (std::size_t k = 0; k < cs.sub.size(); ++k) slip_s += cs.sub.slip_energy[k];
  EXPECT_NEAR(slip_p, slip_s, 1e-12);
  EXPECT_FALSE(pairwise.moved_pairs(b, cp, 0.0, moved)) << "sampled again: its travel starts afresh";
  // Gather lists cover every subcontact twice.
  EXPECT_EQ(static_cast<std::size_t>(cp.gather_offset.back()), 2 * cp.sub.size());
}

// A moved pair no longer within the margin: the whole scene is searched
// (the guarantee for new pairs starts again from here).
TEST(PairTrigger, APairThatLeftTheMarginMakesItASceneDetection) {
  const JointLaws laws = uniform_joint_laws(kLaw, 3);
  Blocks b = two_resting_cubes();
  ContactDetector det(b, kMargin, 0.002);
  det.set_pair_trigger(true);
  ContactSet c;
  det.detect(b, c, false, laws);
  translate(b, 2, Vec3(0, 0, 0.05));  // lifted clear of the base
  std::vector<int> moved;
  ASSERT_TRUE(det.moved_pairs(b, c, 0.0, moved));
  EXPECT_EQ(moved, std::vector<int>{1});
  det.resample(b, c, moved, laws);
  EXPECT_EQ(c.detections, 2);
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs[0].b, 1);
  // A pair's poses go into checkpoints: a detector loaded from one answers
  // as the one that wrote it.
  std::string bytes;
  ByteWriter w(bytes);
  det.save(w);
  ContactDetector again(b, kMargin, 0.002);
  again.set_pair_trigger(true);
  ByteReader r(bytes);
  again.load(r, c.pairs.size());
  translate(b, 1, Vec3(0.003, 0, 0));
  std::vector<int> m1, m2;
  EXPECT_TRUE(det.moved_pairs(b, c, 0.0, m1));
  EXPECT_TRUE(again.moved_pairs(b, c, 0.0, m2));
  EXPECT_EQ(m1, m2);
  EXPECT_EQ(again.pairs_resampled(), det.pairs_resampled());
}

// A moved pair whose subcontacts change in number (a cube overhanging the
// base's edge turned, so that the edge clips its footprint into a
// pentagon): the set is rebuilt around it, the other pair copied whole, the
// moved one as a scene-wide detection samples it, the ledger's totals as
// the scene's.
TEST(PairTrigger, APairThatChangesItsSubcontactsIsSplicedIn) {
  const JointLaws laws = uniform_joint_laws(kLaw, 3);
  auto scene_of = [] {
    return build_blocks({block_spec("base", make_box(Vec3(6, 3, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                         block_spec("left", make_box(Vec3(1, 1, 1), Vec3(-1.5, 0, 0.5)), BlockMotion::free),
                         block_spec("right", make_box(Vec3(1, 1, 1), Vec3(2.55, 0, 0.5)), BlockMotion::free)});
  };
  Blocks b = scene_of(), s = scene_of();
  ContactDetector pairwise(b, kMargin, 0.002), scene(s, kMargin, 0.002);
  pairwise.set_pair_trigger(true);
  ContactSet cp, cs;
  pairwise.detect(b, cp, false, laws);
  scene.detect(s, cs, false, laws);
  ASSERT_EQ(cp.pairs.size(), 2u);
  ASSERT_EQ(cp.pairs[1].count, 4);
  for (std::size_t k = 0; k < cp.sub.size(); ++k) {
    const Vec3 f(3.0 + k, 2.0, 0.0);
    cp.sub.shear_force.set(k, f);
    cs.sub.shear_force.set(k, f);
    cp.sub.slip_energy[k] = cs.sub.slip_energy[k] = 0.5 * k;
  }
  const std::string left_before = pair_bytes(cp, 0);
  turn(b, 2, 0.2, Vec3::UnitZ());
  turn(s, 2, 0.2, Vec3::UnitZ());
  std::vector<int> moved;
  ASSERT_TRUE(pairwise.moved_pairs(b, cp, 0.0, moved));
  ASSERT_EQ(moved, std::vector<int>{1});
  pairwise.resample(b, cp, moved, laws);
  scene.detect(s, cs, false, laws);
  ASSERT_EQ(cp.pairs.size(), 2u);
  EXPECT_EQ(cp.detections, 1);
  EXPECT_EQ(pair_bytes(cp, 0), left_before);
  const ContactPair &a = cp.pairs[1], &c = cs.pairs[1];
  ASSERT_EQ(a.count, c.count);
  EXPECT_GT(a.count, 4) << "the test's premise: the edge clips the turned footprint";
  for (int k = 0; k < a.count; ++k) {
    const std::size_t i = static_cast<std::size_t>(a.first + k), j = static_cast<std::size_t>(c.first + k);
    EXPECT_NEAR((cp.sub.point[i] - cs.sub.point[j]).norm(), 0.0, 1e-12) << k;
    EXPECT_NEAR(cp.sub.area[i], cs.sub.area[j], 1e-12) << k;
    EXPECT_NEAR((cp.sub.shear_force[i] - cs.sub.shear_force[j]).norm(), 0.0, 1e-9) << k;
  }
  double slip_p = cp.retired_slip_energy, slip_s = cs.retired_slip_energy;
  for (std::size_t k = 0; k < cp.sub.size(); ++k) slip_p += cp.sub.slip_energy[k];
  for (std::size_t k = 0; k < cs.sub.size(); ++k) slip_s += cs.sub.slip_energy[k];
  EXPECT_NEAR(slip_p, slip_s, 1e-12);
  EXPECT_NEAR(cp.dropped_shear_energy, cs.dropped_shear_energy, 1e-9 * std::abs(cs.dropped_shear_energy) + 1e-12);
  EXPECT_NEAR(cp.resampled_normal_energy, cs.resampled_normal_energy,
              1e-9 * std::abs(cs.resampled_normal_energy) + 1e-12);
  EXPECT_EQ(static_cast<std::size_t>(cp.gather_offset.back()), 2 * cp.sub.size());
}

// A detection right after a detection, nothing moved between them (shear
// and twist stored first): every pair's force and moment the same to 1e-9
// of the largest, on the spire pressed into itself (random poses) and on a
// cube edge-on and corner-on 2 mm into another. A point of the previous
// patch found again where it was must keep its shear although the blocks'
// reach is zero (round-off puts it a hair off the patch: its shear was
// dropped, 0.2 % of a sliver pair's force and the whole of a corner's).
// With the blocks moved since the last detection the subcontact model
// still jumps (benchmarks/redetection_jump.cpp, docs/contact.md).
TEST(Redetection, ADetectionRightAfterADetectionChangesNoForceOrMoment) {
  for (std::uint64_t seed : {3u, 4u, 5u}) {
    Blocks blocks = test::default_spire_blocks();
    const JointLaws laws = uniform_joint_laws(test::round_law(0.5), blocks.count);
    std::mt19937_64 rng(seed);
    test::perturb(blocks, rng, 2e-4);
    const test::RedetectionJump j =
        test::redetection_jump(test::JointModelKind::subcontacts, blocks, laws, 0.003, seed + 100, 0.0);
    EXPECT_GT(j.pairs, 1000u);
    EXPECT_LT(j.worst, 1e-9) << "spire, seed " << seed;
  }
  for (const bool corner : {false, true}) {
    for (std::uint64_t seed : {7u, 8u, 9u}) {
      Blocks b = test::cube_into_cube(corner, 0.002);
      const test::RedetectionJump j = test::redetection_jump(
          test::JointModelKind::subcontacts, b, uniform_joint_laws(test::round_law(0.5), 2), 0.01, seed, 0.0);
      EXPECT_EQ(j.pairs, 1u);
      EXPECT_LT(j.worst, 1e-9) << (corner ? "corner-on" : "edge-on") << ", seed " << seed;
    }
  }
}

}  // namespace
}  // namespace polydem
