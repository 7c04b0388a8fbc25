#include "run/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {

namespace {

Vec3 rotation_vector(const Quat& q) {
  const Eigen::AngleAxisd aa(q);
  double angle = aa.angle();
  if (angle > M_PI) angle -= 2 * M_PI;
  return angle * aa.axis();
}

void append_channel(const Simulation& sim, const Channel& c, std::vector<double>& row) {
  const Blocks& b = sim.blocks();
  if (c.block < 0) {  // a group, in block order
    Vec3 v = Vec3::Zero();
    for (int i : c.members) {
      const double m = b.props.mass[i];
      if (c.quantity == "position") v += m * sim.position_at_force_time(i);
      else if (c.quantity == "velocity") v += m * sim.velocity_at_force_time(i);
      else if (c.quantity == "contact_force") v += b.state.contact_force[i];
    }
    if (c.quantity != "contact_force") v /= c.mass;
    row.insert(row.end(), {v.x(), v.y(), v.z()});
    return;
  }
  const int i = c.block;
  Vec3 v = Vec3::Zero();
  if (c.quantity == "position") v = sim.position_at_force_time(i);
  else if (c.quantity == "velocity") v = sim.velocity_at_force_time(i);
  else if (c.quantity == "angular_velocity") v = sim.angular_velocity_at_force_time(i);
  else if (c.quantity == "rotation")
    v = rotation_vector(sim.orientation_at_force_time(i) * b.initial_orientation[i].conjugate());
  else if (c.quantity == "contact_force") v = b.state.contact_force[i];
  row.insert(row.end(), {v.x(), v.y(), v.z()});
}

const char* unit_of(const std::string& q) {
  if (q == "position") return "m";
  if (q == "velocity") return "m/s";
  if (q == "angular_velocity") return "rad/s";
  if (q == "rotation") return "rad";
  if (q == "contact_force") return "N";
  return "-";
}

// Each joint's opening into `gaps`, and the largest of bed joints and of
// vertical joints (by their normal at t = 0).
struct Openings {
  double bed = 0, vertical = 0;
  int bed_joint = -1, vertical_joint = -1;
};
Openings joint_openings(const Simulation& sim, const JointMesh& mesh, std::vector<double>& gaps) {
  Openings o;
  for (std::size_t q = 0; q < mesh.joints.size(); ++q) {
    const InitialJoint& j = mesh.joints[q];
    const double gap = mesh.opening(sim, j);
    gaps[q] = gap;
    double& best = j.bed ? o.bed : o.vertical;
    int& which = j.bed ? o.bed_joint : o.vertical_joint;
    if (gap > best) {
      best = gap;
      which = static_cast<int>(q);
    }
  }
  return o;
}

}  // namespace

Recorder::Recorder(const SceneSpec& spec, const Simulation& sim) {
  histories.columns.push_back("time");
  histories.units.push_back("s");
  for (const HistorySpec& h : spec.output.histories) {
    if (h.block.rfind(kGroupPrefix, 0) == 0) {
      const int g = sim.blocks().find_group(h.block.substr(kGroupPrefix.size()));
      if (g < 0) continue;  // the deck reader has checked the names
      Channel c{-1, h.quantity, {}, 0.0};
      for (int i = 0; i < sim.blocks().count; ++i) {
        if (sim.blocks().props.group[i] != g) continue;
        c.members.push_back(i);
        c.mass += sim.blocks().props.mass[i];
      }
      channels.push_back(std::move(c));
    } else {
      const int i = sim.blocks().find(h.block);
      if (i < 0) continue;  // the deck reader has checked the names
      channels.push_back({i, h.quantity, {}, 0.0});
    }
    for (const char* axis : {"x", "y", "z"}) {
      histories.columns.push_back(h.block + "." + h.quantity + "." + axis);
      histories.units.push_back(unit_of(h.quantity));
    }
  }
  walking = spec.output.walking;
  energies_on = spec.output.energies;
  up = spec.simulation.gravity.norm() > 0 ? Vec3(-spec.simulation.gravity.normalized()) : Vec3(0, 0, 1);
  ground_channel = sim.ground_motion().active() && (!channels.empty() || walking);
  if (walking) {
    mesh = JointMesh::from_contacts(sim, up, spec.simulation.overlap_tolerance);
    gaps.assign(mesh.joints.size(), 0.0);
    walk.courses.assign(mesh.course_levels.size(), CourseWalking{});
    for (std::size_t k = 0; k < mesh.course_levels.size(); ++k) walk.courses[k].level = mesh.course_levels[k];
    for (const InitialJoint& j : mesh.joints) ++(j.bed ? walk.courses[j.course].bed_joints : walk.courses[j.course].vertical_joints);
    for (const char* c : {"walking.bed_opening", "walking.vertical_opening"}) {
      histories.columns.push_back(c);
      histories.units.push_back("m");
    }
  }
  if (ground_channel) {
    histories.columns.push_back("ground.acceleration");
    histories.units.push_back("m/s^2");
  }
  if (energies_on) {
    energies.columns = {"time", "kinetic", "gravitational", "strain", "slip", "damping", "load_work", "numerical"};
    energies.units = {"s", "J", "J", "J", "J", "J", "J", "J"};
  }
  const double interval = spec.output.history_interval;
  expected_rows = interval > 0 ? static_cast<long>(spec.simulation.end_time / interval) + 2
                               : static_cast<long>(spec.simulation.end_time / sim.dt()) + 2;
  any_history = !channels.empty() || walking;
  reserve_rows();
}

void Recorder::reserve_rows() {
  if (any_history) histories.rows.reserve(expected_rows * histories.columns.size());
  if (energies_on) energies.rows.reserve(expected_rows * energies.columns.size());
}

void Recorder::record(const Simulation& sim) {
  const double t = std::max(0.0, sim.time() - sim.dt());  // force time
  if (any_history) {
    histories.rows.push_back(t);
    for (const Channel& c : channels) append_channel(sim, c, histories.rows);
    if (walking) {
      const Openings o = joint_openings(sim, mesh, gaps);
      histories.rows.push_back(o.bed);
      histories.rows.push_back(o.vertical);
      walk.max_bed_opening = std::max(walk.max_bed_opening, o.bed);
      walk.max_vertical_opening = std::max(walk.max_vertical_opening, o.vertical);
      for (std::size_t q = 0; q < gaps.size(); ++q) {
        const InitialJoint& j = mesh.joints[q];
        double& peak = j.bed ? walk.courses[j.course].peak_bed : walk.courses[j.course].peak_vertical;
        peak = std::max(peak, gaps[q]);
      }
    }
    if (ground_channel) histories.rows.push_back(sim.ground_motion().acceleration_at(t));
  }
  if (energies_on) {
    const EnergyLedger e = sim.energies();
    if (first_energy) {
      start = e;
      first_energy = false;
    }
    const double numerical = numerical_energy(e, start);
    energies.rows.insert(energies.rows.end(),
                         {t, e.kinetic, e.gravitational, e.strain, e.slip, e.damping, e.load_work, numerical});
    reference = std::max(reference, energy_put_in(e, start));
    worst = std::max(worst, std::abs(numerical));
  }
}

void Recorder::finish_walking(const Simulation& sim) {
  if (!walking) return;
  const Openings o = joint_openings(sim, mesh, gaps);
  auto name = [&](int q) {
    if (q < 0) return std::string();
    const InitialJoint& j = mesh.joints[q];
    return sim.blocks().props.name[j.a] + "|" + sim.blocks().props.name[j.b];
  };
  walk.bed_opening = o.bed;
  walk.vertical_opening = o.vertical;
  walk.bed_joint = name(o.bed_joint);
  walk.vertical_joint = name(o.vertical_joint);
  for (CourseWalking& c : walk.courses) c.bed_mean = c.bed_largest = c.vertical_mean = c.vertical_largest = 0;
  for (std::size_t q = 0; q < gaps.size(); ++q) {
    const InitialJoint& j = mesh.joints[q];
    CourseWalking& c = walk.courses[j.course];
    const double open = std::max(0.0, gaps[q]);
    (j.bed ? c.bed_mean : c.vertical_mean) += open;
    double& largest = j.bed ? c.bed_largest : c.vertical_largest;
    largest = std::max(largest, open);
  }
  for (CourseWalking& c : walk.courses) {
    if (c.bed_joints > 0) c.bed_mean /= c.bed_joints;
    if (c.vertical_joints > 0) c.vertical_mean /= c.vertical_joints;
    c.peak_bed = std::max(c.peak_bed, c.bed_largest);  // the records sample the run; the end is one more sample
    c.peak_vertical = std::max(c.peak_vertical, c.vertical_largest);
  }
}

}  // namespace polydem
