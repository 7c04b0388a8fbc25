// The static stage: bring a scene to equilibrium under gravity before the
// dynamic stage, as 3DEC's `model solve` ([equilibrium] in a deck).
//
// Why: gravity applied in full at t = 0 strikes the joints with twice the
// static load; with little damping they unload to zero force every period
// and a block on a frictional slope ratchets down it (a 1 m cube on a 40°
// slope, φ = 50°, kn = ks = 1e7 Pa/m, no damping: metres, then it tumbles;
// at equilibrium it has moved 4 mm). An earthquake must start from the
// state the weight alone produces.
//
// How: the ordinary explicit step (integrators/simulation.hpp) with
// Cundall's local damping on every free block, F − α|F|sign(v) for each
// component of the force and of the moment (α = equilibrium.local_damping,
// 0.8 as in 3DEC), no ground motion, gravity in full. The joints keep their
// own law and their stiffness-proportional damping: it is part of the
// joint, the step was chosen for it, and at rest it vanishes, so it cannot
// change the equilibrium found (nor can local damping).
//
// When: after every step the unbalanced-force ratio
//     R = max over free blocks i of max(|F_i|, |M_i| / r_i)  /  mean over free blocks of m_i·|g|
// where F_i = m_i·g + Σ joint forces is block i's out-of-balance force, M_i
// the out-of-balance moment about its centroid (joint moments), r_i its
// bounding radius (a moment counts as the force that would make it at the
// block's edge) and m_i·|g| its weight, the only applied load of the stage.
// This is 3DEC's maximum unbalanced-force ratio, moments included so that a
// block still rocking is not taken for one at rest. The stage stops when
// R ≤ equilibrium.ratio on two steps in a row (a block swinging through its
// place has a zero net force for a step at its fastest, its dashpots then
// balancing its springs' error: the next step's force is far from zero);
// equilibrium.max_steps steps without that is a SceneError naming
// equilibrium.max_steps.
//
// Then: Simulation::end_static_stage(): t = 0, every block at rest, the
// equilibrium state is the reference of displacements, rotations and
// energies; the joints keep their forces.
#pragma once

#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"

#include <string>

namespace polydem {

struct EquilibriumReport {
  bool ran = false;
  long steps = 0;
  double ratio = 0;             // R at the end
  double wall_seconds = 0;
  double max_displacement = 0;  // m, largest centroid displacement of a free block during the stage
  std::string max_displacement_block;
};

// R for the state the last step's forces were evaluated on (see above); 0
// when there is no free block or no gravity.
double unbalanced_force_ratio(const Simulation& sim, const Vec3& gravity);

// The block that sets R: the free block with the largest unbalanced force or
// moment over its radius (`moment` says which), that value (N) and R.
struct Unbalance {
  int block = -1;
  double value = 0;
  bool moment = false;
  double ratio = 0;
};
Unbalance largest_unbalance(const Simulation& sim, const Vec3& gravity);

// Runs the stage on `sim` (freshly set up) and starts the dynamic stage.
// Throws SceneError ("equilibrium.max_steps") when R stays above the
// tolerance for max_steps steps.
EquilibriumReport solve_equilibrium(const EquilibriumSpec& spec, const Vec3& gravity, Simulation& sim);

}  // namespace polydem
