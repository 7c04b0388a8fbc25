// The detection travel (contact/detection.hpp): between two detections a
// joint's subcontacts stay where the last detection put them, so a stone
// whose support slides away keeps standing on points past the support's
// edge until the next detection. How far blocks move between detections
// must not be set by the contact margin, or the margin (which should only
// decide how early contacts are found) decides when a stone tips.
#include "integrators/simulation.hpp"
#include "tests/support/blocks.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <cstdio>

namespace polydem {
namespace {

constexpr double kG = 9.81;

// The tilt of block i from its initial orientation, rad.
double tilt(const Simulation& s, int i) {
  const Quat dq = s.blocks().state.orientation[i] * s.blocks().initial_orientation[i].conjugate();
  return 2.0 * std::atan2(dq.vec().norm(), std::abs(dq.w()));
}

struct Tipping {
  double onset = -1;  // s, when the stone's tilt first exceeds 1 mrad
  double tilt = 0;    // rad, at the end
  int detections = 0;
  double travel = 0;  // m, the run's detection travel
  long long pairs_resampled = 0;
  long long pairs_clipped = 0;
};

// A 0.5 m cube stone on a 1 × 1 × 0.5 m base, flush with the base's edge at
// x = −0.5; the base is drawn away along +x at 0.5 m/s under a joint
// without friction, so the stone stays where it is and the base's edge
// passes under its centre at t* = 0.5 s: from then on it tips over the edge.
Tipping withdraw_support(double margin, double travel, DetectionTrigger trigger = DetectionTrigger::scene,
                         JointSampling sampling = JointSampling::detection) {
  SimulationSpec sim;
  sim.detection_trigger = trigger;
  sim.joint_sampling = sampling;
  sim.gravity = Vec3(0, 0, -kG);
  sim.detection_travel = travel;
  JointSpec joint;
  joint.normal_stiffness = 1e8;
  joint.shear_stiffness = 4e7;
  joint.friction_angle = 0;
  joint.damping = 0.2;
  const double v = 0.5;
  const double settle = 2600 * 0.5 * kG / joint.normal_stiffness;
  BlockSpec base = test::block_spec("base", make_box(Vec3(1, 1, 0.5), Vec3(0, 0, -0.25)), BlockMotion::kinematic);
  base.velocity = Vec3(v, 0, 0);
  BlockSpec stone =
      test::block_spec("stone", make_box(Vec3(0.5, 0.5, 0.5), Vec3(-0.25, 0, 0.25 - settle)), BlockMotion::free);
  Blocks blocks = build_blocks({base, stone});
  BlockLoads loads;
  Prescription p;
  p.block = 0;
  p.velocity = base.velocity;
  p.start = blocks.state.position[0];
  loads.prescribed.push_back(p);
  const double dt = critical_time_step(blocks, make_joint_law(joint), sim.safety_factor).chosen;
  JointLaws laws = make_joint_laws(blocks, joint, {});
  Simulation s(std::move(blocks), sim, std::move(laws), GroundMotion{}, margin, dt, true, std::move(loads));
  Tipping out;
  while (s.time() < 0.8) {
    s.step();
    if (out.onset < 0 && tilt(s, 1) > 1e-3) out.onset = s.time();
  }
  out.tilt = tilt(s, 1);
  out.detections = s.contacts().detections;
  out.travel = s.detection_travel();
  out.pairs_resampled = s.pairs_resampled();
  out.pairs_clipped = s.pairs_clipped();
  return out;
}

// The stone tips at the same moment whatever the margin: with the automatic
// detection travel (0.25 % of 0.5 m, 1.25 mm) the margins 10 and 40 mm give
// onsets within 2.5 ms (1.25 mm of the base's travel) of each other and
// tilts at 0.8 s within 0.5 % (measured: the same onset, 0.5039 s, and
// tilts 0.4168 and 0.4169 rad). With the travel at half the margin (as when
// the margin set it) the stone stands on points past the edge for up to
// 20 mm of the base's travel: measured at 40 mm, onset 12 ms later and the
// tilt 5 % smaller.
TEST(DetectionTravel, AStoneTipsWhenItsSupportIsWithdrawnWhateverTheMargin) {
  const Tipping small = withdraw_support(0.01, 0), large = withdraw_support(0.04, 0);
  const Tipping half_small = withdraw_support(0.01, 1.0), half_large = withdraw_support(0.04, 1.0);
  std::printf("onset (tilt at 0.8 s, detections): margin 10 mm %.4f s (%.4f rad, %d), 40 mm %.4f s (%.4f rad, %d); "
              "travel half the margin: 10 mm %.4f s (%.4f rad, %d), 40 mm %.4f s (%.4f rad, %d)\n",
              small.onset, small.tilt, small.detections, large.onset, large.tilt, large.detections, half_small.onset,
              half_small.tilt, half_small.detections, half_large.onset, half_large.tilt, half_large.detections);
  ASSERT_GT(small.onset, 0.5) << "the stone must not tip before its centre is past the edge";
  ASSERT_GT(large.onset, 0.5);
  EXPECT_NEAR(small.onset, large.onset, 0.0025);
  EXPECT_NEAR(small.tilt, large.tilt, 0.005 * small.tilt);
  // The premise: had the margin set the detections, it would have moved the
  // answer.
  EXPECT_GT(half_large.onset - small.onset, 0.005);
  EXPECT_LT(half_large.tilt, 0.97 * small.tilt);
}

// Pair by pair (simulation.detection_trigger = "pair") the automatic travel
// is a sixteenth of the scene-wide one (78 µm here) and the stone's joint is
// re-sampled on its own motion: it tips as with the scene-wide trigger,
// within the scene-wide travel's resolution (2.5 ms of the base's travel),
// at either margin.
TEST(DetectionTravel, PairByPairTheStoneTipsAsWithTheSceneWideTrigger) {
  const Tipping scene = withdraw_support(0.01, 0);
  const Tipping small = withdraw_support(0.01, 0, DetectionTrigger::pair),
                large = withdraw_support(0.04, 0, DetectionTrigger::pair);
  std::printf("pair by pair, onset (tilt at 0.8 s, scene detections, pairs re-sampled): margin 10 mm %.4f s "
              "(%.4f rad, %d, %lld), 40 mm %.4f s (%.4f rad, %d, %lld); scene-wide %.4f s\n",
              small.onset, small.tilt, small.detections, small.pairs_resampled, large.onset, large.tilt,
              large.detections, large.pairs_resampled, scene.onset);
  EXPECT_DOUBLE_EQ(small.travel, scene.travel / 16);
  EXPECT_DOUBLE_EQ(scene.travel, 0.0025 * 0.5);
  ASSERT_GT(small.onset, 0.5);
  EXPECT_NEAR(small.onset, scene.onset, 0.0025);
  EXPECT_NEAR(large.onset, scene.onset, 0.0025);
  EXPECT_NEAR(small.tilt, scene.tilt, 0.01 * scene.tilt);
  EXPECT_NEAR(large.tilt, scene.tilt, 0.01 * scene.tilt);
  EXPECT_GT(small.pairs_resampled, 16 * scene.detections / 2) << "the joint re-sampled at its own, finer travel";
}

// Under joint_sampling = "clip" the joint is clipped again whenever the
// stone and the base have moved relative to each other by the travel, so
// its points lag the base's edge by at most the travel: the stone tips as
// when it is clipped at every step (the travel 1e-12 m) at the automatic
// travel (78 µm) and at sixteen times it (1.25 mm, the scene-wide
// automatic travel), within that travel's 2.5 ms of the base's motion and
// 1 % of the tilt at 0.8 s; the clips follow the base's 0.4 m of travel,
// about one per travel, and every step's clip one per step (measured:
// onsets 0.5026, 0.5027 and 0.5038 s, tilts 0.4184, 0.4184 and 0.4177 rad,
// 80,006, 8,598 and 506 clips).
TEST(DetectionTravel, ClippedAtTheTravelTheStoneTipsAsWhenClippedEveryStep) {
  const Tipping every = withdraw_support(0.01, 1e-12, DetectionTrigger::pair, JointSampling::clip);
  const Tipping automatic = withdraw_support(0.01, 0, DetectionTrigger::pair, JointSampling::clip);
  const Tipping coarse = withdraw_support(0.01, 0.0025 * 0.5, DetectionTrigger::pair, JointSampling::clip);
  std::printf("clipped: onset (tilt at 0.8 s, pairs clipped, re-sampled): every step %.4f s (%.4f rad, %lld, %lld), "
              "at the travel %.4f s (%.4f rad, %lld, %lld), at 16 x the travel %.4f s (%.4f rad, %lld, %lld)\n",
              every.onset, every.tilt, every.pairs_clipped, every.pairs_resampled, automatic.onset, automatic.tilt,
              automatic.pairs_clipped, automatic.pairs_resampled, coarse.onset, coarse.tilt, coarse.pairs_clipped,
              coarse.pairs_resampled);
  ASSERT_GT(every.onset, 0.5) << "the stone must not tip before its centre is past the edge";
  EXPECT_NEAR(automatic.onset, every.onset, 0.0025);
  EXPECT_NEAR(coarse.onset, every.onset, 0.0025);
  EXPECT_NEAR(automatic.tilt, every.tilt, 0.01 * every.tilt);
  EXPECT_NEAR(coarse.tilt, every.tilt, 0.01 * every.tilt);
  // The base's 0.4 m at about one clip per travel (the stone's own motion
  // adds some once it tips), and every step's clip at each step.
  const double base_travel = 0.5 * 0.8;
  EXPECT_GT(automatic.pairs_clipped, 0.5 * base_travel / automatic.travel);
  EXPECT_LT(automatic.pairs_clipped, 4.0 * base_travel / automatic.travel);
  EXPECT_GT(coarse.pairs_clipped, 0.5 * base_travel / coarse.travel);
  EXPECT_LT(coarse.pairs_clipped, 4.0 * base_travel / coarse.travel);
  EXPECT_GT(every.pairs_clipped, 5 * automatic.pairs_clipped);
}

// An edge-to-edge pair has no faces to clip: under "clip" it is re-sampled
// on its travel as under the default sampling. Two 1 m cubes turned 45° so
// that the lower one's ridge runs along x and the upper one's along y,
// just touching, without gravity; the upper one, free, moves along x at
// 0.1 m/s for 0.5 s, its ridge sliding along the lower one's: the pair's one
// subcontact must follow the crossing (within the travel and the margin),
// the pair re-sampled about once per travel of the 50 mm.
TEST(DetectionTravel, ClippedAnEdgeToEdgePairIsReSampledOnItsTravel) {
  SimulationSpec sim;
  sim.detection_trigger = DetectionTrigger::pair;
  sim.joint_sampling = JointSampling::clip;
  sim.gravity = Vec3::Zero();
  JointSpec joint;
  joint.normal_stiffness = 1e8;
  joint.shear_stiffness = 4e7;
  joint.friction_angle = 0;
  const double h = std::sqrt(0.5), v = 0.1, margin = 0.02;
  BlockSpec lower = test::block_spec("lower", make_box(Vec3(1, 1, 1)), BlockMotion::fixed);
  BlockSpec upper = test::block_spec("upper", make_box(Vec3(1, 1, 1)), BlockMotion::free);
  upper.velocity = Vec3(v, 0, 0);
  Blocks blocks = build_blocks({lower, upper});
  auto turn = [&](int i, const Vec3& axis, const Vec3& at) {
    blocks.state.orientation[i] = Quat(Eigen::AngleAxisd(std::numbers::pi / 4, axis));
    blocks.state.rotation[i] = blocks.state.orientation[i].toRotationMatrix();
    blocks.state.position[i] = at;
  };
  turn(0, Vec3::UnitX(), Vec3(0, 0, -h));
  turn(1, Vec3::UnitY(), Vec3(0, 0, h));
  const double dt = 1e-4;
  JointLaws laws = make_joint_laws(blocks, joint, {});
  Simulation s(std::move(blocks), sim, std::move(laws), GroundMotion{}, margin, dt, false);
  ASSERT_EQ(s.contacts().pairs.size(), 1u);
  ASSERT_EQ(s.contacts().pairs[0].ref_face, -1) << "the test's premise: an edge-to-edge pair";
  while (s.time() < 0.5) s.step();
  ASSERT_EQ(s.contacts().pairs.size(), 1u);
  const double x = s.blocks().state.position[1].x();
  const double travel = s.detection_travel();
  const Vec3 at = s.contacts().sub.point[0];
  std::printf("edge to edge under clip: the upper cube at x = %.4f m, the subcontact at x = %.4f m; %lld pairs "
              "re-sampled (travel %.3g m)\n",
              x, at.x(), s.pairs_resampled(), travel);
  EXPECT_NEAR(x, 0.05, 1e-3);
  EXPECT_NEAR(at.x(), x, travel + margin);
  EXPECT_GT(s.pairs_resampled(), static_cast<long long>(0.5 * 0.05 / travel));
}

}  // namespace
}  // namespace polydem
