// The static stage (run/equilibrium.hpp), as 3DEC's `model solve`.
//
// While it is active the step applies its load in full (gravity by
// default, no rise time) and no ground motion (no body force, kinematic
// blocks stay), and reduces each free block's force and moment by
// Cundall's local damping α (core/loads.hpp locally_damped). The joints
// keep their law, damping included.
//
// The stage's inertia: every free block (1 + α) times heavier. Local damping
// F − α|F|·sign(v), per component, adds α|F| to a force that points against
// the velocity. In the fastest mode the step can carry, the sawtooth
// x_n = (−1)ⁿ·a, the velocity v(t − dt/2) = (x_n − x_{n−1})/dt always points
// away from the joints' restoring force: every step the force is
// (1 + α)·(K·x + C·v), as if the joints were (1 + α) times stiffer and their
// dashpots (1 + α) times stronger. The central-difference limit of that
// system is the limit of the real one at frequency √(1 + α)·ω, so the step
// chosen for ω at the safety factor s is stable only while s·√(1 + α) stays
// below 1 (s = 0.8, α = 0.8: 1.07, and blocks whose frequency is close to
// the bound, as in walls of small units and arches, chatter or diverge). A
// mass (1 + α)·M turns (1 + α)·K, (1 + α)·C back into K, C: the limit is the
// real system's again, and the step keeps its safety factor, dashpots
// included. For rotations the same factor bounds each component of the
// damped moment. Only the path to rest slows (about √(1 + α) more steps per
// cycle of the slowest mode); the state reached is the same: weights stay
// the real m·g, and at rest every force balances whatever the inertia.
// Keeping the damping's form (the one of 3DEC, UDEC and PFC, dissipating on
// both halves of a swing) keeps α meaning what it means there.
//
// Density scaling (3DEC's for static solutions): in the stage the inertia is
// fictitious, only the equilibrium counts, so each free block's mass and
// inertia are lowered by the factor (ω_b / ω_top)² (ω_b its highest
// frequency on all its faces, ω_top the stiffest block's, the one that set
// the step; integrators/critical_time_step.hpp block_frequencies), on top of
// the (1 + α) above. Every block then vibrates at the step's own frequency
// over √(1 + α) and local damping takes the same few steps per cycle out of
// a heavy stone as out of the lightest one; the step stays stable (no block
// is above the frequency the step was chosen for, amplified). Weights stay
// the real m·g: only the inertia in the update changes, so the equilibrium
// is the same.
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
  // The stage's inverse mass and principal inertia per block: the real ones
  // over (1 + α), and with density scaling each brought to the step's
  // frequency (above).
  std::vector<double> scaled_inv_mass;
  std::vector<Vec3> scaled_inv_inertia;
};

// The stage with local damping α under `load`, every free block (1 + α)
// times heavier, with density scaling if asked: each block's highest
// frequency on all its faces or on the joints it has now, whichever is
// higher, brought to the highest of all (the step `dt` allows it).
StaticStage start_static_stage(const Blocks& blocks, const ContactSet& contacts, const JointLaws& laws,
                               const JointLaw& step_law, const SimulationSpec& sim, double dt, double local_damping,
                               const Vec3& load, bool density_scaling);

}  // namespace polydem
