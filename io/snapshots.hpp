// ParaView output of a run: one .vtu per snapshot for the blocks (id,
// course, displacement, velocity) and one for the joints (the contact
// patches with normal and shear force, opening, slip energy), listed in
// DIR/blocks.pvd and DIR/joints.pvd by finish().
#pragma once

#include "core/byte_stream.hpp"
#include "integrators/simulation.hpp"
#include "io/vtk.hpp"

#include <string>
#include <vector>

namespace polydem {

// The joints as ParaView cells: for each pair with sampled points, the
// polygon of its points and, per cell, its normal force (elastic and
// viscous), shear force, largest opening (minus the overlap where closed)
// and cumulative slip energy. Under the subcontact model the forces are the
// sums over its subcontacts (the shear as the sum of their magnitudes);
// under the overlap model they are the pair's own (contact/pair_joints.hpp:
// the magnitude of its elastic shear force), its subcontacts carrying none.
struct JointCells {
  std::vector<std::vector<Vec3>> polygons;
  std::vector<double> normal_force, shear_force, opening, slip_energy;  // N, N, m, J
};
JointCells joint_cells(const ContactSet& contacts);

class SnapshotWriter {
 public:
  SnapshotWriter(std::string dir, bool joints);

  void write(const Simulation& sim, double time);
  // The .pvd series of what was written so far.
  void finish();

  // Checkpoints: the series so far. A restart continues the numbering and
  // overwrites the snapshots written after the checkpoint.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  std::string dir_;
  bool joints_;
  int count_ = 0;
  std::vector<PvdEntry> blocks_, joints_series_;
};

}  // namespace polydem
