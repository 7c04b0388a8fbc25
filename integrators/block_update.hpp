// The blocks' update: each block sums its joint forces (the gather,
// contact/gather.hpp) and moves by central differences.
//
// Leapfrog: x, q at t; v, L (angular momentum) at t − dt/2.
//   v(t+dt/2) = v(t−dt/2) + dt·F(t)/m,  x(t+dt) = x(t) + dt·v(t+dt/2)
//   L(t+dt/2) = L(t−dt/2) + dt·T(t),    q(t+dt) = exp(ω(t+dt/2)·dt)·q(t)
// with ω = R I⁻¹ Rᵀ L evaluated at the half-step orientation (one predictor
// pass), so rotation is second-order accurate with the full inertia tensor.
// With a changing step the velocity update spans the mean of the two steps.
//
// Gather and update are fused in one loop over a thread's blocks, two at a
// time (a block's update needs only its own gathered force), so the step
// needs one barrier less. Free blocks go four at a time through the update
// kernel (block_update_lanes.hpp); blocks under point loads, every block
// while gravity rises, and the static stage's locally damped blocks go one
// at a time (they have load terms the kernel does not).
#pragma once

#include "contact/gather.hpp"
#include "contact/pair_gather.hpp"
#include "core/blocks.hpp"
#include "core/ground_motion.hpp"
#include "integrators/applied_loads.hpp"
#include "integrators/block_update_lanes.hpp"
#include "integrators/dashpot_rest.hpp"
#include "integrators/energy_ledger.hpp"
#include "integrators/static_stage.hpp"

namespace polydem {

// The loads of a step, the same for every block.
struct StepLoads {
  Vec3 gravity;   // g(t) (core/loads.hpp gravity_at), or the static stage's load
  Vec3 a_ground;  // the ground's body acceleration
  bool rising;    // g(t) ≠ g: count m·(g(t) − g) as load work
};

// What one step's update reads and writes.
struct BlockUpdate {
  Blocks& blocks;
  LedgerKinematics& ledger;
  AppliedLoads& loads;
  const StaticStage& stage;
  const GroundMotion& motion;
  const ContactSet& contacts;
  Vec3 gravity;  // the scene's g: the ledger's potential
  StepLoads step;
  StepClock clock;
  gather_lanes::GatherKernels gather;
  block_lanes::AdvanceFour advance_four;
  // The overlap joint model: the joints' wrenches per pair, gathered by pair
  // (contact/pair_gather.hpp) in place of the subcontacts' forces.
  const PairGather* pair_gather = nullptr;
  const std::vector<lanes::PairRest>* pair_wrench = nullptr;
  // Under joint_sampling = "clip": the rest of each pair's gradient
  // (contact/clip_joint.hpp), gathered by pair onto the subcontacts' forces.
  const PairGather* clip_gather = nullptr;
  const std::vector<lanes::PairRest>* clip_rest = nullptr;
};

// Gathers and advances the free blocks [begin, end) (the calling thread's).
// `rest`: the joint law's forces are gathered already (the split scheme's
// prediction); the rest of the dashpots is gathered onto them instead.
void gather_and_advance(BlockUpdate& u, DashpotRest* rest, int begin, int end);

// The split scheme's first half: gathers the joint law's forces on blocks
// [begin, end) and predicts each block's velocities after the step
// (rest.velocity_next, rest.omega_next; kinematic blocks their own).
void gather_and_predict(BlockUpdate& u, DashpotRest& rest, int begin, int end);

// The joint forces of every block, gathered (outside the step: setup).
void gather_all_blocks(const BlockUpdate& u);

}  // namespace polydem
