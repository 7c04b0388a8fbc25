#include "run/assessment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace polydem {

AssessmentMonitor::AssessmentMonitor(const AssessmentSpec& spec, const Simulation& sim, const Vec3& gravity,
                                     double joint_tolerance)
    : spec_(spec), up_(gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3(0, 0, 1)),
      crack_(sim, up_, joint_tolerance) {
  const Blocks& b = sim.blocks();
  direction_ = sim.ground_motion().active() ? sim.ground_motion().direction : Vec3(1, 0, 0);
  start_ = b.state.position;
  // The base the displacements are measured from: the first kinematic block
  // that follows the ground motion ([[prescribe]]'s blocks push, they are
  // not the ground).
  for (int i : b.kinematic_blocks) {
    if (sim.is_prescribed(i)) continue;
    reference_ = i;
    reference_start_ = b.state.position[reference_];
    break;
  }
  if (!spec.monitor_block.empty()) monitor_ = b.find(spec.monitor_block);
  const int group = spec.monitor_group.empty() ? -1 : b.find_group(spec.monitor_group);
  if (monitor_ < 0) {
    // The highest free block (of the monitor group, if one is given), "up"
    // being against gravity.
    double top = -std::numeric_limits<double>::infinity();
    for (int i : b.free_blocks)
      if ((group < 0 || b.props.group[i] == group) && b.state.position[i].dot(up_) > top) {
        top = b.state.position[i].dot(up_);
        monitor_ = i;
      }
  }
  if (monitor_ >= 0) result_.monitor_block = b.props.name[monitor_];
  dislodged_.assign(b.count, 0);
  for (int i : b.free_blocks) free_mass_ += b.props.mass[i];
}

// Marks the blocks beyond collapse_displacement; the collapse criterion is
// the mass fraction of those (assessment.collapse_mass_fraction; 0: any one).
bool AssessmentMonitor::track_dislodged(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  for (int i : b.free_blocks) {
    if (dislodged_[i] || !(displacement(sim, i).norm() > spec_.collapse_displacement)) continue;
    dislodged_[i] = 1;
    result_.dislodged_mass += b.props.mass[i];
    if (result_.first_dislodged_time < 0) result_.first_dislodged_time = sim.time();
  }
  result_.dislodged_mass_fraction = free_mass_ > 0 ? result_.dislodged_mass / free_mass_ : 0.0;
  return result_.dislodged_mass > 0 && result_.dislodged_mass_fraction >= spec_.collapse_mass_fraction;
}

void AssessmentMonitor::list_dislodged(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  result_.dislodged_blocks.clear();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i : b.free_blocks) {
    if (!dislodged_[i]) continue;
    result_.dislodged_blocks.push_back(b.props.name[i]);
    lo = std::min(lo, start_[i].dot(up_));
    hi = std::max(hi, start_[i].dot(up_));
  }
  if (!result_.dislodged_blocks.empty()) {
    result_.dislodged_low_z = lo;
    result_.dislodged_high_z = hi;
  }
}

Vec3 AssessmentMonitor::displacement(const Simulation& sim, int i) const {
  Vec3 d = sim.blocks().state.position[i] - start_[i];
  if (reference_ >= 0) d -= sim.blocks().state.position[reference_] - reference_start_;
  return d;
}

void AssessmentMonitor::observe(const Simulation& sim) {
  if (sim.steps() % 16 != 0 || collapsed_) return;
  const Blocks& b = sim.blocks();
  for (int i : b.free_blocks) {
    const double d = displacement(sim, i).norm();
    if (d > result_.max_displacement) {
      result_.max_displacement = d;
      result_.max_displacement_block = b.props.name[i];
    }
  }
  if (monitor_ >= 0) {
    const double u = displacement(sim, monitor_).dot(direction_);
    result_.monitor_peak_displacement = std::max(result_.monitor_peak_displacement, std::abs(u));
    // A sign counts once the tip has moved a fifth of the damage threshold.
    const double small = 0.2 * spec_.damage_displacement;
    const int sign = u > small ? 1 : (u < -small ? -1 : 0);
    if (first_sign_ == 0) first_sign_ = sign;
    else if (sign != 0 && sign != first_sign_) reversed_ = true;
  }
  if (result_.damage_time < 0 && result_.max_displacement > spec_.damage_displacement) {
    result_.damage_time = sim.time();
    result_.ground_acceleration_at_damage = sim.ground_motion().acceleration_at(sim.time());
  }
  if (track_dislodged(sim)) {
    collapsed_ = true;
    result_.collapse_time = sim.time();
    result_.collapse_mode = reversed_ ? "I" : "II";
    record_crack(sim);
  }
}

void AssessmentMonitor::record_crack(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  result_.moved_blocks.clear();
  for (int i : b.free_blocks)
    if (displacement(sim, i).norm() > spec_.damage_displacement) result_.moved_blocks.push_back(b.props.name[i]);
  // The crack: the joints of the initial mesh whose faces have moved apart
  // by more than half the damage displacement (run/crack.hpp).
  const Crack c = crack_.measure(sim, direction_, 0.5 * spec_.damage_displacement);
  result_.opened_joints = c.cracked_joints;
  if (c.cracked_joints < 2) return;
  result_.crack_angle_deg = c.angle_deg;
  result_.crack_low_z = c.low_z;
  result_.crack_high_z = c.high_z;
}

Assessment AssessmentMonitor::finish(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  for (int i : b.free_blocks) {
    const double d = displacement(sim, i).norm();
    result_.max_residual_displacement = std::max(result_.max_residual_displacement, d);
    if (d > result_.max_displacement) {
      result_.max_displacement = d;
      result_.max_displacement_block = b.props.name[i];
    }
  }
  if (!collapsed_ && track_dislodged(sim)) {
    collapsed_ = true;
    result_.collapse_time = sim.time();
    result_.collapse_mode = reversed_ ? "I" : "II";
  }
  list_dislodged(sim);
  if (collapsed_) {
    result_.status = "collapsed";
    if (result_.moved_blocks.empty()) record_crack(sim);
  } else if (result_.max_residual_displacement > spec_.damage_displacement || !result_.dislodged_blocks.empty()) {
    result_.status = "damaged";
    record_crack(sim);
  }
  return result_;
}

void AssessmentMonitor::save(ByteWriter& w) const {
  w.put(collapsed_);
  w.put(static_cast<std::int32_t>(first_sign_));
  w.put(reversed_);
  const Assessment& a = result_;
  w.put(a.status);
  w.put(a.collapse_mode);
  for (double x : {a.collapse_time, a.damage_time, a.ground_acceleration_at_damage, a.max_displacement}) w.put(x);
  w.put(a.max_displacement_block);
  w.put(a.max_residual_displacement);
  w.put(a.monitor_block);
  w.put(a.monitor_peak_displacement);
  w.put(a.moved_blocks);
  w.put(static_cast<std::int32_t>(a.opened_joints));
  for (double x : {a.crack_angle_deg, a.crack_low_z, a.crack_high_z}) w.put(x);
  w.put(dislodged_);
  for (double x : {a.dislodged_mass, a.dislodged_mass_fraction, a.first_dislodged_time}) w.put(x);
}

void AssessmentMonitor::load(ByteReader& r) {
  r.get(collapsed_);
  std::int32_t sign = 0;
  r.get(sign);
  first_sign_ = sign;
  r.get(reversed_);
  Assessment& a = result_;
  r.get(a.status);
  r.get(a.collapse_mode);
  for (double* x : {&a.collapse_time, &a.damage_time, &a.ground_acceleration_at_damage, &a.max_displacement})
    r.get(*x);
  r.get(a.max_displacement_block);
  r.get(a.max_residual_displacement);
  r.get(a.monitor_block);
  r.get(a.monitor_peak_displacement);
  r.get(a.moved_blocks);
  std::int32_t opened = 0;
  r.get(opened);
  a.opened_joints = opened;
  for (double* x : {&a.crack_angle_deg, &a.crack_low_z, &a.crack_high_z}) r.get(*x);
  std::vector<std::uint8_t> dislodged;
  r.get(dislodged);
  if (dislodged.size() != dislodged_.size()) throw StateFormatError("assessment: dislodged flags do not fit the blocks");
  dislodged_ = std::move(dislodged);
  for (double* x : {&a.dislodged_mass, &a.dislodged_mass_fraction, &a.first_dislodged_time}) r.get(*x);
}

}  // namespace polydem
