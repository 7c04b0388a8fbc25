// The recorder: what a run writes down as it goes, at the deck's
// output.history_interval.
//
//   histories  one row per record time: the deck's block channels (position,
//              velocity, rotation, angular velocity, contact force; x y z),
//              the walking openings and the ground acceleration
//   energies   the energy ledger (kinetic, gravitational, strain, slip,
//              damping, load work, balance) and the balance error: the
//              largest drift of the balance from its first value over the
//              largest energy in play
//   walking    the largest opening of bed joints (normal within 45° of "up")
//              and of vertical joints, over the run and at the end; and per
//              course (run/joint_mesh.hpp) the mean and the largest opening
//              of its bed and vertical joints at the end, and the largest
//              during the run
//
// Walking is measured from the blocks' motion, not from the contacts the
// search happens to hold: on the joints of the initial mesh
// (run/joint_mesh.hpp).
//
// Records are taken at the force time (time() − dt()), where the leapfrog's
// velocities and forces belong together. Plain data: run_scene writes its
// fields into checkpoints in a fixed order.
#pragma once

#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"
#include "run/joint_mesh.hpp"
#include "run/walking.hpp"

#include <string>
#include <vector>

namespace polydem {

// A table of histories: one row per record time, columns named with units.
struct HistoryTable {
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::vector<double> rows;  // row-major
  std::size_t row_count() const { return columns.empty() ? 0 : rows.size() / columns.size(); }
};

// One recorded quantity of one block.
// One history channel: a block's quantity, or a group's ("group:NAME.QUANTITY":
// `members` its blocks, `mass` their mass). A group's position is its
// mass-weighted centroid, its velocity the mass-weighted mean (momentum over
// mass), its contact_force the sum over its blocks (the joints inside the
// group cancel: what the rest of the structure puts on it, e.g. a base shear).
struct Channel {
  int block;
  std::string quantity;
  std::vector<int> members;  // a group's blocks (block = -1)
  double mass = 0;
};

struct Recorder {
  // Sets up the columns the deck asks for and reserves the rows.
  Recorder(const SceneSpec& spec, const Simulation& sim);

  // One row of histories and energies at the force time.
  void record(const Simulation& sim);
  // The walking openings at the end of the run.
  void finish_walking(const Simulation& sim);
  // The largest |numerical| energy so far over the energy put in.
  double balance_error() const { return reference > 0 ? worst / reference : 0.0; }
  // After a restart has refilled the rows: room for the rest of the run.
  void reserve_rows();

  std::vector<Channel> channels;
  bool walking = false, energies_on = false, ground_channel = false, any_history = false;
  Vec3 up = Vec3(0, 0, 1);
  JointMesh mesh;  // walking only
  std::vector<double> gaps;  // walking only: each joint's opening at the last record
  long expected_rows = 0;
  HistoryTable histories, energies;
  Walking walk;
  // Energy balance tracking.
  EnergyLedger start;                  // the ledger at the first record
  double reference = 0, worst = 0;     // running max of the energy put in, of |numerical| (J)
  bool first_energy = true;
};

}  // namespace polydem
