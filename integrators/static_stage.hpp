// The static stage (run/equilibrium.hpp), as 3DEC's `model solve`.
//
// While it is active the step applies its load in full (gravity by
// default, no rise time) and no ground motion (no body force, kinematic
// blocks stay), and reduces each free block's force and moment by
// Cundall's local damping α (core/loads.hpp locally_damped). The joints
// keep their law, damping included.
//
// Density scaling (3DEC's for static solutions): in the stage the inertia is
// fictitious, only the equilibrium counts, so each free block's mass and
// inertia are lowered by the factor (ω_b / ω_top)² (ω_b its highest
// frequency on all its faces, ω_top the stiffest block's, the one that set
// the step; integrators/critical_time_step.hpp block_frequencies). Every
// block then vibrates at the step's own frequency and local damping takes
// the same few steps per cycle out of a heavy stone as out of the lightest
// one; the step stays stable (no block is above the frequency the step was
// chosen for). Weights stay the real m·g: only the inertia in the update
// changes, so the equilibrium is the same.
#pragma once

#include "contact/joint_law.hpp"
#include "core/blocks.hpp"
#include "core/scene_spec.hpp"

#include <vector>

namespace polydem {

struct StaticStage {
  bool active = false;
  double local_damping = 0;  // α
  Vec3 load = Vec3::Zero();  // the stage's body acceleration, m/s²
  // Density scaling: the stage's inverse mass and principal inertia per
  // block (empty without it).
  std::vector<double> scaled_inv_mass;
  std::vector<Vec3> scaled_inv_inertia;
};

// The stage with local damping α under `load`, with density scaling if
// asked: each block's highest frequency on all its faces or on the joints
// it has now, whichever is higher, brought to the highest of all (the step
// `dt` allows it).
StaticStage start_static_stage(const Blocks& blocks, const ContactSet& contacts, const JointLaws& laws,
                               const JointLaw& step_law, const SimulationSpec& sim, double dt, double local_damping,
                               const Vec3& load, bool density_scaling);

}  // namespace polydem
