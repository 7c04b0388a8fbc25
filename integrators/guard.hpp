// The guard: a run that cannot go on stops with a clear error and keeps its
// last good state, instead of carrying NaN or exploding energy to the end.
//
// Every 256 steps the state is checked: a non-finite value, two blocks in
// contact overlapping more than the penetration limit (their penetration
// depth, the least distance that parts them, beyond a fraction, 10 % by
// default, of the smaller block's size, and at least the contact margin:
// blocks passing through each other, not a hard impact, which sinks a joint
// by millimetres), or a mechanical energy that has grown by more than
// energy_growth_limit of the energy in play beyond the work of the loads
// (energy appearing from nowhere: the step is too large) throws
// InstabilityError naming the cause, the step and the time. The state of the
// last passed check is kept.
#pragma once

#include "contact/subcontacts.hpp"
#include "core/blocks.hpp"
#include "core/byte_stream.hpp"
#include "integrators/energy_ledger.hpp"

#include <stdexcept>

namespace polydem {

// The run cannot go on (non-finite state): the message names the step,
// the time and the block.
struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Guard {
  double energy_growth_limit = 0.1;  // of the energy in play
  double penetration_limit = 0.1;    // of the smaller block's size
  // The mechanical energy at the first check, and the largest energy in play since.
  double energy_reference = 0, mechanical0 = 0;
  bool energy_started = false;
  BlockState last_good;
  double last_good_time = 0;
  long last_good_step = 0;

  // A fresh start from `state` at time 0 (the limits kept).
  void restart(const BlockState& state);
  // Checkpoints: everything but the limits.
  void save(ByteWriter& w) const;
  void load(ByteReader& r, std::size_t blocks);
};

// The check at step `step`, time `time`, with the ledger `e` of the state
// now; keeps the state as the last good one, or throws InstabilityError.
void check_health(Guard& g, const Blocks& blocks, const ContactSet& contacts, double margin, const EnergyLedger& e,
                  const Vec3& gravity, long step, double time, double dt);

// The block state's records, bit for bit (checkpoints).
void save_block_state(ByteWriter& w, const BlockState& s);
void load_block_state(ByteReader& r, BlockState& s, std::size_t blocks);

}  // namespace polydem
