#include "apps/assessment.hpp"

#include <cmath>
#include <numbers>

namespace polydem {

AssessmentMonitor::AssessmentMonitor(const AssessmentSpec& spec, const Simulation& sim) : spec_(spec) {
  const Blocks& b = sim.blocks();
  direction_ = sim.ground_motion().active() ? sim.ground_motion().direction : Vec3(1, 0, 0);
  start_ = b.state.position;
  if (!b.kinematic_blocks.empty()) {
    reference_ = b.kinematic_blocks.front();
    reference_start_ = b.state.position[reference_];
  }
  if (!spec.monitor_block.empty()) monitor_ = b.find(spec.monitor_block);
  if (monitor_ < 0) {
    double top = -std::numeric_limits<double>::infinity();
    for (int i : b.free_blocks)
      if (b.state.position[i].z() > top) {
        top = b.state.position[i].z();
        monitor_ = i;
      }
  }
  if (monitor_ >= 0) result_.monitor_block = b.props.name[monitor_];
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
  if (result_.max_displacement > spec_.collapse_displacement) {
    collapsed_ = true;
    result_.collapse_time = sim.time();
    result_.collapse_mode = reversed_ ? "I" : "II";
    record_crack(sim);
  }
}

void AssessmentMonitor::record_crack(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  result_.moved_blocks.clear();
  // Lowest moved block per sector of 45° around the vertical axis.
  constexpr int kSectors = 8;
  double low_z[kSectors], along[kSectors];
  for (int k = 0; k < kSectors; ++k) low_z[k] = std::numeric_limits<double>::infinity();
  Vec3 centre = Vec3::Zero();
  for (int i = 0; i < b.count; ++i) centre += start_[i];
  centre /= std::max(1, b.count);
  for (int i : b.free_blocks) {
    if (displacement(sim, i).norm() <= spec_.damage_displacement) continue;
    result_.moved_blocks.push_back(b.props.name[i]);
    const Vec3 r = start_[i] - centre;
    const double angle = std::atan2(r.y(), r.x());
    const int k = std::clamp(static_cast<int>(std::floor((angle + std::numbers::pi) / (2 * std::numbers::pi) * kSectors)), 0,
                             kSectors - 1);
    if (start_[i].z() < low_z[k]) {
      low_z[k] = start_[i].z();
      along[k] = r.dot(direction_);
    }
  }
  // Least-squares line z = a + slope·s through the sectors' lowest points.
  double n = 0, ss = 0, sz = 0, sss = 0, ssz = 0;
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  for (int k = 0; k < kSectors; ++k) {
    if (!std::isfinite(low_z[k])) continue;
    n += 1;
    ss += along[k];
    sz += low_z[k];
    sss += along[k] * along[k];
    ssz += along[k] * low_z[k];
    zmin = std::min(zmin, low_z[k]);
    zmax = std::max(zmax, low_z[k]);
  }
  if (n >= 2 && n * sss - ss * ss > 1e-12) {
    const double slope = (n * ssz - ss * sz) / (n * sss - ss * ss);
    result_.crack_angle_deg = std::atan(std::abs(slope)) * 180.0 / std::numbers::pi;
    result_.crack_low_z = zmin;
    result_.crack_high_z = zmax;
  }
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
  if (!collapsed_ && result_.max_displacement > spec_.collapse_displacement) {
    collapsed_ = true;
    result_.collapse_time = sim.time();
    result_.collapse_mode = reversed_ ? "I" : "II";
  }
  if (collapsed_) {
    result_.status = "collapsed";
    if (result_.moved_blocks.empty()) record_crack(sim);
  } else if (result_.max_residual_displacement > spec_.damage_displacement) {
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
  w.put(a.moved_blocks);
  for (double x : {a.crack_angle_deg, a.crack_low_z, a.crack_high_z}) w.put(x);
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
  r.get(a.moved_blocks);
  for (double* x : {&a.crack_angle_deg, &a.crack_low_z, &a.crack_high_z}) r.get(*x);
}

}  // namespace polydem
