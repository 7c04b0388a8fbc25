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

// The largest opening of the joints between blocks, split into bed joints
// (normal within 45° of vertical) and vertical joints. A joint's opening is
// the largest gap among its subcontacts (negative when it is closed).
struct Openings {
  double bed = 0, vertical = 0;
  int bed_pair = -1, vertical_pair = -1;
};
Openings joint_openings(const Simulation& sim, const Vec3& up) {
  Openings o;
  const ContactSet& c = sim.contacts();
  const auto& st = sim.blocks().state;
  for (std::size_t q = 0; q < c.pairs.size(); ++q) {
    const ContactPair& p = c.pairs[q];
    if (p.count == 0) continue;
    double gap = -std::numeric_limits<double>::infinity();
    for (int s = p.first; s < p.first + p.count; ++s) gap = std::max(gap, -c.sub.overlap[s]);
    const Vec3 n = st.rotation[p.ref_block] * c.sub.ref_normal_local[p.first];
    const bool bed = std::abs(n.dot(up)) > std::sqrt(0.5);
    double& best = bed ? o.bed : o.vertical;
    int& which = bed ? o.bed_pair : o.vertical_pair;
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
    const int i = sim.blocks().find(h.block);
    if (i < 0) continue;  // the deck reader has checked the names
    channels.push_back({i, h.quantity});
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
    energies.columns = {"time", "kinetic", "gravitational", "strain", "slip", "damping", "load_work", "balance"};
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
      const Openings o = joint_openings(sim, up);
      histories.rows.push_back(o.bed);
      histories.rows.push_back(o.vertical);
      walk.max_bed_opening = std::max(walk.max_bed_opening, o.bed);
      walk.max_vertical_opening = std::max(walk.max_vertical_opening, o.vertical);
    }
    if (ground_channel) histories.rows.push_back(sim.ground_motion().acceleration_at(t));
  }
  if (energies_on) {
    const EnergyLedger e = sim.energies();
    energies.rows.insert(energies.rows.end(),
                         {t, e.kinetic, e.gravitational, e.strain, e.slip, e.damping, e.load_work, e.balance});
    if (first_energy) {
      balance0 = e.balance;
      first_energy = false;
    }
    reference = std::max(reference, e.kinetic + e.strain + std::abs(e.gravitational) + e.slip + e.damping +
                                        std::abs(e.load_work));
    worst = std::max(worst, std::abs(e.balance - balance0));
  }
}

void Recorder::finish_walking(const Simulation& sim) {
  if (!walking) return;
  const Openings o = joint_openings(sim, up);
  auto name = [&](int q) {
    if (q < 0) return std::string();
    const ContactPair& p = sim.contacts().pairs[q];
    return sim.blocks().props.name[p.a] + "|" + sim.blocks().props.name[p.b];
  };
  walk.bed_opening = o.bed;
  walk.vertical_opening = o.vertical;
  walk.bed_joint = name(o.bed_pair);
  walk.vertical_joint = name(o.vertical_pair);
}

}  // namespace polydem
