// The overlap joint model (contact/overlap_joint.hpp) against closed forms,
// and the continuity of its forces across a detection.
//
// Geometry: a cube of side 1 m resting on a fixed base whose top face is the
// plane z = 0; the cube pressed into it by δ = 2⁻¹² m, tilted, slid or
// twisted. The Winkler layer's integrals are exact for these linear fields,
// so the forces agree with the closed forms to round-off (1e-12 relative).
#include "contact/detection.hpp"
#include "contact/overlap_joint.hpp"
#include "contact/pair_gather.hpp"

#include "tests/support/blocks.hpp"
#include "tests/support/redetection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace polydem {
namespace {

constexpr double kDelta = 1.0 / 4096.0;
constexpr double kMargin = 0.01;

JointLaw law_for_test() { return test::round_law(0.5); }

using test::block_spec;

using test::perturb;
using test::turn;

// A base and a cube on it, detected under the overlap model.
struct CubeOnBase {
  Blocks blocks;
  JointLaws laws;
  ContactDetector detector;
  ContactSet contacts;
  OverlapScratch scratch;
  explicit CubeOnBase(const JointLaw& law = law_for_test())
      : blocks(build_blocks({block_spec("base", make_box(Vec3(3, 3, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                             block_spec("cube", make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5)), BlockMotion::free)})),
        laws(uniform_joint_laws(law, 2)),
        detector(blocks, kMargin) {
    detector.set_pair_joints(true);
    detect();
  }
  void detect() { detector.detect(blocks, contacts, false, laws); }
  // One evaluation of the law (dt = 0: no increments, no dashpot work).
  const lanes::PairRest& wrench(double dt = 0.0) {
    overlap_joint_forces(laws, blocks.props.local_shape, blocks.state, contacts.pairs, contacts.sub, contacts.joints,
                         dt, 0, contacts.pairs.size(), scratch);
    return contacts.joints.wrench[0];
  }
  Vec3 force() { return Vec3(wrench().force[0], wrench().force[1], wrench().force[2]); }
};

Vec3 v3(const double (&a)[3]) { return Vec3(a[0], a[1], a[2]); }

TEST(OverlapJoint, PressedFlatCarriesKnTimesAreaTimesDepthAtTheCentre) {
  CubeOnBase s;
  s.blocks.state.position[1].z() -= kDelta;
  const lanes::PairRest& w = s.wrench();
  const double kn = law_for_test().kn;
  EXPECT_NEAR(w.force[2], kn * 1.0 * kDelta, 1e-12 * kn * kDelta);
  EXPECT_NEAR(std::hypot(w.force[0], w.force[1]), 0.0, 1e-12 * kn * kDelta);
  // Through the centroid: no moment on the cube about its centroid.
  EXPECT_NEAR(v3(w.moment).norm(), 0.0, 1e-12 * kn * kDelta);
  EXPECT_NEAR(s.contacts.joints.strain_energy[0], 0.5 * kn * kDelta * kDelta, 1e-12 * kn * kDelta * kDelta);
  EXPECT_NEAR(s.contacts.joints.area[0], 1.0, 1e-12);
  EXPECT_NEAR(s.contacts.joints.overlap[0], kDelta, 1e-15);
}

// Tilted by θ about y with the whole base pressed. The base's points at
// body abscissa x lie at depth δ + x·sin θ − ½(1 − cos θ), at world abscissa
// ξ = x·cos θ − ½ sin θ: over the region, of width cos θ about ξ_c = −½ sin θ,
// the overlap is linear, t = t_c + tan θ·(ξ − ξ_c) with t_c = δ − ½(1 − cos θ).
// So N = kn·t_c·cos θ and, about the base's centre, M_y = −kn·tan θ·cos³θ/12.
// The cube's side face, tilted by θ, adds a sliver 4e-8 m wide: 1e-7 of N.
TEST(OverlapJoint, TiltedBaseGivesTheLinearPressuresMoment) {
  CubeOnBase s;
  const double theta = 1.0 / 8192.0;  // the whole face stays pressed
  s.blocks.state.position[1].z() -= kDelta;
  turn(s.blocks, 1, theta, Vec3::UnitY());
  const lanes::PairRest& w = s.wrench();
  const double kn = law_for_test().kn;
  const double tc = kDelta - 0.5 * (1 - std::cos(theta));
  EXPECT_NEAR(w.force[2], kn * tc * std::cos(theta), 1e-6 * kn * kDelta);
  const Vec3 centre = s.blocks.state.position[1] + s.blocks.state.rotation[1] * Vec3(0, 0, -0.5);
  const Vec3 about_centre = v3(w.moment) - (centre - s.blocks.state.position[1]).cross(v3(w.force));
  const double expected = -kn * std::tan(theta) * std::pow(std::cos(theta), 3) / 12.0;
  EXPECT_NEAR(about_centre.y(), expected, 1e-6 * std::abs(expected));
}

// Sliding at v along x for k steps of dt: F = −ks·A·v·dt·k while below
// μN; then held at μN and the friction's work is μN times the slip.
TEST(OverlapJoint, ShearSticksThenSlipsAtTheCoulombCap) {
  CubeOnBase s;
  s.blocks.state.position[1].z() -= kDelta;
  const JointLaw law = law_for_test();
  const double dt = 1e-6, v = 1e-3;
  s.blocks.state.velocity[1] = Vec3(v, 0, 0);
  const double cap = law.tan_phi * law.kn * kDelta;  // 1.2e6 N
  int k = 0;
  for (; k < 5; ++k) s.wrench(dt);
  // The dashpot is off (β = 0): the wrench is the spring's.
  EXPECT_NEAR(s.contacts.joints.shear[0].x(), -law.ks * 1.0 * v * dt * k, 1e-9 * law.ks * v * dt * k);
  EXPECT_EQ(s.contacts.joints.slip_energy[0], 0.0);
  // Steps enough to reach the cap (ks·A·v·dt = 4 N a step: 3e5 steps) are
  // many; one long step instead, as the law takes any dt.
  const double long_dt = 2.0 * cap / (law.ks * v);  // twice the cap's displacement
  s.wrench(long_dt);
  EXPECT_NEAR(s.contacts.joints.shear[0].norm(), cap, 1e-9 * cap);
  EXPECT_EQ(s.contacts.joints.sliding[0], 1);
  // Trial |F_t| ≈ 2·cap + the first 5 steps; work = cap·(|F_t| − cap)/(ks·A).
  const double trial = law.ks * v * (dt * 5 + long_dt);
  EXPECT_NEAR(s.contacts.joints.slip_energy[0], cap * (trial - cap) / law.ks, 1e-9 * cap * cap / law.ks);
}

// A sheared joint whose region shrinks: the cube moved (at rest, no
// increment) half off the base's edge. The layer that left takes its
// stress with it: F halves with the area, and the strain energy it held,
// F²/(2·ks·A) − (F/2)²/(2·ks·A/2) = F²/(4·ks), is booked as slip, so the
// joint's strain plus its slip is what it held.
TEST(OverlapJoint, TheLayerThatLeavesTheJointSlipsOff) {
  CubeOnBase s;
  s.blocks.state.position[1].z() -= kDelta;
  const JointLaw law = law_for_test();
  s.wrench();  // the region: the whole face, A = 1
  const Vec3 f(3e4, -4e4, 0);  // 50 kN, below the cap
  s.contacts.joints.shear[0] = f;
  const double held = f.squaredNorm() / (2 * law.ks * 1.0);
  s.blocks.state.position[1].x() += 1.5;  // the cube over x in [1, 2], the base to 1.5
  s.wrench();
  EXPECT_NEAR(s.contacts.joints.area[0], 0.5, 1e-12);
  EXPECT_NEAR((s.contacts.joints.shear[0] - 0.5 * f).norm(), 0.0, 1e-9 * f.norm());
  const double kept = s.contacts.joints.shear[0].squaredNorm() / (2 * law.ks * 0.5);
  EXPECT_NEAR(s.contacts.joints.slip_energy[0], held - kept, 1e-12 * held);
  EXPECT_NEAR(s.contacts.joints.slip_energy[0], f.squaredNorm() / (4 * law.ks), 1e-12 * held);
}

// A sheared and twisted joint that parts (the cube lifted clear, at rest):
// the cap falls to zero with the overlap and the shear and twist slip off,
// their strain energy booked as slip.
TEST(OverlapJoint, AJointThatPartsLetsItsShearAndTwistSlipOff) {
  CubeOnBase s;
  s.blocks.state.position[1].z() -= kDelta;
  const JointLaw law = law_for_test();
  s.wrench();  // A = 1, J = 1/6
  const Vec3 f(3e4, -4e4, 0);
  const double t = 2e3;
  s.contacts.joints.shear[0] = f;
  s.contacts.joints.twist[0] = t;
  const double held = f.squaredNorm() / (2 * law.ks * 1.0) + t * t / (2 * law.ks * (1.0 / 6.0));
  s.blocks.state.position[1].z() += 2 * kDelta;  // clear of the base by δ
  s.wrench();
  EXPECT_EQ(s.contacts.joints.shear[0], Vec3::Zero());
  EXPECT_EQ(s.contacts.joints.twist[0], 0.0);
  EXPECT_NEAR(s.contacts.joints.slip_energy[0], held, 1e-12 * held);
}

// Spun at ω about z: T = −ks·J·ω·dt per step with J = 1/6 for the unit
// square about its centre; held at T_max = 0.94·√(J/A)·μN when spun far.
TEST(OverlapJoint, TwistHasThePolarMomentsStiffnessAndTheEllipsesCap) {
  CubeOnBase s;
  s.blocks.state.position[1].z() -= kDelta;
  const JointLaw law = law_for_test();
  const double dt = 1e-6, w = 1e-3;
  s.blocks.state.angular_velocity[1] = Vec3(0, 0, w);
  s.wrench(dt);
  EXPECT_NEAR(s.contacts.joints.twist[0], -law.ks * w * dt / 6.0, 1e-9 * law.ks * w * dt);
  EXPECT_NEAR(s.contacts.joints.shear[0].norm(), 0.0, 1e-9 * law.ks * w * dt);
  s.wrench(1.0);  // far beyond the cap
  const double cap = law.tan_phi * law.kn * kDelta;
  EXPECT_NEAR(std::abs(s.contacts.joints.twist[0]), 0.94 * std::sqrt(1.0 / 6.0) * cap, 1e-9 * cap);
  EXPECT_GT(s.contacts.joints.slip_energy[0], 0.0);
}

TEST(OverlapJoint, TheDashpotNeverPullsTheBlocksTogether) {
  JointLaw law = law_for_test();
  law.beta = 1e-3;
  CubeOnBase s(law);
  s.blocks.state.position[1].z() -= kDelta;
  s.blocks.state.velocity[1] = Vec3(0, 0, 10.0);  // leaving fast
  const lanes::PairRest& w = s.wrench(1e-6);
  EXPECT_NEAR(w.force[2], 0.0, 1e-12 * law.kn * kDelta);  // cut at zero, not below
}

// A stone that left its bed and now lies beside the base, 2 mm from its
// side face, within the margin: the pair is found again, open on the bed's
// plane, and takes the side face's plane, so that pressed into that face it
// is pushed back across it, kn·A·δ, not along the bed's normal.
TEST(OverlapJoint, AJointFoundOpenTakesThePlaneTheDetectionFinds) {
  CubeOnBase s;
  ASSERT_EQ(s.contacts.pairs.size(), 1u);
  const auto normal = [&s] {
    const int r = s.contacts.joints.ref_block[0];
    return Vec3(s.blocks.state.rotation[r] * s.contacts.joints.normal_local[0]);
  };
  EXPECT_NEAR(std::abs(normal().z()), 1.0, 1e-15);
  s.blocks.state.position[1] = Vec3(1.5 + 0.5 + 0.002, 0, -0.5);
  s.detect();
  ASSERT_EQ(s.contacts.pairs.size(), 1u);
  EXPECT_NEAR(std::abs(normal().x()), 1.0, 1e-15);
  s.blocks.state.position[1].x() -= 0.002 + kDelta;
  const double kn = law_for_test().kn;
  const Vec3 f = s.force();
  EXPECT_NEAR(f.x(), kn * 1.0 * kDelta, 1e-12 * kn * kDelta);
  EXPECT_NEAR(std::hypot(f.y(), f.z()), 0.0, 1e-12 * kn * kDelta);
}

// Forces continuous at a re-detection (tests/support/redetection.hpp): shear
// and twist stored, the blocks moved since the last detection (less than
// half the margin), found again at the same pose: the wrenches must not
// change (1e-9 relative to the largest).
double redetection_jump(Blocks& blocks, const JointLaws& laws, double margin, std::uint64_t seed, double move) {
  return test::redetection_jump(test::JointModelKind::overlap, blocks, laws, margin, seed, move).worst;
}

TEST(OverlapJoint, ForcesDoNotJumpAtARedetectionOnTheSpire) {
  Blocks blocks = test::default_spire_blocks();
  const JointLaws laws = uniform_joint_laws(law_for_test(), blocks.count);
  // Pressed into each other first, so that the joints carry load.
  std::mt19937_64 rng(11);
  perturb(blocks, rng, 2e-4);
  const double worst = redetection_jump(blocks, laws, 0.003, 5, 0.1);
  std::printf("spire: worst jump at a re-detection %.3g\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(OverlapJoint, ForcesDoNotJumpAtARedetectionEdgeOnAndCornerOn) {
  for (const bool corner : {false, true}) {
    Blocks b = test::cube_into_cube(corner, 0.002);
    const double worst = redetection_jump(b, uniform_joint_laws(law_for_test(), 2), 0.01, corner ? 7 : 9, 0.02);
    std::printf("%s-on: worst jump at a re-detection %.3g\n", corner ? "corner" : "edge", worst);
    EXPECT_LT(worst, 1e-9);
  }
}

// The face pairs found at a detection hold every cell until the next one:
// the integral over them equals the full one, to the bit, on the spire's
// pairs moved by up to a quarter of the margin.
TEST(OverlapJoint, TheCellsFoundAtADetectionHoldEveryCellUntilTheNext) {
  Blocks blocks = test::default_spire_blocks();
  const JointLaws laws = uniform_joint_laws(law_for_test(), blocks.count);
  const double margin = 0.003;
  ContactDetector det(blocks, margin);
  det.set_pair_joints(true);
  ContactSet c;
  det.detect(blocks, c, false, laws);
  std::mt19937_64 rng(2);
  perturb(blocks, rng, 0.25 * margin / std::sqrt(3.0));
  OverlapScratch s;
  int nonzero = 0;
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    const ContactPair& cp = c.pairs[q];
    const int r = c.joints.ref_block[q], o = r == cp.a ? cp.b : cp.a;
    const PosedBlock A{&blocks.props.local_shape[r], blocks.state.rotation[r], blocks.state.position[r]};
    const PosedBlock B{&blocks.props.local_shape[o], blocks.state.rotation[o], blocks.state.position[o]};
    const Vec3 n = blocks.state.rotation[r] * c.joints.normal_local[q];
    const JointFrame f = make_joint_frame(n, 0.5 * (A.x + B.x));
    const OverlapMoments full = overlap_integral(A, B, f, s);
    const FacePair* cells = c.joints.cells.data();
    const OverlapMoments held =
        overlap_integral(A, B, f, cells + c.joints.cell_first[q], cells + c.joints.cell_first[q + 1], s);
    ASSERT_EQ(full.volume, held.volume) << "pair " << q;
    ASSERT_EQ(full.area, held.area) << "pair " << q;
    ASSERT_EQ(full.volume_moment, held.volume_moment) << "pair " << q;
    nonzero += full.volume > 0;
  }
  EXPECT_GT(nonzero, 100);
}

}  // namespace
}  // namespace polydem
