// critical_time_step against a hand computation for boxes.
//
// A box a × b × c (body axes x, y, z) with every face in full contact. A face
// point displaced by u carries kn·(n·u)n + ks·(u − (n·u)n) per unit area.
//
// Translation along x: the two x-faces (area bc) resist normally, the four
// others tangentially:          K_x = 2·kn·bc + 2·ks·(ab + ac).
// Rotation θ about z moves r by θ(−y, x, 0):
//   x-faces (x = ±a/2): normal part −y → kn∫y² = kn·c·b³/12, tangential ±a/2
//                        → ks·(a²/4)·bc; two faces.
//   y-faces: likewise with a ↔ b.
//   z-faces: all tangential → ks∫(x²+y²) = ks·ab(a²+b²)/12; two faces.
//   K_θz = kn·c(a³+b³)/6 + ks·abc(a+b)/2 + ks·ab(a²+b²)/6.
// Opposite faces cancel every coupling term (the box is centrally symmetric
// and mirror symmetric), so the 6 × 6 stiffness is diagonal in the principal
// frame and ω_b² = max(K_i/m, K_θi/I_i). For a cube of side L:
//   K = (2kn + 4ks)L², K_θ = (kn + 4ks)L⁴/3, m = ρL³, I = ρL⁵/6,
//   ω_t² = (2kn + 4ks)/(ρL) < ω_r² = 2(kn + 4ks)/(ρL): rotation governs.
// Two free blocks on one joint: ω = √2·ω_b. With ξ = βω/2 the step is
// (2/ω)(√(1+ξ²) − ξ) times the safety factor.
//
// Tolerance 1e-12 relative: the code sums exact quadratures of the same
// polynomials, so only round-off separates the two.
#include "integrators/critical_time_step.hpp"

#include "integrators/simulation.hpp"
#include "io/deck.hpp"
#include "tests/support/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace polydem {
namespace {

double box_omega_b(double a, double b, double c, double rho, double kn, double ks) {
  const double m = rho * a * b * c;
  const double Kx = 2 * kn * b * c + 2 * ks * (a * b + a * c);
  const double Ky = 2 * kn * a * c + 2 * ks * (b * c + a * b);
  const double Kz = 2 * kn * a * b + 2 * ks * (b * c + a * c);
  // Rotation about the axis of length `h` with in-plane lengths p, q.
  auto Krot = [&](double h, double p, double q) {
    return kn * h * (p * p * p + q * q * q) / 6 + ks * a * b * c * (p + q) / 2 + ks * p * q * (p * p + q * q) / 6;
  };
  const double Ix = m * (b * b + c * c) / 12, Iy = m * (a * a + c * c) / 12, Iz = m * (a * a + b * b) / 12;
  const double w2 = std::max({Kx / m, Ky / m, Kz / m, Krot(a, b, c) / Ix, Krot(b, a, c) / Iy, Krot(c, a, b) / Iz});
  return std::sqrt(w2);
}

Blocks one_box(Vec3 size, double rho, Vec3 centre = Vec3::Zero(), BlockMotion motion = BlockMotion::free) {
  BlockSpec s;
  s.name = "b";
  s.density = rho;
  s.motion = motion;
  s.shape = make_box(size, centre);
  return build_blocks({s});
}

TEST(CriticalTimeStep, UnitCubeMatchesTheHandFormula) {
  JointSpec joint;
  joint.normal_stiffness = 98e9;
  joint.shear_stiffness = 39.2e9;
  joint.damping = 0.0;
  const double L = 1.0, rho = 2600.0;
  const Blocks b = one_box(Vec3(L, L, L), rho);
  const CriticalStep cs = critical_time_step(b, make_joint_law(joint), 0.8);
  const double kn = joint.normal_stiffness, ks = joint.shear_stiffness;
  // Translational: K = kn·2L² + ks·4L² per axis, m = ρL³.
  const double w_t2 = (2 * kn + 4 * ks) * L * L / (rho * L * L * L);
  // Rotational: K_θ = (kn + 4ks)L⁴/3, I = ρL⁵/6.
  const double w_r2 = (kn + 4 * ks) * L * L * L * L / 3 / (rho * L * L * L * L * L / 6);
  ASSERT_GT(w_r2, w_t2);
  const double omega = std::sqrt(2.0 * w_r2);
  EXPECT_NEAR(cs.omega_max, omega, 1e-12 * omega);
  EXPECT_NEAR(cs.omega_max, std::sqrt(2.0) * box_omega_b(L, L, L, rho, kn, ks), 1e-12 * omega);
  EXPECT_EQ(cs.governing_block, 0);
  EXPECT_EQ(cs.damping_ratio, 0.0);
  EXPECT_NEAR(cs.critical, 2.0 / omega, 1e-12 * cs.critical);  // undamped: 2/ω
  EXPECT_NEAR(cs.chosen, 0.8 * 2.0 / omega, 1e-12 * cs.critical);
}

TEST(CriticalTimeStep, UnequalBoxMatchesTheHandFormula) {
  JointSpec joint;
  joint.normal_stiffness = 5e9;
  joint.shear_stiffness = 4e9;  // stiff in shear: a different mode may govern
  joint.damping = 0.0;
  for (const Vec3& size : {Vec3(1, 2, 3), Vec3(3, 0.5, 1), Vec3(0.2, 0.2, 2)}) {
    const Blocks b = one_box(size, 2000.0, Vec3(5, -2, 1));
    const CriticalStep cs = critical_time_step(b, make_joint_law(joint), 1.0);
    const double omega = std::sqrt(2.0) * box_omega_b(size.x(), size.y(), size.z(), 2000.0, joint.normal_stiffness,
                                                      joint.shear_stiffness);
    EXPECT_NEAR(cs.omega_max, omega, 1e-12 * omega) << size.transpose();
    EXPECT_NEAR(cs.chosen, 2.0 / omega, 1e-12 / omega) << size.transpose();
  }
}

TEST(CriticalTimeStep, DampingCorrection) {
  JointSpec joint;
  joint.normal_stiffness = 98e9;
  joint.shear_stiffness = 39.2e9;
  joint.damping = 2.1e-5;
  const double rho = 2600.0, L = 0.5;
  const Blocks b = one_box(Vec3(L, L, L), rho);
  const CriticalStep cs = critical_time_step(b, make_joint_law(joint), 0.7);
  const double omega = std::sqrt(2.0 * 2.0 * (joint.normal_stiffness + 4 * joint.shear_stiffness) / (rho * L));
  const double xi = joint.damping * omega / 2.0;
  EXPECT_NEAR(cs.omega_max, omega, 1e-12 * omega);
  EXPECT_NEAR(cs.damping_ratio, xi, 1e-12 * xi);
  const double dt = (2.0 / omega) * (std::sqrt(1.0 + xi * xi) - xi);
  EXPECT_NEAR(cs.critical, dt, 1e-12 * dt);
  EXPECT_NEAR(cs.chosen, 0.7 * dt, 1e-12 * dt);
  // Damping shortens the step.
  EXPECT_LT(cs.critical, 2.0 / omega);
  // The step gives back the frequency it was chosen for (with and without β).
  EXPECT_NEAR(highest_frequency_for_step(cs.chosen, joint.damping, 0.7), omega, 1e-12 * omega);
  joint.damping = 0;
  EXPECT_NEAR(highest_frequency_for_step(critical_step_for(omega, joint.damping, 0.7).chosen, joint.damping, 0.7), omega, 1e-12 * omega);
}

TEST(CriticalTimeStep, SmallestFreeBlockGovernsAndFixedBlocksDoNot) {
  JointSpec joint;
  joint.damping = 0.0;
  BlockSpec big, small, tiny_fixed;
  big.name = "big";
  big.shape = make_box(Vec3(1, 1, 1));
  small.name = "small";
  small.shape = make_box(Vec3(0.5, 0.5, 0.5), Vec3(3, 0, 0));
  tiny_fixed.name = "tiny";
  tiny_fixed.shape = make_box(Vec3(0.1, 0.1, 0.1), Vec3(-3, 0, 0));
  tiny_fixed.motion = BlockMotion::fixed;
  const Blocks b = build_blocks({big, small, tiny_fixed});
  const CriticalStep cs = critical_time_step(b, make_joint_law(joint), 1.0);
  EXPECT_EQ(cs.governing_block, 1);
  // ω ∝ 1/√L for a cube: the half-size cube is √2 faster.
  const Blocks big_only = one_box(Vec3(1, 1, 1), 2600.0);
  EXPECT_NEAR(cs.omega_max, std::sqrt(2.0) * critical_time_step(big_only, make_joint_law(joint), 1.0).omega_max, 1e-9 * cs.omega_max);
  // No free block: no step to choose.
  const Blocks fixed_only = one_box(Vec3(1, 1, 1), 2600.0, Vec3::Zero(), BlockMotion::fixed);
  const CriticalStep none = critical_time_step(fixed_only, make_joint_law(joint), 1.0);
  EXPECT_EQ(none.omega_max, 0.0);
  EXPECT_EQ(none.chosen, 0.0);
  EXPECT_EQ(none.governing_block, -1);
}

// A detection asks only whether its joints need a step below the run's
// (`below`); blocks whose Gershgorin bound allows it skip their eigenvalues.
// On the spire's 401 free blocks and their joints: when the answer is yes
// the estimate is bit for bit the full one; when no, it says so.
TEST(CriticalTimeStep, ASkippedBlockNeverChangesTheAnswerOnTheSpire) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  Simulation sim = one_law_simulation(build_blocks(spec.blocks), spec.simulation, spec.joint, GroundMotion{}, 0.005, 1e-6);
  const JointLaws& laws = sim.joint_laws();
  const CriticalStep full = critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, spec.joint.damping, 0.8);
  ASSERT_GT(full.chosen, 0.0);
  for (const double f : {1.0 + 1e-12, 1.01, 1.5, 10.0}) {  // some block needs a step below `below`
    const CriticalStep c =
        critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, spec.joint.damping, 0.8, f * full.chosen);
    EXPECT_EQ(c.chosen, full.chosen) << f;
    EXPECT_EQ(c.omega_max, full.omega_max) << f;
    EXPECT_EQ(c.governing_block, full.governing_block) << f;
  }
  for (const double f : {1.0, 0.99, 0.5}) {  // none does
    const CriticalStep c =
        critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, spec.joint.damping, 0.8, f * full.chosen);
    EXPECT_TRUE(c.chosen == 0.0 || c.chosen >= f * full.chosen) << f << " " << c.chosen;
  }
  // Per block: the bound is above the frequency (every block's own step
  // asked: none may be skipped when it is the one that governs).
  const std::vector<double> w = block_frequencies_from_contacts(sim.blocks(), sim.contacts(), laws);
  int checked = 0;
  for (int i : sim.blocks().free_blocks) {
    if (!(w[i] > 0)) continue;
    JointSpec joint = spec.joint;
    // The block alone: a scene whose stiffest block is i answers "yes" for
    // a `below` just above i's own step.
    const double own = 0.8 * (2.0 / (std::sqrt(2.0) * w[i])) *
                       (std::sqrt(1 + std::pow(0.5 * joint.damping * std::sqrt(2.0) * w[i], 2)) -
                        0.5 * joint.damping * std::sqrt(2.0) * w[i]);
    const CriticalStep c =
        critical_time_step_from_contacts(sim.blocks(), sim.contacts(), laws, spec.joint.damping, 0.8, own * (1 + 1e-9));
    EXPECT_GE(c.omega_max, std::sqrt(2.0) * w[i] * (1 - 1e-12)) << sim.blocks().props.name[i];
    ++checked;
  }
  EXPECT_GT(checked, 390);
}

}  // namespace
}  // namespace polydem
