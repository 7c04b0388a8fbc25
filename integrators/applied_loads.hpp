// Point loads, prescribed motions and the kinematic base during a run.
//
// core/loads.hpp says what a [[load]] and a [[prescribe]] are; this is
// their state in the step. Point loads are evaluated once per step, before
// the threads (several loads on one block sum in the deck's order), and
// added to their blocks' force and torque as the sum's last term; the
// ledger books their work over each step by the trapezoid. Kinematic blocks
// (the base under a kinematic ground motion, and prescribed blocks) move
// after the free blocks, with their velocity at the half step; the work
// they do through their joints is the ledger's load work. A scene with
// neither sizes nothing here, and the step touches none of it.
#pragma once

#include "core/blocks.hpp"
#include "core/byte_stream.hpp"
#include "core/ground_motion.hpp"
#include "core/loads.hpp"
#include "integrators/energy_ledger.hpp"

#include <vector>

namespace polydem {

struct AppliedLoads {
  BlockLoads spec;
  std::vector<char> loaded;                   // per block: some point load acts on it (empty: no loads)
  std::vector<Vec3> force, torque;            // per loaded block, at the step's time
  std::vector<Vec3> force_prev, torque_prev;  // ... at the step before (the ledger's trapezoid)
  std::vector<int> prescription_of;           // per block: index into spec.prescribed, −1 (empty: none)
  struct History {
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();  // a prescribed block's joints at the step before
  };
  std::vector<History> prescribed_history;  // per prescription

  bool on(int i) const { return !loaded.empty() && loaded[i]; }
  // Checkpoints: the step-before records (nothing for a scene without them).
  void save(ByteWriter& w) const;
  void load(ByteReader& r, std::size_t blocks);
};

// The loads of `spec` on `blocks`; prescribed blocks take their velocities
// at t = 0. Throws std::invalid_argument when a prescribed block is not
// kinematic.
AppliedLoads make_applied_loads(BlockLoads spec, Blocks& blocks);

// The point loads at time t.
void evaluate_point_loads(AppliedLoads& loads, const BlockState& state, double t);

// The step's clock as the stages read it: the step runs from `time` to
// time + dt; dt_prev is the step before; `steps` counts the steps run.
struct StepClock {
  double time = 0;
  double dt = 0;
  double dt_prev = 0;
  long steps = 0;
};

// Kinematic block i's velocity and angular velocity over the step ahead
// (t to t + dt): its prescription's, the ground's, or held (and held still
// in the static stage).
void kinematic_velocity_next(const Blocks& blocks, const AppliedLoads& loads, const GroundMotion& motion,
                             const StepClock& clock, bool static_stage, int i, Vec3& v, Vec3& w);

// Moves the kinematic blocks over the step, booking the work they do through
// their joints into the ledger.
void move_kinematic_blocks(Blocks& blocks, AppliedLoads& loads, const GroundMotion& motion, const StepClock& clock,
                           bool static_stage, LedgerKinematics& ledger);

}  // namespace polydem
