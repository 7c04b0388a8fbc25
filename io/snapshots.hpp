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
