// The energy ledger: where every joule of a run has gone.
//
// Kinetic energy, the potential of gravity, the strain stored in the
// joints, and the dissipation of slip and of the joints' dashpots, against
// the work the loads (ground motion, point loads, prescribed blocks) have
// done: only physical lines. Their balance is constant in exact mechanics;
// what it drifts by is one line of its own, `numerical`, the energy the
// numerics made (> 0) or lost (< 0): the time integration (most of it a
// joint closing or opening within a step, first order in the step) and the
// contact detection re-sampling a joint (the part summary.json's
// numerical_at_detections_J names; docs/results.md). It is reported against the energy
// dissipated (slip plus damping) and the relative balance against the
// energy put in, neither of which a longer run inflates by double counting.
//
// The kinetic energy at the force time t is the leapfrog's own:
// ½·m·v(t − dt/2)·v(t + dt/2), the product of the two half steps around t
// (and ½·ω₋ᵀ·I·ω₊ in rotation, I in the body frame cached at t + dt: a
// second-order difference). With the joint law's dashpot work at the
// centred velocity (contact/joint_law.hpp), this is what makes the ledger an
// exact invariant of the update for linear springs and dashpots: per step,
// m·(v₊ − v₋)·v(t) = dt·F·v(t) books the work of every force at the centred
// velocity, and ½·m·v₋·v₊ + ½·k·x² + mg·x + dissipation is then constant.
// The square of the centred velocity, ½·m·v(t)², would exceed it by
// m·(dt·a)²/8: nothing in a slow motion, but a percent of the energy in play
// in the first steps of an overdamped impact.
#pragma once

#include "contact/joint_law.hpp"
#include "core/blocks.hpp"
#include "core/byte_stream.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace polydem {

struct EnergyLedger {
  double kinetic = 0;        // J, ½·m·v₋·v₊ (the half steps around the force time) and its rotational part
  double gravitational = 0;  // J, −Σ m g·x relative to t = 0
  double strain = 0;         // J, stored in the joints
  double slip = 0;           // J, dissipated by Coulomb slip
  double damping = 0;        // J, dissipated by joint damping
  double load_work = 0;      // J, work of the ground motion (body force or base)
  double balance = 0;        // kinetic + gravitational + strain + slip + damping − load_work
};

// The energy the numerics made (> 0) or lost (< 0) between `start` and `e`:
// the balance's drift.
inline double numerical_energy(const EnergyLedger& e, const EnergyLedger& start) { return e.balance - start.balance; }

// The energy put into the run between `start` and `e`: what the blocks had
// at the start (kinetic and strain), the net work of the loads and the
// potential gravity has released, each when positive. What the relative
// balance divides by (its running maximum).
inline double energy_put_in(const EnergyLedger& e, const EnergyLedger& start) {
  return start.kinetic + start.strain + std::max(0.0, e.load_work - start.load_work) +
         std::max(0.0, start.gravitational - e.gravitational);
}

// Every term by magnitude: the scale of the guard's test of energy growth
// (integrators/guard.hpp).
inline double energy_in_play(const EnergyLedger& e) {
  return e.kinetic + e.strain + std::abs(e.gravitational) + e.slip + e.damping + std::abs(e.load_work);
}

// What the ledger reads of each block besides its state, per block: the
// mean of the two half-step velocities around the last force time (the
// state holds the later one), the pose at that time, and the work the loads
// have done on the block so far (J).
struct LedgerKinematics {
  std::vector<Vec3> velocity_mid, omega_mid, position_prev;
  std::vector<Quat> orientation_prev;
  std::vector<double> load_work;

  // The blocks as they are, without load work: the ledger starts here.
  void start(const BlockState& st);
  void save(ByteWriter& w) const;
  void load(ByteReader& r, std::size_t blocks);
};

// The ledger at the last force time. `rest_work`: the split damping
// scheme's dashpot work booked block by block (J, negative: dissipation;
// empty under the explicit scheme).
EnergyLedger energies(const Blocks& blocks, const LedgerKinematics& k, const JointLaws& laws,
                      const ContactSet& contacts, const std::vector<double>& rest_work, const Vec3& gravity);

}  // namespace polydem
