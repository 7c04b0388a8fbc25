#include "io/snapshots.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <limits>

namespace polydem {

JointCells joint_cells(const ContactSet& c) {
  JointCells out;
  const bool per_pair = c.pair_joints_in_use();  // the overlap model
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    const ContactPair& p = c.pairs[q];
    if (p.count == 0) continue;
    std::vector<Vec3> poly;
    double n = 0, t = 0, open = -std::numeric_limits<double>::infinity(), e = 0;
    for (int s = p.first; s < p.first + p.count; ++s) {
      poly.push_back(c.sub.point[s]);
      open = std::max(open, -c.sub.geometric_overlap(s));
      if (per_pair) continue;  // the subcontacts carry no force: the pair's below
      n += c.sub.normal_force[s];
      t += c.sub.shear_force[s].norm();
      e += c.sub.slip_energy[s];
    }
    if (per_pair) {
      n = c.joints.normal_force[q];
      t = c.joints.shear[q].norm();
      e = c.joints.slip_energy[q];
    }
    out.polygons.push_back(std::move(poly));
    out.normal_force.push_back(n);
    out.shear_force.push_back(t);
    out.opening.push_back(open);
    out.slip_energy.push_back(e);
  }
  return out;
}

// The folder is made at the first snapshot, not here: a run rejected at
// setup (overlapping blocks, a step above the critical one) leaves nothing.
SnapshotWriter::SnapshotWriter(std::string dir, bool joints) : dir_(std::move(dir)), joints_(joints) {}

void SnapshotWriter::write(const Simulation& sim, double time) {
  std::filesystem::create_directories(dir_);  // one stat when it exists; snapshots are rare
  const Blocks& b = sim.blocks();
  std::vector<Polyhedron> shapes;
  std::vector<int> id, course, group;
  std::vector<Vec3> disp, vel;
  for (int i = 0; i < b.count; ++i) {
    shapes.push_back(world_shape(b, i));
    id.push_back(i);
    course.push_back(b.props.course[i]);
    group.push_back(b.props.group[i]);
    disp.push_back(b.state.position[i] - b.initial_position[i]);
    vel.push_back(b.state.velocity[i]);
  }
  VtkCellData data;
  // group: the index into results.h5's /blocks/group_names (-1: none).
  data.add_ints("block_id", id).add_ints("course", course).add_ints("group", group).add_vectors("displacement", disp).add_vectors("velocity",
                                                                                                         vel);
  const std::string name = fmt::format("blocks_{:05d}.vtu", count_);
  write_vtu(dir_ + "/" + name, shapes, data);
  blocks_.push_back({time, name});
  if (joints_) {
    const JointCells j = joint_cells(sim.contacts());
    VtkCellData jd;
    jd.add_scalars("normal_force", j.normal_force)
        .add_scalars("shear_force", j.shear_force)
        .add_scalars("opening", j.opening)
        .add_scalars("slip_energy", j.slip_energy);
    const std::string jname = fmt::format("joints_{:05d}.vtu", count_);
    write_vtu_polygons(dir_ + "/" + jname, j.polygons, jd);
    joints_series_.push_back({time, jname});
  }
  ++count_;
}

void SnapshotWriter::finish() {
  if (!blocks_.empty()) write_pvd(dir_ + "/blocks.pvd", blocks_);
  if (!joints_series_.empty()) write_pvd(dir_ + "/joints.pvd", joints_series_);
}

void SnapshotWriter::save(ByteWriter& w) const {
  w.put(static_cast<std::int32_t>(count_));
  for (const auto* series : {&blocks_, &joints_series_}) {
    w.put(static_cast<std::uint64_t>(series->size()));
    for (const PvdEntry& e : *series) {
      w.put(e.time);
      w.put(e.file);
    }
  }
}

void SnapshotWriter::load(ByteReader& r) {
  std::int32_t count = 0;
  r.get(count);
  count_ = count;
  for (auto* series : {&blocks_, &joints_series_}) {
    std::uint64_t n = 0;
    r.get(n);
    if (n > r.remaining()) throw StateFormatError("snapshot series: count beyond the data");
    series->resize(static_cast<std::size_t>(n));
    for (PvdEntry& e : *series) {
      r.get(e.time);
      r.get(e.file);
    }
  }
}

}  // namespace polydem
