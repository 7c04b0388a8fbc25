// How conservative the automatic step is: the free blocks' highest natural
// frequency on their joints, as one system, against the block-by-block bound
// that sets the step (critical_time_step.hpp).
//
// The step of an explicit run is set by the highest frequency ω_max of the
// blocks vibrating on their joints' springs: each subcontact a spring kn·A
// normal and ks·A tangential at its point, between the two blocks' rigid
// motions. Assembled, these springs make the 6N×6N stiffness K of the N free
// blocks; with the mass matrix M, ω_max² is the largest eigenvalue of
// M^-½ K M^-½. With stiffness-proportional damping (C = β·K) every mode keeps
// its shape and has ξ = β·ω/2, so the central-difference limit
// (2/ω)(√(1+ξ²) − ξ), which falls as ω rises, is exactly the limit at ω_max:
// the step of the linear system at this set of joints.
//
// A run does not solve for ω_max: it bounds it block by block. For a joint
// between free blocks with relative displacement x − y at a subcontact,
//   (x − y)ᵀ D (x − y) ≤ (1 + t)·xᵀ D x + (1 + 1/t)·yᵀ D y   for any t > 0
// (the difference is (√t·x − y/√t)ᵀ D (√t·x − y/√t) ≥ 0). With t = 1 at
// every joint, K ⪯ 2·blockdiag(K_b), K_b block b's stiffness on its joints
// with its neighbours held: ω_max ≤ √2·max_b ω_b, the run's bound. Choosing
// t per joint as the ratio of the two blocks' own ω_b² (exact for two point
// masses on one spring) gives a second, tighter bound where light stones sit
// on heavy ones (split_bound). A run takes the same bound with the ratio of
// the blocks' Gershgorin bounds instead when the deck asks for it
// (simulation.time_step_bound = "joint", critical_time_step.hpp); this one,
// with the exact ratios, is the independent reference its tests compare
// with (docs/benchmarks.md, "The spire").
//
// Dense: for verification and the benchmark polydem_step_bound, not for runs
// (N ≤ max_joint_mode_blocks: a 2412-degree eigenproblem takes seconds).
#pragma once

#include "contact/joint_law.hpp"
#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"

#include <vector>

namespace polydem {

inline constexpr int max_joint_mode_blocks = 3000;

struct JointModes {
  double omega_max = 0;          // rad/s, the assembled system's highest frequency
  double split_bound = 0;        // rad/s, the per-joint-weighted bound (header)
  double block_bound = 0;        // rad/s, √2·max ω_b: what the run's step uses
  std::vector<double> omega;     // rad/s, every frequency, ascending (6 per free block)
  std::vector<double> share;     // per block: its part of the top mode's mass-normalised amplitude² (sums to 1)
};

// The free blocks with the subcontacts of `contacts` (each joint's kn and ks
// from `laws`). Throws std::invalid_argument above max_joint_mode_blocks free
// blocks.
JointModes joint_modes(const Blocks& blocks, const ContactSet& contacts, const JointLaws& laws);

}  // namespace polydem
