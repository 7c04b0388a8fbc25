// The split damping scheme's second pass in the step (split_damping.hpp
// says why and proves the step; contact/joint_law.hpp apply_dashpot_rest
// computes the rest per pair): its per-subcontact, per-pair and per-block
// records. Under the explicit scheme nothing here is sized or touched.
//
// The rest of the dashpots is summed per pair and gathered onto each block's
// joint force over its pairs in a fixed order, a quarter of the entries of a
// gather by subcontact. Its work is booked block by block: the rest force
// and moment times the block's velocities (summed over a joint's two blocks,
// the rest force times the relative velocity at the point), at the centred
// velocity as the law's dashpot work: half with the velocities before the
// update, booked in the step, and half with those after it, booked at the
// next step, when the ledger's kinetic energy has taken that half of the
// impulse.
#pragma once

#include "contact/joint_law.hpp"
#include "contact/pair_gather.hpp"
#include "core/blocks.hpp"
#include "integrators/energy_ledger.hpp"

#include <cstdint>
#include <vector>

namespace polydem {

struct DashpotRest {
  double fraction = 0;                        // θ (0: the explicit scheme, one pass)
  std::vector<std::uint8_t> dashpot_state;    // per subcontact (DashpotState)
  std::vector<lanes::PairRest> pair_rest;     // per pair
  Vec3Array force_sub;                        // per subcontact: the rest force (Simulation::subcontact_force)
  PairGather pairs;                           // each block's pairs
  std::vector<Vec3> velocity_next, omega_next;  // per block: predicted after the step's forces
  std::vector<Vec3> force, torque;              // per block: the gathered rest
  std::vector<double> work;                     // per block, J (the ledger's: −Σ is dissipation)
  std::vector<double> pending;                  // per block, J: the last step's second half

  // θ for the step `dt` under the stiffest law's β (0 without damping); the
  // per-block records sized for `blocks` blocks.
  void set_step(double dt, double beta, double safety_factor, int blocks);
  // The per-subcontact and per-pair records, and each block's pairs, after a
  // detection.
  void size_for(const ContactSet& contacts, int blocks);
  // The rest onto block i's joint force and moment (the law's already there).
  void gather(int i, BlockState& state);
  // Books block i's rest work for the step just taken (its state holds the
  // velocities after it).
  void book_work(int i, const BlockState& state, const LedgerKinematics& ledger, double dt);
};

}  // namespace polydem
