// ContactDetector: subcontact persistence across detections, and the
// half-margin rule that decides when detection has to run again.
//
// Scene: a fixed 3 × 3 × 1 base with its top at z = 0 and a free unit cube
// resting on it (bottom at z = 0). Margin 0.02 m.
#include "contact/detection.hpp"
#include "contact/joint_law.hpp"

#include "tests/support/blocks.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
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

}  // namespace
}  // namespace polydem
