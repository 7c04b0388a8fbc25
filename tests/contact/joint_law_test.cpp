// The Coulomb joint law on one subcontact, against hand-computed forces.
//
// Geometry: the reference block sits at the origin with its face plane z = 0
// (normal +z); the incident block's centroid is at z = 0.5 and its contact
// point at body-frame (0.25, −0.25, −0.5 − δ), i.e. at depth δ below the
// plane. δ is a power of two so u_n = δ is exact, and every expected force
// below is a product of the same factors the law multiplies: they agree to
// a few ulps (EXPECT_DOUBLE_EQ, 4 ulps) or, for sums, to 1e-12 relative.
#include "contact/joint_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace polydem {
namespace {

constexpr double kDelta = 1.0 / 4096.0;  // 2⁻¹², m
constexpr double kA = 0.25;              // m²
constexpr double kDt = 1e-5;             // s

JointLaw law_for_test() {
  JointLaw law;
  law.kn = 1e10;
  law.ks = 4e9;
  law.tan_phi = 0.5;
  return law;
}

struct OneSubcontact {
  BlockState st;
  Subcontacts sub;
  explicit OneSubcontact(double depth) {
    st.position = {Vec3::Zero(), Vec3(0, 0, 0.5)};
    st.orientation = {Quat::Identity(), Quat::Identity()};
    st.rotation = {Mat3::Identity(), Mat3::Identity()};
    st.velocity = {Vec3::Zero(), Vec3::Zero()};
    st.angular_momentum = {Vec3::Zero(), Vec3::Zero()};
    st.angular_velocity = {Vec3::Zero(), Vec3::Zero()};
    st.contact_force = {Vec3::Zero(), Vec3::Zero()};
    st.contact_torque = {Vec3::Zero(), Vec3::Zero()};
    sub.resize(1);
    sub.pair[0] = 0;
    sub.ref_block[0] = 0;
    sub.inc_block[0] = 1;
    sub.key[0] = 7;
    sub.ref_normal_local[0] = Vec3::UnitZ();
    sub.ref_offset_local[0] = 0.0;
    sub.inc_point_local.set(0, Vec3(0.25, -0.25, -0.5 - depth));
    sub.area[0] = kA;
    sub.shear_force.set(0, Vec3::Zero());
    sub.bonded[0] = 0;
    sub.force[0] = Vec3::Zero();
    sub.point[0] = Vec3::Zero();
    sub.overlap[0] = 0;
    sub.normal_force[0] = 0;
    sub.slip_energy[0] = 0;
    sub.damping_energy[0] = 0;
    sub.damping_force.set(0, Vec3::Zero());
  }
  // One step of the law (one pair of one subcontact).
  void run(const JointLaw& law) {
    ContactPair p;
    p.a = 0;
    p.b = 1;
    p.ref_block = 0;
    p.count = 1;
    compute_pair_forces(uniform_joint_laws(law, 2), st, {p}, sub, kDt, 0, 1);
  }
  // Both blocks turned by R about the origin (the reference block's centroid).
  void pose(const Mat3& R) {
    st.rotation = {R, R};
    st.orientation = {Quat(R), Quat(R)};
    st.position[1] = R * Vec3(0, 0, 0.5);
  }
};

TEST(JointLaw, NormalForceIsKnAOverlap) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  c.run(law);
  const double fn = law.kn * kA * kDelta;  // 610351.5625 N, exact
  EXPECT_EQ(c.sub.overlap[0], kDelta);
  EXPECT_DOUBLE_EQ(c.sub.normal_force[0], fn);
  EXPECT_DOUBLE_EQ(c.sub.force[0].z(), fn);
  EXPECT_EQ(c.sub.force[0].x(), 0.0);
  EXPECT_EQ(c.sub.force[0].y(), 0.0);
  EXPECT_NEAR((c.sub.point[0] - Vec3(0.25, -0.25, -kDelta)).norm(), 0.0, 1e-15);
  // Stored energy: ½·kn·A·u_n².
  EXPECT_DOUBLE_EQ(joint_strain_energy(uniform_joint_laws(law, 2), c.sub), 0.5 * law.kn * kA * kDelta * kDelta);
}

TEST(JointLaw, ShearForceIncrementsBy_ksA_vs_dt) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  c.st.velocity[1] = Vec3(0.01, 0, 0);  // incident slides +x over the reference
  c.run(law);
  const double dfs = law.ks * kA * kDt * 0.01;  // 100 N, opposing the sliding
  EXPECT_NEAR(c.sub.shear_force[0].x(), -dfs, 1e-12 * dfs);
  EXPECT_NEAR(c.sub.force[0].x(), -dfs, 1e-12 * dfs);
  EXPECT_EQ(c.sub.slip_energy[0], 0.0);
  // Incremental: a second step adds the same amount.
  c.run(law);
  EXPECT_NEAR(c.sub.shear_force[0].x(), -2 * dfs, 1e-12 * dfs);
  // Relative velocity is incident minus reference: moving both does nothing.
  OneSubcontact d(kDelta);
  d.st.velocity[0] = d.st.velocity[1] = Vec3(0.01, 0.02, 0);
  d.run(law);
  EXPECT_NEAR(d.sub.shear_force[0].norm(), 0.0, 1e-9);
  // Elastic shear energy: |Fs|²/(2·ks·A).
  EXPECT_NEAR(joint_strain_energy(uniform_joint_laws(law, 2), c.sub),
              0.5 * law.kn * kA * kDelta * kDelta + 0.5 * (2 * dfs) * (2 * dfs) / (law.ks * kA), 1e-12);
}

TEST(JointLaw, StoredShearIsRotatedIntoThePlane) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  c.sub.shear_force.set(0, Vec3(30, -40, 50));  // has a normal component
  c.run(law);
  EXPECT_EQ(c.sub.shear_force[0], Vec3(30, -40, 0));
}

// Both blocks spinning as one about the joint's normal (no relative motion
// at the point): the stored shear turns with them, by ω·dt a step, and keeps
// its length. Before the joint's spin was applied it stayed fixed in space.
TEST(JointLaw, StoredShearTurnsWithAPairSpinningAboutTheNormal) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  const double w = 100.0;  // rad/s: 1e-3 rad a step
  c.st.angular_velocity = {Vec3(0, 0, w), Vec3(0, 0, w)};
  const Vec3 f0(300, 0, 0);
  c.sub.shear_force.set(0, f0);
  c.run(law);
  const Vec3 one_step = Eigen::AngleAxisd(w * kDt, Vec3::UnitZ()) * f0;
  EXPECT_NEAR((c.sub.shear_force[0] - one_step).norm(), 0.0, 1e-12 * f0.norm());
  // A quarter turn in 1571 steps (the pair's pose follows): the force ends
  // along y, as long as it started.
  const int n = 1571;
  const double step = (std::acos(-1.0) / 2) / n;
  c.st.angular_velocity = {Vec3(0, 0, step / kDt), Vec3(0, 0, step / kDt)};
  c.sub.shear_force.set(0, f0);
  for (int k = 1; k <= n; ++k) {
    c.pose(Eigen::AngleAxisd(k * step, Vec3::UnitZ()).toRotationMatrix());
    c.run(law);
  }
  EXPECT_NEAR((c.sub.shear_force[0] - Vec3(0, 300, 0)).norm(), 0.0, 1e-9 * f0.norm());
  // The twist is the mean of the two spins: with the reference block still,
  // the force turns by half the incident block's turn (the incident block's
  // own motion at the point adds the increment −ks·A·v_s·dt on top).
  // (1 rad/s: the increment, 3.5 kN, stays under the Coulomb cap.)
  OneSubcontact d(kDelta);
  const double w_inc = 1.0;
  d.st.angular_velocity[1] = Vec3(0, 0, w_inc);
  d.sub.shear_force.set(0, f0);
  d.run(law);
  const Vec3 arm = d.sub.point[0] - d.st.position[1];
  const Vec3 increment = -(law.ks * kA * kDt) * Vec3(0, 0, w_inc).cross(arm);
  const Vec3 expected = Eigen::AngleAxisd(0.5 * w_inc * kDt, Vec3::UnitZ()) * f0 + increment;
  // The half turn moves f0 by 1.5e-3 N; round-off is ~1e-12 of the increment.
  EXPECT_NEAR((d.sub.shear_force[0] - expected).norm(), 0.0, 1e-12 * (f0.norm() + increment.norm()));
}

// The pair tilting as one (the normal turns with the reference block): the
// stored shear turns with the plane and keeps its length; projecting it onto
// the new plane alone would shorten it by 1 − cos θ a step.
TEST(JointLaw, StoredShearTurnsWithTheNormalAndKeepsItsLength) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  const double w = 100.0;
  const Mat3 R = Eigen::AngleAxisd(w * kDt, Vec3::UnitX()).toRotationMatrix();
  c.pose(R);  // the pose at t: turned by ω·dt since the force was stored
  c.st.angular_velocity = {Vec3(w, 0, 0), Vec3(w, 0, 0)};
  c.st.velocity[1] = Vec3(w, 0, 0).cross(c.st.position[1]);  // rigid with the reference block
  const Vec3 f0(0, 300, 0);  // in the plane of t − dt
  c.sub.shear_force.set(0, f0);
  c.run(law);
  EXPECT_NEAR((c.sub.shear_force[0] - R * f0).norm(), 0.0, 1e-12 * f0.norm());
  EXPECT_NEAR(c.sub.shear_force[0].norm(), 300.0, 1e-12 * 300.0);
}

// A joint that does not move while its normal force falls (the edge of a
// stone lifting): Coulomb's cap falls below the stored shear, which slips
// down to it under a friction force that falls with the cap. Friction's
// work is the strain energy given up, (F² − c²)/(2·ks·A), whether the cap
// falls in one step or in many: what is booked does not depend on the step.
// (Booking the cap times the slip, c·(F − c)/(ks·A), would give c²/(ks·A)
// here in one step and nearly 1.5·c²/(ks·A) in 64.)
TEST(JointLaw, AFallingCapBooksFrictionsWorkHoweverFastItFalls) {
  const JointLaw law = law_for_test();
  const double cap = law.kn * kA * kDelta * law.tan_phi;
  const Vec3 f0(0, 2.0 * cap, 0);  // stored under twice the normal force
  const double released = 0.5 * (f0.squaredNorm() - cap * cap) / (law.ks * kA);
  for (const int steps : {1, 64}) {
    OneSubcontact c(2.0 * kDelta);
    c.sub.shear_force.set(0, f0);
    for (int i = 1; i <= steps; ++i) {  // at rest: the depth falls from 2δ to δ
      const double depth = kDelta * (2.0 - static_cast<double>(i) / steps);
      c.sub.inc_point_local.set(0, Vec3(0.25, -0.25, -0.5 - depth));
      c.run(law);
    }
    EXPECT_NEAR(c.sub.shear_force[0].norm(), cap, 1e-12 * cap) << steps;
    EXPECT_NEAR(c.sub.slip_energy[0], released, 1e-12 * released) << steps;
  }
}

TEST(JointLaw, CoulombCapAndSlipEnergy) {
  const JointLaw law = law_for_test();
  OneSubcontact c(kDelta);
  const double v = 100.0;  // m/s: trial force 1e6 N, well over the cap
  c.st.velocity[1] = Vec3(0, v, 0);
  c.run(law);
  const double fn = law.kn * kA * kDelta;
  const double cap = fn * law.tan_phi;        // 305175.78125 N
  const double trial = law.ks * kA * kDt * v;  // 1e6 N
  EXPECT_NEAR(c.sub.shear_force[0].y(), -cap, 1e-12 * cap);
  EXPECT_NEAR(c.sub.shear_force[0].norm(), cap, 1e-12 * cap);
  // Plastic slip (trial − cap)/(ks·A) under the force cap.
  const double slip = (trial - cap) / (law.ks * kA);
  EXPECT_NEAR(c.sub.slip_energy[0], cap * slip, 1e-12 * cap * slip);
  // Slipping: no shear damping even with β > 0.
  JointLaw damped = law;
  damped.beta = 1e-4;
  OneSubcontact d(kDelta);
  d.st.velocity[1] = Vec3(0, v, 0);
  d.run(damped);
  EXPECT_NEAR(d.sub.force[0].y(), -cap, 1e-12 * cap);
}

// friction_normal_force = "total": the cap is (F_n + dashpot)·tan φ while the
// joint closes; "elastic" (the default) F_n·tan φ. An opening joint's
// dashpot pulls the cap down, never below zero.
TEST(JointLaw, FrictionOnTheTotalNormalForce) {
  JointLaw law = law_for_test();
  law.beta = 1e-4;
  const double v = 100.0, closing = 0.5;  // m/s: the trial force far over either cap
  const double fn_el = law.kn * kA * kDelta;
  const double fn_damp = law.beta * law.kn * kA * closing;  // 125000 N
  for (const bool total : {false, true}) {
    JointLaw l = law;
    l.friction_on_total = total;
    OneSubcontact c(kDelta);
    c.st.velocity[1] = Vec3(0, v, -closing);
    c.run(l);
    const double cap = (total ? fn_el + fn_damp : fn_el) * law.tan_phi;
    EXPECT_NEAR(c.sub.shear_force[0].norm(), cap, 1e-12 * cap) << (total ? "total" : "elastic");
    EXPECT_NEAR(c.sub.normal_force[0], fn_el + fn_damp, 1e-12 * fn_el);  // the normal force is the same
    const double slip = (law.ks * kA * kDt * v - cap) / (law.ks * kA);
    EXPECT_NEAR(c.sub.slip_energy[0], cap * slip, 1e-12 * cap * slip);
  }
  // Opening fast: the dashpot would pull harder than the spring pushes.
  JointLaw l = law;
  l.friction_on_total = true;
  OneSubcontact c(kDelta);
  c.st.velocity[1] = Vec3(0, v, 10.0);
  c.run(l);
  EXPECT_EQ(c.sub.shear_force[0].norm(), 0.0);
  OneSubcontact opening_slowly(kDelta);
  opening_slowly.st.velocity[1] = Vec3(0, v, 0.2 * closing);
  opening_slowly.run(l);
  EXPECT_NEAR(opening_slowly.sub.shear_force[0].norm(), (fn_el - 0.2 * fn_damp) * law.tan_phi, 1e-12 * fn_el);
}

TEST(JointLaw, StiffnessProportionalDamping) {
  JointLaw law = law_for_test();
  law.beta = 1e-4;
  OneSubcontact c(kDelta);
  const double closing = 0.01, vs = 0.002;  // m/s
  c.st.velocity[1] = Vec3(vs, 0, -closing);  // u̇_n = +closing
  c.run(law);
  const double fn_el = law.kn * kA * kDelta;
  const double fn_damp = law.beta * law.kn * kA * closing;  // 2500 N
  EXPECT_NEAR(c.sub.normal_force[0], fn_el + fn_damp, 1e-12 * fn_el);
  EXPECT_NEAR(c.sub.force[0].z(), fn_el + fn_damp, 1e-12 * fn_el);
  const double fs_el = law.ks * kA * kDt * vs;
  const double fs_damp = law.beta * law.ks * kA * vs;
  EXPECT_NEAR(c.sub.force[0].x(), -(fs_el + fs_damp), 1e-12 * fs_damp);
  // The stored (elastic) shear does not include damping.
  EXPECT_NEAR(c.sub.shear_force[0].x(), -fs_el, 1e-12 * fs_el);
  // The dashpot force is kept for the next step.
  EXPECT_NEAR((c.sub.damping_force[0] - Vec3(-fs_damp, 0, fn_damp)).norm(), 0.0, 1e-12 * fn_damp);
  // Half the step's work is booked with the velocity the force came from:
  // dt/2·(F_damp,n·u̇_n + F_damp,s·v_s).
  const double first_half = 0.5 * kDt * (fn_damp * closing + fs_damp * vs);
  EXPECT_NEAR(c.sub.damping_energy[0], first_half, 1e-12 * first_half);
  // The other half with the next half step's velocity (the work at the
  // centred velocity): here the joint closes at half the speed and slides
  // back, so over that half the shear dashpot gave work back.
  c.st.velocity[1] = Vec3(-vs, 0, -0.5 * closing);
  c.sub.damping_force.set(0, Vec3(-fs_damp, 0, fn_damp));  // exactly, for the hand sum
  const double before = c.sub.damping_energy[0];
  c.run(law);
  const double second_half = 0.5 * kDt * (fn_damp * 0.5 * closing - fs_damp * vs);
  const double this_first_half = 0.5 * kDt * (0.5 * fn_damp * 0.5 * closing + fs_damp * vs);
  EXPECT_NEAR(c.sub.damping_energy[0] - before, second_half + this_first_half, 1e-12 * first_half);
}

// The work of the last step's dashpot force owed when detection replaces the
// subcontacts (or a joint opens) is booked with the velocity of now.
TEST(JointLaw, PendingDashpotWorkIsSettledWithTheVelocityOfNow) {
  JointLaw law = law_for_test();
  law.beta = 1e-4;
  OneSubcontact c(kDelta);
  c.sub.damping_force.set(0, Vec3(0, 0, 1000));  // N, pushing the incident block up
  c.st.velocity[1] = Vec3(0, 0, -0.5);         // still closing
  settle_damping_work(c.st, c.sub, kDt);
  EXPECT_DOUBLE_EQ(c.sub.damping_energy[0], 0.5 * kDt * 1000 * 0.5);
  EXPECT_EQ(c.sub.damping_force[0], Vec3::Zero());
  // An opening joint books it too, then carries nothing.
  OneSubcontact d(-kDelta);
  d.sub.damping_force.set(0, Vec3(0, 0, 1000));
  d.st.velocity[1] = Vec3(0, 0, 0.5);  // opening: the dashpot force did negative work on this half
  d.run(law);
  EXPECT_DOUBLE_EQ(d.sub.damping_energy[0], -0.5 * kDt * 1000 * 0.5);
  EXPECT_EQ(d.sub.damping_force[0], Vec3::Zero());
}

TEST(JointLaw, DampingNeverPullsAnUnbondedJointTogether) {
  JointLaw law = law_for_test();
  law.beta = 1e-2;
  OneSubcontact c(kDelta);
  c.st.velocity[1] = Vec3(0, 0, 10.0);  // separating fast: damping > elastic
  ASSERT_GT(law.beta * law.kn * kA * 10.0, law.kn * kA * kDelta);
  c.run(law);
  EXPECT_EQ(c.sub.normal_force[0], 0.0);
  EXPECT_EQ(c.sub.force[0].z(), 0.0);
}

TEST(JointLaw, NoTensionWhenOpen) {
  const JointLaw law = law_for_test();
  OneSubcontact c(-kDelta);  // a gap of δ
  c.st.velocity[1] = Vec3(0.5, 0, -0.1);
  c.run(law);
  EXPECT_EQ(c.sub.overlap[0], -kDelta);
  EXPECT_EQ(c.sub.force[0], Vec3::Zero());
  EXPECT_EQ(c.sub.normal_force[0], 0.0);
  EXPECT_EQ(c.sub.shear_force[0], Vec3::Zero());
  EXPECT_EQ(joint_strain_energy(uniform_joint_laws(law, 2), c.sub), 0.0);
}

// An opening joint's cap is zero: its stored shear slips off, friction's
// work the shear's strain energy, as for any cap falling below it.
TEST(JointLaw, OpeningLetsTheStoredShearSlipOff) {
  const JointLaw law = law_for_test();
  OneSubcontact c(-kDelta);
  const Vec3 fs(300, -400, 0);  // 500 N
  c.sub.shear_force.set(0, fs);
  c.sub.slip_energy[0] = 1.0;
  c.run(law);
  EXPECT_EQ(c.sub.shear_force[0], Vec3::Zero());
  const double stored = 0.5 * fs.squaredNorm() / (law.ks * kA);
  EXPECT_NEAR(c.sub.slip_energy[0], 1.0 + stored, 1e-12);
}

TEST(JointLaw, TensileBondHoldsUpToSigmaTA) {
  JointLaw law = law_for_test();
  law.tensile_strength = 1e6;  // Pa: holds 250 kN on A = 0.25 m²
  // A gap whose spring force is 1e-6 below σt·A: the bond holds (tension).
  const double gap_hold = law.tensile_strength / law.kn * (1 - 1e-6);
  OneSubcontact c(-gap_hold);
  c.sub.bonded[0] = 1;
  c.run(law);
  EXPECT_EQ(c.sub.bonded[0], 1);
  EXPECT_NEAR(c.sub.normal_force[0], -law.kn * kA * gap_hold, 1e-6);
  EXPECT_NEAR(c.sub.force[0].z(), -law.kn * kA * gap_hold, 1e-6);
  // Bonded open joints store tension energy too.
  EXPECT_NEAR(joint_strain_energy(uniform_joint_laws(law, 2), c.sub), 0.5 * law.kn * kA * gap_hold * gap_hold, 1e-9);
  // 1e-6 above σt·A: it breaks and carries nothing, for good.
  const double gap_break = law.tensile_strength / law.kn * (1 + 1e-6);
  OneSubcontact d(-gap_break);
  d.sub.bonded[0] = 1;
  d.run(law);
  EXPECT_EQ(d.sub.bonded[0], 0);
  EXPECT_EQ(d.sub.force[0], Vec3::Zero());
  OneSubcontact e(-gap_hold);  // after breaking, even a small gap carries nothing
  e.sub.bonded[0] = 0;
  e.run(law);
  EXPECT_EQ(e.sub.force[0], Vec3::Zero());
}

TEST(JointLaw, CohesionRaisesTheCapUntilTheFirstSlip) {
  JointLaw law = law_for_test();
  law.cohesion = 2e6;  // Pa: c·A = 500 kN
  const double fn = law.kn * kA * kDelta;
  const double cap_bonded = law.cohesion * kA + fn * law.tan_phi;  // 805175.78 N
  // Trial shear 700 kN: under the bonded cap, over the frictional one.
  OneSubcontact c(kDelta);
  c.sub.bonded[0] = 1;
  c.st.velocity[1] = Vec3(70.0, 0, 0);
  c.run(law);
  EXPECT_EQ(c.sub.bonded[0], 1);
  EXPECT_NEAR(c.sub.shear_force[0].x(), -7e5, 1e-12 * 7e5);
  EXPECT_EQ(c.sub.slip_energy[0], 0.0);
  // Trial shear 1 MN: capped at c·A + Fn·tan φ, and the bond is lost.
  OneSubcontact d(kDelta);
  d.sub.bonded[0] = 1;
  d.st.velocity[1] = Vec3(100.0, 0, 0);
  d.run(law);
  EXPECT_EQ(d.sub.bonded[0], 0);
  EXPECT_NEAR(d.sub.shear_force[0].x(), -cap_bonded, 1e-12 * cap_bonded);
  EXPECT_NEAR(d.sub.slip_energy[0], cap_bonded * (1e6 - cap_bonded) / (law.ks * kA), 1e-6);
  // Next step, same velocity: only friction is left.
  d.run(law);
  EXPECT_NEAR(d.sub.shear_force[0].norm(), fn * law.tan_phi, 1e-12 * fn);
}

TEST(JointLaw, MakeJointLawConvertsDegrees) {
  JointSpec spec;
  spec.friction_angle = 45.0;
  spec.normal_stiffness = 1e9;
  spec.shear_stiffness = 3e8;
  spec.cohesion = 5.0;
  spec.tensile_strength = 6.0;
  spec.damping = 7e-5;
  const JointLaw law = make_joint_law(spec);
  EXPECT_NEAR(law.tan_phi, 1.0, 1e-15);
  EXPECT_EQ(law.kn, 1e9);
  EXPECT_EQ(law.ks, 3e8);
  EXPECT_EQ(law.cohesion, 5.0);
  EXPECT_EQ(law.tensile_strength, 6.0);
  EXPECT_EQ(law.beta, 7e-5);
}

}  // namespace
}  // namespace polydem
