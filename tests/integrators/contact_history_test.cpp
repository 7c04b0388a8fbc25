// Shear history across re-detection, in whole runs: the stored shear must
// belong to the place on the joint, survive the detections that re-clip the
// patch, and whatever shear a detection cannot carry (area that is gone) must
// be booked so that the energy ledger still closes.
//
// The blocks start in static equilibrium on their joints (lowered by the
// settlement m·g/(kn·A)), so no sudden load rings the joints.
#include "integrators/simulation.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polydem {
namespace {

constexpr double kG = 9.81;

BlockSpec box(const std::string& name, Vec3 size, Vec3 centre, BlockMotion motion = BlockMotion::free) {
  BlockSpec s;
  s.name = name;
  s.shape = make_box(size, centre);
  s.density = 2600.0;
  s.motion = motion;
  return s;
}

// The turn of block i about z since the start, rad.
double twist(const Simulation& s, int i) {
  const Quat dq = s.blocks().state.orientation[i] * s.blocks().initial_orientation[i].conjugate();
  return 2.0 * std::atan2(dq.z(), dq.w());
}

// Tracks, after every step, the ledger's numerical line beside what the
// detections counted as handed on imperfectly (the elastic shear they
// dropped, the normal strain their re-sampling removed): `worst` is the
// largest |numerical + dropped + re-sampled| over the energy put in, what
// the numerics lost besides the detections.
struct BalanceError {
  EnergyLedger start;
  double reference = 0, worst = 0, numerical = 0;
  bool first = true;
  void observe(const Simulation& s) {
    const EnergyLedger e = s.energies();
    if (first) {
      start = e;
      first = false;
    }
    numerical = numerical_energy(e, start);
    const double detections = s.contacts().dropped_shear_energy + s.contacts().resampled_normal_energy;
    reference = std::max(reference, energy_put_in(e, start));
    if (reference > 0) worst = std::max(worst, std::abs(numerical + detections) / reference);
  }
};

// A 1 m cube on an equal fixed cube, spun about the vertical at 0.54 rad/s:
// it twists elastically on its joint (ks = 6.2e5 Pa/m, torsional stiffness
// ks·ΣA·r² = 3.1e5 N·m/rad) to about 0.02 rad, where the shear at its
// corners is 60 % of what friction holds (μ·m·g/4 each), and springs back:
// a torsional oscillator with no damping. A turn of 0.0115 rad moves its
// corners half the 2 cm margin, so detection runs while it is twisted, and
// the corners of the top cube, now outside the bottom one's face, are
// clipped into eight edge crossings: a new clip topology on the same joint.
// The stored shear must survive: the cube must swing back through its
// initial orientation to the same twist the other way (measured: centred
// within 3 % of the swing, since the eight crossings sample the twist's
// field with less stiffness than the four corners; the detection drops
// 6.2 J of shear energy, which the ledger's numerical line shows, and the
// rest of the numerical line is 1.0 % of the energy put in).
TEST(ContactHistory, TwistedBlockSpringsBackThroughReDetection) {
  SimulationSpec sim;
  sim.gravity = Vec3(0, 0, -kG);
  sim.detection_trigger = DetectionTrigger::scene;  // the detections counted below are the scene's
  sim.detection_travel = 0.01;  // re-detected once twisted by 0.01 rad (half the 0.02 m margin)
  JointSpec joint;
  joint.normal_stiffness = 1e9;
  joint.shear_stiffness = 6.2e5;
  joint.damping = 0;
  const double m = 2600.0;
  const double settle = m * kG / joint.normal_stiffness;  // m, over the 1 m² face
  BlockSpec top = box("top", Vec3(1, 1, 1), Vec3(0, 0, 0.5 - settle));
  top.angular_velocity = Vec3(0, 0, 0.54);
  Blocks blocks = build_blocks({box("base", Vec3(1, 1, 1), Vec3(0, 0, -0.5), BlockMotion::fixed), top});
  const double dt = critical_time_step(blocks, make_joint_law(joint), sim.safety_factor).chosen;
  Simulation s = one_law_simulation(std::move(blocks), sim, joint, GroundMotion{}, 0.02, dt);
  BalanceError balance;
  double lo = 0, hi = 0, twist_at_redetection = 0;
  int subcontacts_after = 0;
  while (s.time() < 1.0) {  // four periods of the torsional mode (0.24 s)
    const int detections = s.contacts().detections;
    s.step();
    balance.observe(s);
    if (detections == 1 && s.contacts().detections == 2) {
      twist_at_redetection = twist(s, 1);
      subcontacts_after = static_cast<int>(s.contacts().sub.size());
    }
    if (s.contacts().detections >= 2) {
      lo = std::min(lo, twist(s, 1));
      hi = std::max(hi, twist(s, 1));
    }
  }
  std::printf("twist: re-detected at %.4f rad (%d subcontacts), swings %.4f .. %.4f rad, centre %.2e, slip %.3g J, "
              "dropped %.3g J, balance error %.2e\n",
              twist_at_redetection, subcontacts_after, lo, hi, 0.5 * (lo + hi), s.energies().slip,
              s.contacts().dropped_shear_energy, balance.worst);
  ASSERT_GT(std::abs(twist_at_redetection), 0.01) << "the test must re-detect while the block is twisted";
  EXPECT_EQ(subcontacts_after, 8) << "the clip's topology must have changed (the test's premise)";
  EXPECT_GT(hi, 0.018);
  EXPECT_LT(lo, -0.018);
  // Centred on the initial orientation, to 5 % of the swing.
  EXPECT_LT(std::abs(hi + lo), 0.05 * (hi - lo));
  EXPECT_EQ(s.energies().slip, 0.0) << "the peak shear is meant to stay below friction";
  EXPECT_LT(balance.worst, 0.015);
}

// A 1 × 1 × 0.5 m stone (1300 kg) slides at 1.5 m/s towards the edge of its
// base, flush with it, and stops 0.14-0.2 m past it, its patch shrinking as
// it goes (the corners past the edge clipped into crossings on it). The
// joints' shear springs are soft (ks = 2.5e5 Pa/m: an elastic shear
// displacement of 3 cm at friction) so that the shear energy of the area
// lost over the edge is a sizeable share of the energy put in, and the
// ledger's numerical line must show it. Clipped as it moves (the default),
// each spring keeps its elastic shear displacement as its area shrinks, and
// the joint loses the energy of the area that left (25.5 J of 1463 J);
// re-sampled at detection (every centimetre), each detection drops the
// shear it cannot hand on (74.7 J). The rest of the line is below 0.1 % of
// the energy put in (measured 0.048 % and 0.038 %; the stored shear a
// falling Coulomb cap lets slip off is friction's work, booked as slip:
// contact/joint_law.hpp).
TEST(ContactHistory, LedgerClosesWhenASlidingBlockLeavesItsBase) {
  for (JointSampling sampling : {JointSampling::automatic, JointSampling::detection}) {
    SimulationSpec sim;
    sim.gravity = Vec3(0, 0, -kG);
    sim.joint_sampling = sampling;
    JointSpec joint;
    joint.normal_stiffness = 1e9;
    joint.shear_stiffness = 2.5e5;
    const double settle = 2600 * 0.5 * kG / joint.normal_stiffness;
    BlockSpec stone = box("stone", Vec3(1, 1, 0.5), Vec3(0, 0, 0.25 - settle));
    stone.velocity = Vec3(1.5, 0, 0);
    Blocks blocks = build_blocks({box("base", Vec3(2, 2, 0.5), Vec3(-0.5, 0, -0.25), BlockMotion::fixed), stone});
    const double dt = critical_time_step(blocks, make_joint_law(joint), sim.safety_factor).chosen;
    Simulation s = one_law_simulation(std::move(blocks), sim, joint, GroundMotion{}, 0.01, dt);
    BalanceError balance;
    while (s.time() < 1.0) {
      s.step();
      balance.observe(s);
    }
    const double dropped = s.contacts().dropped_shear_energy;
    std::printf("slide off (%s): %.3f m past the edge, %d detections, dropped %.3g J, numerical %.3g J of %.4g J "
                "put in, rest %.2e\n",
                sampling == JointSampling::detection ? "detection" : "clip", s.blocks().state.position[1].x(),
                s.contacts().detections, dropped, balance.numerical, balance.reference, balance.worst);
    EXPECT_GT(s.blocks().state.position[1].x(), 0.1) << "the stone must slide well past the edge";
    EXPECT_GT(dropped, 0.015 * balance.reference) << "the test's premise: the dropped shear matters";
    EXPECT_LT(balance.numerical, -0.9 * dropped) << "the ledger's numerical line shows the shear dropped";
    EXPECT_GT(balance.numerical, -1.1 * dropped) << "and little else";
    EXPECT_LT(balance.worst, 0.001);
  }
}

}  // namespace
}  // namespace polydem
