// The energy ledger: where every joule of a run has gone.
//
// Kinetic energy, the potential of gravity, the strain stored in the
// joints, and the dissipation of slip and of the joints' dashpots, against
// the work the loads (ground motion, point loads, prescribed blocks) have
// done. Their balance is the error of the numerics (docs/robustness.md).
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

#include <vector>

namespace polydem {

struct EnergyLedger {
  double kinetic = 0;        // J, ½·m·v₋·v₊ (the half steps around the force time) and its rotational part
  double gravitational = 0;  // J, −Σ m g·x relative to t = 0
  double strain = 0;         // J, stored in the joints
  double slip = 0;           // J, dissipated by Coulomb slip
  double damping = 0;        // J, dissipated by joint damping
  double dropped_shear = 0;  // J, elastic shear energy detections could not carry over (ContactSet)
  double resampled_normal = 0;  // J, normal strain detections removed (> 0) or added (< 0) at the same pose
  double load_work = 0;      // J, work of the ground motion (body force or base)
  double balance = 0;  // kinetic + gravitational + strain + slip + damping + dropped_shear + resampled_normal − load_work
};

// The energy in play, what a balance error is measured against: every term
// of the ledger, the potential and the load work by magnitude.
inline double energy_in_play(const EnergyLedger& e) {
  return e.kinetic + e.strain + std::abs(e.gravitational) + e.slip + e.damping + e.dropped_shear +
         std::abs(e.resampled_normal) + std::abs(e.load_work);
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
