// joint_modes: the assembled system's frequencies against hand results, and
// the run's block-by-block bound above them on the spire.
//
// A stack of equal cubes on a fixed base, touching face to face: every joint
// is four corner subcontacts whose areas sum to the face (L²), symmetric
// about the stack's axis, so vertical translation is a mode family of its own:
// a chain base–k–m–k–m with k = kn·L², whose frequencies are
// ω² = (k/m)(3 ± √5)/2. One cube alone on the base vibrates at its own ω_b,
// where the run's bound says √2·ω_b. Tolerance 1e-9
// relative: a dense eigensolver's round-off. The joint bound a run takes
// with simulation.time_step_bound = "joint" (critical_time_step.hpp) lies
// above the exact frequency in every case and is exact on a fixed base.
#include "integrators/joint_modes.hpp"

#include "integrators/critical_time_step.hpp"
#include "integrators/simulation.hpp"
#include "io/deck.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace polydem {
namespace {

BlockSpec cube(const std::string& name, double z, BlockMotion motion = BlockMotion::free) {
  BlockSpec s;
  s.name = name;
  s.shape = make_box(Vec3(1, 1, 1), Vec3(0, 0, z));
  s.density = 2000.0;
  s.motion = motion;
  return s;
}

JointSpec stiff_joint() {
  JointSpec j;
  j.normal_stiffness = 1e10;
  j.shear_stiffness = 4e9;
  return j;
}

Simulation stack(int free_cubes) {
  std::vector<BlockSpec> specs{cube("base", -1.0, BlockMotion::fixed)};
  for (int i = 0; i < free_cubes; ++i) specs.push_back(cube(std::to_string(i), static_cast<double>(i)));
  return one_law_simulation(build_blocks(specs), SimulationSpec{}, stiff_joint(), GroundMotion{}, 0.01, 1e-6);
}

// The relative distance from `w` to the nearest of `omega`.
double nearest(const std::vector<double>& omega, double w) {
  double best = 1e300;
  for (double o : omega) best = std::min(best, std::abs(o - w) / w);
  return best;
}

// The run's joint bound of the highest frequency (rad/s).
double joint_bound(const Simulation& sim, const JointLaws& laws, const JointSpec& joint) {
  return critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, joint.damping, 0.8, 0, 1, StepBound::joint)
      .omega_max;
}

TEST(JointModes, OneCubeOnTheBaseVibratesAtItsOwnFrequency) {
  Simulation sim = stack(1);
  const JointLaws& laws = sim.joint_laws();
  const JointModes m = joint_modes(sim.blocks(), sim.contacts(), laws);
  const std::vector<double> own = block_frequencies_from_contacts(sim.blocks(), sim.contacts(), laws);
  ASSERT_EQ(m.omega.size(), 6u);
  EXPECT_NEAR(m.omega_max / own[1], 1.0, 1e-9);
  // On a held neighbour there is nothing to split: the tighter bound is exact.
  EXPECT_NEAR(m.split_bound / m.omega_max, 1.0, 1e-9);
  EXPECT_NEAR(m.block_bound / (std::sqrt(2.0) * own[1]), 1.0, 1e-12);
  EXPECT_NEAR(joint_bound(sim, laws, stiff_joint()) / m.omega_max, 1.0, 1e-9);
  // Vertical translation on kn·L²: √(kn/(ρL)).
  EXPECT_LT(nearest(m.omega, std::sqrt(1e10 / 2000.0)), 1e-9);
}

TEST(JointModes, TwoCubesStackedVibrateVerticallyAsTheChain) {
  Simulation sim = stack(2);
  const JointLaws& laws = sim.joint_laws();
  const JointModes m = joint_modes(sim.blocks(), sim.contacts(), laws);
  ASSERT_EQ(m.omega.size(), 12u);
  const double k_over_m = 1e10 * 1.0 / 2000.0;
  for (const double root : {(3 - std::sqrt(5.0)) / 2, (3 + std::sqrt(5.0)) / 2})
    EXPECT_LT(nearest(m.omega, std::sqrt(k_over_m * root)), 1e-9) << root;
  // Bounds above the exact highest, the split one no looser than the run's.
  EXPECT_GE(m.split_bound, m.omega_max * (1 - 1e-12));
  EXPECT_LE(m.split_bound, m.block_bound * (1 + 1e-12));
  const double joint = joint_bound(sim, laws, stiff_joint());
  EXPECT_GE(joint, m.omega_max * (1 - 1e-12));
  EXPECT_LE(joint, m.block_bound * (1 + 1e-12));
  const double shares = std::accumulate(m.share.begin(), m.share.end(), 0.0);
  EXPECT_NEAR(shares, 1.0, 1e-12);
  EXPECT_EQ(m.share[0], 0.0);  // the base does not move
}

// Three free cubes joined in a ring (two side by side, one bridging them):
// moving the whole cluster as one rigid body strains no joint, so exactly six
// frequencies are zero, and each face joint holds all six relative motions, so
// no other is. (A chain would not tell a wrong sign on one side of a joint: on
// a tree that is a change of variables with the same spectrum; a ring is not.)
TEST(JointModes, RigidMotionOfAFreeClusterStrainsNoJoint) {
  std::vector<BlockSpec> specs{cube("a", 0.0), cube("b", 0.0), cube("top", 1.0)};
  specs[0].shape = make_box(Vec3(1, 1, 1), Vec3(-0.5, 0, 0));
  specs[1].shape = make_box(Vec3(1, 1, 1), Vec3(0.5, 0, 0));
  Simulation sim = one_law_simulation(build_blocks(specs), SimulationSpec{}, stiff_joint(), GroundMotion{}, 0.01, 1e-6);
  ASSERT_EQ(sim.contacts().pairs.size(), 3u);
  const JointModes m = joint_modes(sim.blocks(), sim.contacts(), sim.joint_laws());
  ASSERT_EQ(m.omega.size(), 18u);
  for (int k = 0; k < 6; ++k) EXPECT_LT(m.omega[k], 1e-6 * m.omega_max) << k;
  EXPECT_GT(m.omega[6], 1e-2 * m.omega_max);
  EXPECT_GE(joint_bound(sim, sim.joint_laws(), stiff_joint()), m.omega_max * (1 - 1e-12));
}

// The spire at its first detection (examples/spire/earthquake.toml): the
// step's bound is the one the run computes, and both bounds lie above the
// assembled system's highest frequency (the exact one is 0.875 of the run's
// bound, the split scheme's 0.923, the joint bound's, with Gershgorin
// ratios, 0.921).
TEST(JointModes, TheSpiresStepBoundsLieAboveItsHighestFrequency) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  Simulation sim = one_law_simulation(build_blocks(spec.blocks), spec.simulation, spec.joint, GroundMotion{}, 0.005, 1e-6);
  const JointLaws& laws = sim.joint_laws();
  const JointModes m = joint_modes(sim.blocks(), sim.contacts(), laws);
  const CriticalStep run = critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, spec.joint.damping, 0.8);
  EXPECT_NEAR(m.block_bound / run.omega_max, 1.0, 1e-12);
  EXPECT_GT(m.block_bound, m.split_bound);
  EXPECT_GT(m.split_bound, m.omega_max);
  EXPECT_NEAR(m.omega_max / m.block_bound, 0.875, 0.005);
  EXPECT_NEAR(m.split_bound / m.block_bound, 0.923, 0.005);
  const double joint = joint_bound(sim, laws, spec.joint);
  EXPECT_GT(joint, m.omega_max);
  EXPECT_NEAR(joint / m.block_bound, 0.921, 0.005);
  EXPECT_NEAR(joint / m.split_bound, 0.997, 0.002);  // Gershgorin ratios against exact ones
  // The top mode lives in the top course's half-stones (course 19).
  double top_course = 0;
  for (int i = 0; i < sim.blocks().count; ++i)
    if (sim.blocks().props.name[i].rfind("course19_", 0) == 0) top_course += m.share[i];
  EXPECT_GT(top_course, 0.9);
}

// The 8-drum column (examples/structures/column.toml): the plinth on the
// fixed base sets the top mode, where the block bound's √2 is loosest and the
// joint bound counts the base joint once: 1.023 of the exact frequency,
// against 1.41 for the block bound.
TEST(JointModes, TheColumnsJointBoundIsCloseAboveItsHighestFrequency) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/structures/column.toml");
  Simulation sim = one_law_simulation(build_blocks(spec.blocks), spec.simulation, spec.joint, GroundMotion{}, 0.005, 1e-6);
  const JointLaws& laws = sim.joint_laws();
  const JointModes m = joint_modes(sim.blocks(), sim.contacts(), laws);
  const double joint = joint_bound(sim, laws, spec.joint);
  EXPECT_GT(joint, m.omega_max);
  EXPECT_NEAR(joint / m.omega_max, 1.023, 0.005);
  EXPECT_NEAR(m.block_bound / m.omega_max, 1.409, 0.005);
  EXPECT_NEAR(joint / m.split_bound, 1.008, 0.002);  // Gershgorin ratios against exact ones
}

TEST(JointModes, RefusesSceneTooLargeForADenseSolve) {
  std::vector<BlockSpec> specs;
  for (int i = 0; i <= max_joint_mode_blocks; ++i) specs.push_back(cube(std::to_string(i), 2.0 * i));
  Simulation sim = one_law_simulation(build_blocks(specs), SimulationSpec{}, stiff_joint(), GroundMotion{}, 0.01, 1e-6);
  EXPECT_THROW(joint_modes(sim.blocks(), sim.contacts(), sim.joint_laws()),
               std::invalid_argument);
}

}  // namespace
}  // namespace polydem
