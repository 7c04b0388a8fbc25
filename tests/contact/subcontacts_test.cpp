// carry_history: a new subcontact takes the elastic shear displacement of
// the joint where it lies (interpolated over the previous patch), and the
// bond and dissipation of the previous subcontact nearest to it, whatever
// the clip's topology; shear energy that cannot be handed on is booked as
// dropped, dissipation that no one takes is retired.
//
// The scenes are built by hand: two blocks at the origin with the identity
// orientation (so body frames are the world frame), pair (0, 1), block 0's
// face z = 0 the reference plane, block 1 incident. Subcontacts are given
// by their points on the plane. ks = 1e9 Pa/m; block 1 has moved 0.01 m
// since the previous detection, so history reaches 0.01 m beyond the
// previous patch.
#include "contact/subcontacts.hpp"

#include "contact/joint_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace polydem {
namespace {

constexpr double kKs = 1e9;
// The blocks' joints under one law of shear stiffness kKs.
JointLaws ks_laws(const Blocks& b) { return uniform_joint_laws(JointLaw{1e10, kKs, 0.5, 0, 0, 0}, b.count); }
constexpr double kReach = 0.01;

// Scratch for a detection after which block 1 has moved kReach along x
// since the previous one (block 0 not at all): the pair's reach.
CarryScratch moved_by(double d) {
  CarryScratch s;
  s.moved = {Vec3::Zero(), Vec3(d, 0, 0)};
  s.turned = {0.0, 0.0};
  return s;
}

struct Point {
  double x, y;
  double area;
  std::uint64_t key;
};

Blocks two_blocks_at_rest() {
  Blocks b;
  b.count = 2;
  b.state.position = {Vec3::Zero(), Vec3::Zero()};
  b.state.orientation = {Quat::Identity(), Quat::Identity()};
  b.state.rotation = {Mat3::Identity(), Mat3::Identity()};
  return b;
}

// One pair (a, b) = (0, 1), reference block `ref`, with the given points.
ContactSet one_pair(const std::vector<Point>& points, int ref = 0, int a = 0, int b = 1) {
  ContactSet cs;
  ContactPair p;
  p.a = a;
  p.b = b;
  p.ref_block = ref;
  p.count = static_cast<int>(points.size());
  cs.pairs.push_back(p);
  cs.sub.resize(points.size());
  for (std::size_t s = 0; s < points.size(); ++s) {
    const Vec3 x(points[s].x, points[s].y, 0);
    cs.sub.pair[s] = 0;
    cs.sub.ref_block[s] = ref;
    cs.sub.inc_block[s] = ref == a ? b : a;
    cs.sub.key[s] = points[s].key;
    cs.sub.ref_normal_local[s] = ref == a ? Vec3::UnitZ() : Vec3(-Vec3::UnitZ());
    cs.sub.ref_offset_local[s] = 0;
    cs.sub.inc_point_local.set(s, x);
    cs.sub.point[s] = x;
    cs.sub.area[s] = points[s].area;
    cs.sub.shear_force.set(s, Vec3::Zero());
    cs.sub.bonded[s] = 0;
    cs.sub.slip_energy[s] = 0;
    cs.sub.damping_energy[s] = 0;
    cs.sub.damping_force.set(s, Vec3::Zero());
    cs.sub.crush[s] = 0;
  }
  return cs;
}

double energy(const Vec3& f, double area) { return 0.5 * f.squaredNorm() / (kKs * area); }

// A unit square's corners, each with a quarter of the area.
std::vector<Point> square(std::uint64_t first_key) {
  return {{-0.5, -0.5, 0.25, first_key},
          {0.5, -0.5, 0.25, first_key + 1},
          {0.5, 0.5, 0.25, first_key + 2},
          {-0.5, 0.5, 0.25, first_key + 3}};
}

TEST(CarryHistory, FollowsThePositionNotTheKey) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair(square(11));
  for (int s = 0; s < 4; ++s) {
    previous.sub.shear_force.set(s, Vec3(100.0 * (s + 1), -30.0 * s, 0));
    previous.sub.slip_energy[s] = 0.5 + s;
    previous.sub.damping_energy[s] = 0.25 * s;
    previous.sub.bonded[s] = s % 2;
  }
  previous.retired_slip_energy = 10.0;
  previous.retired_damping_energy = 20.0;
  previous.dropped_shear_energy = 5.0;
  // The same corners, listed from another vertex and under other keys (the
  // clip's features changed), and a point at the centre of the patch that
  // takes a tenth of the area from them.
  std::vector<Point> now = {{0.5, 0.5, 0.225, 91},  {-0.5, 0.5, 0.225, 92}, {-0.5, -0.5, 0.225, 93},
                            {0.5, -0.5, 0.225, 94}, {0.0, 0.0, 0.1, 95}};
  ContactSet current = one_pair(now);
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  const int source[4] = {2, 3, 0, 1};
  Vec3 mean_stress = Vec3::Zero();
  for (int o = 0; o < 4; ++o) mean_stress += previous.sub.shear_force[o] / 0.25 / 4;
  double e_old = 0, e_new = 0;
  for (int s = 0; s < 4; ++s) {
    const int o = source[s];
    // The shear displacement carries: the force goes with the area.
    EXPECT_NEAR((current.sub.shear_force[s] - 0.9 * previous.sub.shear_force[o]).norm(), 0.0, 1e-12 * 400) << s;
    EXPECT_EQ(current.sub.bonded[s], previous.sub.bonded[o]) << s;
    EXPECT_EQ(current.sub.slip_energy[s], previous.sub.slip_energy[o]) << s;
    EXPECT_EQ(current.sub.damping_energy[s], previous.sub.damping_energy[o]) << s;
    e_old += energy(previous.sub.shear_force[s], 0.25);
    e_new += energy(current.sub.shear_force[s], 0.225);
  }
  // The centre takes the field's value there (the mean), and no dissipation
  // (the nearest corner's went to that corner).
  EXPECT_NEAR((current.sub.shear_force[4] - 0.1 * mean_stress).norm(), 0.0, 1e-12 * 400);
  EXPECT_EQ(current.sub.slip_energy[4], 0.0);
  e_new += energy(current.sub.shear_force[4], 0.1);
  // Nothing retired; the resampled field holds a little less energy, the
  // difference is dropped.
  EXPECT_EQ(current.retired_slip_energy, 10.0);
  EXPECT_EQ(current.retired_damping_energy, 20.0);
  ASSERT_LT(e_new, e_old);
  EXPECT_NEAR(current.dropped_shear_energy, 5.0 + (e_old - e_new), 1e-12);
}

// A twist: the elastic shear displacement grows with the distance from the
// centre, at right angles to it, a linear field. A cube twisted on an equal
// cube is re-clipped into eight crossings, four near the corners and four
// near the middles of the edges, half a metre from any corner; each takes
// the twist's own field at its point, exactly.
TEST(CarryHistory, ATwistIsCarriedOntoANewClipExactly) {
  const Blocks b = two_blocks_at_rest();
  const double tau = 1e5;  // Pa per m from the centre
  auto twist_force = [&](double x, double y, double area) { return Vec3(-tau * y * area, tau * x * area, 0); };
  ContactSet previous = one_pair(square(1));
  for (int s = 0; s < 4; ++s)
    previous.sub.shear_force.set(s, twist_force(previous.sub.point[s].x(), previous.sub.point[s].y(), 0.25));
  const double c = 0.006;  // where the turned edges cross
  std::vector<Point> octagon = {{-0.5 + c, -0.5, 0.124, 1}, {0.5, -0.5 + c, 0.126, 2}, {0.5, 0.5 - c, 0.124, 3},
                                {-0.5 + c, 0.5, 0.126, 4},  {-0.5, 0.0, 0.125, 5},     {0.0, -0.5, 0.125, 6},
                                {0.5, 0.0, 0.125, 7},       {0.0, 0.5, 0.125, 8}};
  ContactSet current = one_pair(octagon);
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  double e_old = 0, e_new = 0;
  for (int s = 0; s < 4; ++s) e_old += energy(previous.sub.shear_force[s], 0.25);
  for (std::size_t s = 0; s < octagon.size(); ++s) {
    const Vec3 expected = twist_force(octagon[s].x, octagon[s].y, octagon[s].area);
    EXPECT_NEAR((current.sub.shear_force[s] - expected).norm(), 0.0, 1e-9 * tau) << s;
    e_new += energy(current.sub.shear_force[s], octagon[s].area);
  }
  // The eight points sample the same field nearer its centre: less energy,
  // the rest is booked as dropped.
  EXPECT_LT(e_new, e_old);
  EXPECT_NEAR(current.dropped_shear_energy, e_old - e_new, 1e-12 * e_old);
}

// A point off the previous patch by more than the pair's reach (how far
// its blocks moved relative to each other since the previous detection) is
// contact area that is new, however large the patch.
TEST(CarryHistory, APointOffThePreviousPatchStartsWithoutHistory) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair(square(1));
  for (int s = 0; s < 4; ++s) {
    previous.sub.shear_force.set(s, Vec3(0, 250, 0));
    previous.sub.bonded[s] = 1;
  }
  // 9 mm off carries, 11 mm off does not (a reach set by the patch's size,
  // a tenth of its 0.71 m radius, would carry both); a point off by just the
  // reach (an edge that moved with the block, 0.5 + 0.01 m: 1e-17 m more in
  // round-off) carries.
  ContactSet current =
      one_pair({{0.509, 0.0, 0.25, 1}, {-0.511, 0.0, 0.25, 2}, {0.5 + kReach, 0.3, 0.25, 3}});
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  EXPECT_NEAR((current.sub.shear_force[0] - Vec3(0, 250, 0)).norm(), 0.0, 1e-9);
  EXPECT_EQ(current.sub.bonded[0], 1);
  EXPECT_EQ(current.sub.shear_force[1], Vec3::Zero());
  EXPECT_EQ(current.sub.bonded[1], 0);
  EXPECT_NEAR((current.sub.shear_force[2] - Vec3(0, 250, 0)).norm(), 0.0, 1e-9);
  // Blocks that have not moved since: the reach is nil, 9 mm off is new.
  ContactSet again = one_pair({{0.509, 0.0, 0.25, 1}});
  CarryScratch still = moved_by(0.0);
  carry_history(b, previous, again, ks_laws(b), still);
  EXPECT_EQ(again.sub.shear_force[0], Vec3::Zero());
}

// A corner clipped into two crossings (a block twisted on an equal block):
// both inherit the corner's shear displacement, so each carries the force in
// proportion to its area and the strain energy is unchanged; the dissipation
// goes to the first one only.
TEST(CarryHistory, ACornerSplitIntoTwoCrossingsSharesItsDisplacement) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair({{0.5, 0.5, 0.25, 1}});
  const Vec3 f(300, -400, 0);
  previous.sub.shear_force.set(0, f);
  previous.sub.slip_energy[0] = 2.0;
  previous.sub.bonded[0] = 1;
  ContactSet current = one_pair({{0.495, 0.5, 0.125, 7}, {0.5, 0.495, 0.125, 8}});
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  for (int s = 0; s < 2; ++s) {
    EXPECT_NEAR((current.sub.shear_force[s] - 0.5 * f).norm(), 0.0, 1e-12 * f.norm()) << s;
    EXPECT_EQ(current.sub.bonded[s], 1);
  }
  EXPECT_EQ(current.sub.slip_energy[0], 2.0);
  EXPECT_EQ(current.sub.slip_energy[1], 0.0);
  EXPECT_EQ(current.retired_slip_energy, 0.0);
  EXPECT_NEAR(current.dropped_shear_energy, 0.0, 1e-12 * energy(f, 0.25));
}

// Inheritors with more area than their source share its strain energy: it
// is never copied (which would make energy from nowhere).
TEST(CarryHistory, InheritorsWithMoreAreaShareTheEnergyInsteadOfCopyingIt) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair({{0.5, 0.5, 0.25, 1}});
  const Vec3 f(0, 1000, 0);
  previous.sub.shear_force.set(0, f);
  ContactSet current = one_pair({{0.495, 0.5, 0.25, 7}, {0.5, 0.495, 0.25, 8}});
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  const double e_new = energy(current.sub.shear_force[0], 0.25) + energy(current.sub.shear_force[1], 0.25);
  EXPECT_NEAR(e_new, energy(f, 0.25), 1e-12 * energy(f, 0.25));
  EXPECT_NEAR(current.sub.shear_force[0].y(), 1000 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(current.dropped_shear_energy, 0.0, 1e-12 * energy(f, 0.25));
}

// A patch that shrinks (a block sliding over an edge) and a subcontact that
// is gone: the shear displacement carries, the strain energy of the area
// lost is booked as dropped, and the gone one's dissipation is retired.
TEST(CarryHistory, ShearOfAreaThatIsGoneIsBookedAsDropped) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair(square(11));
  const Vec3 f(0, 2000, 0);
  for (int s = 0; s < 4; ++s) previous.sub.shear_force.set(s, f);
  previous.sub.slip_energy[1] = 3.0;
  previous.sub.damping_energy[1] = 1.5;
  // Corners 0, 2, 3 remain with a fifth of their area lost; corner 1 is gone.
  ContactSet current = one_pair({{-0.5, -0.5, 0.2, 1}, {0.5, 0.5, 0.2, 2}, {-0.5, 0.5, 0.2, 3}});
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  for (int s = 0; s < 3; ++s) EXPECT_NEAR((current.sub.shear_force[s] - 0.8 * f).norm(), 0.0, 1e-9) << s;
  const double before = 4 * energy(f, 0.25);
  const double after = 3 * energy(0.8 * f, 0.2);
  EXPECT_NEAR(current.dropped_shear_energy, before - after, 1e-12 * before);
  EXPECT_EQ(current.retired_slip_energy, 3.0);
  EXPECT_EQ(current.retired_damping_energy, 1.5);
}

// The reference face changed sides: the same place on the joint, but the
// stored force was the one on block 1 and is now the one on block 0.
TEST(CarryHistory, AReferenceFaceThatChangesSidesTurnsTheForceOntoTheOtherBlock) {
  const Blocks b = two_blocks_at_rest();
  ContactSet previous = one_pair({{0.5, 0.5, 0.25, 1}}, 0);
  previous.sub.shear_force.set(0, Vec3(10, 20, 0));
  ContactSet current = one_pair({{0.5, 0.5, 0.25, 1}}, 1);
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  EXPECT_EQ(current.sub.shear_force[0], Vec3(-10, -20, 0));
}

TEST(CarryHistory, AnotherPairDoesNotInheritAndAPairThatIsGoneDropsItsShear) {
  const Blocks b = [] {
    Blocks three = two_blocks_at_rest();
    three.count = 3;
    three.state.position.push_back(Vec3::Zero());
    three.state.orientation.push_back(Quat::Identity());
    three.state.rotation.push_back(Mat3::Identity());
    return three;
  }();
  ContactSet previous = one_pair({{0.5, 0.5, 0.25, 11}});
  previous.sub.slip_energy[0] = 3.0;
  previous.sub.shear_force.set(0, Vec3(500, 0, 0));
  ContactSet current = one_pair({{0.5, 0.5, 0.25, 11}}, 0, 0, 2);
  CarryScratch scratch = moved_by(kReach);
  carry_history(b, previous, current, ks_laws(b), scratch);
  EXPECT_EQ(current.sub.shear_force[0], Vec3::Zero());
  EXPECT_EQ(current.sub.slip_energy[0], 0.0);
  EXPECT_EQ(current.retired_slip_energy, 3.0);
  EXPECT_DOUBLE_EQ(current.dropped_shear_energy, energy(Vec3(500, 0, 0), 0.25));
  EXPECT_EQ(find_pair(previous, 0, 1), &previous.pairs[0]);
  EXPECT_EQ(find_pair(previous, 0, 2), nullptr);
}

// hold_normal_strain: a detection's re-sampling may lower a pair's normal
// strain at the same pose, never raise it; a rise is taken back by moving
// the pair's plane by δ, after which the joint has its full stiffness.
constexpr double kKn = 1e10;

double normal_energy(const Blocks& b, const ContactSet& cs) {
  return normal_strain_energy_now(uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count), b.state, cs.sub);
}

TEST(HoldNormalStrain, ASliverFoundDeepUnderAFullPolygonKeepsItsEnergy) {
  // A corner 8.5 mm into its neighbour under a sliver of 1e-4 m² (the
  // spire's 1.0 g run); the next detection finds the whole unit square.
  Blocks b = two_blocks_at_rest();
  const double u = 8.5e-3;
  b.state.position[1] = Vec3(0, 0, -u);
  const ContactSet previous = one_pair({{0.4, 0.4, 1e-4, 1}});
  ContactSet current = one_pair(square(11));
  for (int s = 0; s < 4; ++s) current.sub.overlap[s] = u;  // as build_subcontacts leaves it: the geometry's
  const double e_old = normal_energy(b, previous);
  ASSERT_NEAR(e_old, 0.5 * kKn * 1e-4 * u * u, 1e-9 * e_old);
  ASSERT_NEAR(normal_energy(b, current), 1e4 * e_old, 1e-9 * 1e4 * e_old);  // 36 kJ from nowhere
  hold_normal_strain(uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count), b.state, previous, current);
  EXPECT_NEAR(normal_energy(b, current), e_old, 1e-12 * 1e4 * e_old);
  // One shift for the pair: (u − δ)²·1 m² = u²·1e-4 m², δ = 0.99·u.
  for (int s = 0; s < 4; ++s) {
    EXPECT_NEAR(-current.sub.ref_offset_local[s], 0.99 * u, 1e-12) << s;
    EXPECT_EQ(current.sub.crush[s], -current.sub.ref_offset_local[s]) << s;  // what penetration is judged on
    EXPECT_NEAR(current.sub.overlap[s], 0.01 * u, 1e-12) << s;             // the spring's
    EXPECT_NEAR(current.sub.geometric_overlap(s), u, 1e-15) << s;          // the blocks'
  }
  // From there on the joint has the square's full stiffness kn·1 m².
  b.state.position[1].z() -= 1e-4;
  EXPECT_NEAR(normal_energy(b, current), 0.5 * kKn * std::pow(0.01 * u + 1e-4, 2), 1e-9 * e_old);
}

TEST(HoldNormalStrain, ATiltedPatchPartlyOpenMatchesThePreviousEnergy) {
  // The incident block tilted about x: u = 2 mm − 4 mm·y, one edge open.
  Blocks b = two_blocks_at_rest();
  const double tilt = 4e-3;
  b.state.orientation[1] = Quat(Eigen::AngleAxisd(tilt, Vec3::UnitX()));
  b.state.rotation[1] = b.state.orientation[1].toRotationMatrix();
  b.state.position[1] = Vec3(0, 0, -2e-3);
  const ContactSet previous = one_pair({{0.0, -0.5, 0.05, 1}, {0.0, 0.0, 0.05, 2}});
  ContactSet current = one_pair({{-0.5, -0.5, 0.3, 11}, {0.5, -0.5, 0.3, 12}, {0.5, 0.5, 0.2, 13},
                                 {-0.5, 0.5, 0.2, 14}});
  const double e_old = normal_energy(b, previous), e_new = normal_energy(b, current);
  ASSERT_GT(e_new, 2 * e_old);
  hold_normal_strain(uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count), b.state, previous, current);
  EXPECT_NEAR(normal_energy(b, current), e_old, 1e-12 * e_new);
  EXPECT_LT(current.sub.ref_offset_local[0], 0.0);
  EXPECT_EQ(current.sub.ref_offset_local[0], current.sub.ref_offset_local[3]);
}

TEST(HoldNormalStrain, LoweringIsLeftAloneANewPairStartsAtZeroForceBondsAreKept) {
  Blocks b = two_blocks_at_rest();
  b.state.position[1] = Vec3(0, 0, -1e-3);
  const JointLaws laws = uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count);
  // Less strain than before: the ledger books it, the plane stays.
  ContactSet full = one_pair(square(1));
  ContactSet sliver = one_pair({{0.4, 0.4, 1e-4, 11}});
  hold_normal_strain(laws, b.state, full, sliver);
  EXPECT_EQ(sliver.sub.ref_offset_local[0], 0.0);
  // At the first detection (the structure as built) pairs start from the
  // geometry; after it a pair found already overlapping starts at zero
  // force (its plane moved to its deepest point).
  ContactSet other = one_pair({{0.4, 0.4, 1e-4, 11}}, 0, 0, 2);
  ContactSet again = one_pair(square(1));
  hold_normal_strain(laws, b.state, other, again);
  for (int s = 0; s < 4; ++s) EXPECT_EQ(again.sub.ref_offset_local[s], 0.0);
  other.detections = 1;
  hold_normal_strain(laws, b.state, other, again);
  for (int s = 0; s < 4; ++s) EXPECT_NEAR(again.sub.ref_offset_local[s], -1e-3, 1e-15);
  EXPECT_EQ(normal_energy(b, again), 0.0);
  // A bonded joint (tension) is not shifted.
  ContactSet bonded = one_pair(square(1));
  bonded.sub.bonded[2] = 1;
  hold_normal_strain(laws, b.state, sliver, bonded);
  for (int s = 0; s < 4; ++s) EXPECT_EQ(bonded.sub.ref_offset_local[s], 0.0);
}

TEST(HoldNormalStrain, AReferenceFaceThatChangesSidesIsHeldAlike) {
  // The previous sliver on block 0's face, the new square on block 1's (its
  // normal −z in block 1's frame): the same overlap u either way.
  Blocks b = two_blocks_at_rest();
  const double u = 5e-3;
  b.state.position[1] = Vec3(0, 0, -u);
  const ContactSet previous = one_pair({{0.4, 0.4, 1e-4, 1}});
  ContactSet current = one_pair(square(11), 1);
  const double e_old = normal_energy(b, previous), e_new = normal_energy(b, current);
  ASSERT_NEAR(e_new, 1e4 * e_old, 1e-9 * e_new);
  hold_normal_strain(uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count), b.state, previous, current);
  EXPECT_NEAR(normal_energy(b, current), e_old, 1e-12 * e_new);
  for (int s = 0; s < 4; ++s) EXPECT_NEAR(current.sub.crush[s], 0.99 * u, 1e-12) << s;
}

TEST(HoldNormalStrain, ABondsTensionIsNotHandedOnAsCompression) {
  // The previous pair: one corner pressed 1 mm, one bonded corner pulled
  // 3 mm (tension). The new, unbonded square may hold only the compression.
  Blocks b = two_blocks_at_rest();
  const double tilt = 4e-3;  // u = 1 mm at y = −0.5 .. −3 mm at y = +0.5
  b.state.orientation[1] = Quat(Eigen::AngleAxisd(tilt, Vec3::UnitX()));
  b.state.rotation[1] = b.state.orientation[1].toRotationMatrix();
  b.state.position[1] = Vec3(0, 0, 1e-3);
  ContactSet previous = one_pair({{0.0, -0.5, 0.05, 1}, {0.0, 0.5, 0.05, 2}});
  previous.sub.bonded[1] = 1;
  ContactSet current = one_pair({{-0.5, -0.5, 0.25, 11}, {0.5, -0.5, 0.25, 12}, {0.5, 0.5, 0.25, 13},
                                 {-0.5, 0.5, 0.25, 14}});
  const double u_pressed = 0.5 * std::sin(tilt) - 1e-3;  // the corner at y = −0.5
  const double compression = 0.5 * kKn * 0.05 * u_pressed * u_pressed;
  ASSERT_GT(normal_energy(b, previous), 5 * compression);  // the bond's tension counts in the ledger
  hold_normal_strain(uniform_joint_laws(JointLaw{kKn, kKs, 0.5, 0, 0, 0}, b.count), b.state, previous, current);
  EXPECT_NEAR(normal_energy(b, current), compression, 1e-12 * normal_energy(b, previous));
}

}  // namespace
}  // namespace polydem
