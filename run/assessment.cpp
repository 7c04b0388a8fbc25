#include "run/assessment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace polydem {

AssessmentMonitor::AssessmentMonitor(const AssessmentSpec& spec, const Simulation& sim, const Vec3& gravity,
                                     double joint_tolerance)
    : spec_(spec), up_(gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3(0, 0, 1)),
      crack_(sim, up_, joint_tolerance), gravity_(gravity) {
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
  for (int i : b.free_blocks) free_mass_ += b.props.mass[i];
  // The bottom of the model as built: a block whose centre drops below it
  // has fallen off the model and no longer bears on the verdict's timing.
  model_bottom_ = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(b.state.position.size()); ++i)
    for (int v = 0; v < static_cast<int>(b.props.local_shape[i].vertices.size()); ++v)
      model_bottom_ = std::min(model_bottom_, world_vertex(b, i, v).dot(up_));
  result_.moving_speed_limit = std::sqrt(2 * gravity_.norm() * 0.1 * spec.damage_displacement);
}

Vec3 AssessmentMonitor::displacement(const Simulation& sim, int i) const {
  Vec3 d = sim.blocks().state.position[i] - start_[i];
  if (reference_ >= 0) d -= sim.blocks().state.position[reference_] - reference_start_;
  return d;
}

// Dropped below its place by more than collapse_displacement: no longer
// carried where it was (a rocking body rises before it falls).
bool AssessmentMonitor::fallen(const Simulation& sim, int i) const {
  return -displacement(sim, i).dot(up_) > spec_.collapse_displacement;
}

// The point of no return of the monitored body (see assessment.hpp): once
// the loads are final, its centre of mass outside the span of the contact
// points it rests on (those below it along the effective gravity, gravity
// less the ground's acceleration), along the motion or across it, and
// moving further out relative to the base. Outside the span along an axis
// is outside the points' convex hull, so the test never claims too much; a
// body with no contact below it is in flight, judged when it lands.
bool AssessmentMonitor::past_no_return(const Simulation& sim) const {
  if (monitor_ < 0 || !(sim.time() >= loads_final_time_)) return false;
  const Vec3 g = gravity_ - sim.ground_motion().acceleration_vector(sim.time());
  if (!(g.norm() > 0)) return false;
  const Vec3 down = g.normalized();
  Vec3 along = direction_ - direction_.dot(down) * down;
  if (!(along.norm() > 1e-9)) along = down.unitOrthogonal();
  along.normalize();
  const Vec3 across = down.cross(along);
  const Blocks& b = sim.blocks();
  const Vec3 c = b.state.position[monitor_];
  Vec3 v = b.state.velocity[monitor_];
  if (reference_ >= 0) v -= b.state.velocity[reference_];
  const ContactSet& cs = sim.contacts();
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  bool supported = false;
  for (const ContactPair& p : cs.pairs) {
    if (p.a != monitor_ && p.b != monitor_) continue;
    for (int k = p.first; k < p.first + p.count; ++k) {
      if (!(cs.sub.geometric_overlap(k) > 0)) continue;
      const Vec3 x = cs.sub.point[k] - c;
      if (!(x.dot(down) > 0)) continue;  // beside or above the centre of mass: not a support
      supported = true;
      const double s[2] = {x.dot(along), x.dot(across)};
      for (int a = 0; a < 2; ++a) {
        lo[a] = std::min(lo[a], s[a]);
        hi[a] = std::max(hi[a], s[a]);
      }
    }
  }
  if (!supported) return false;
  const double u[2] = {v.dot(along), v.dot(across)};
  for (int a = 0; a < 2; ++a)
    if ((hi[a] < 0 && u[a] > 0) || (lo[a] > 0 && u[a] < 0)) return true;  // the centre beyond the edge, going on
  return false;
}

void AssessmentMonitor::mark_collapse(const Simulation& sim, const char* reason) {
  collapsed_ = true;
  result_.collapse_reason = reason;
  if (excursion_since_ >= 0) {
    result_.collapse_time = excursion_since_;
    result_.collapse_mode = excursion_mode_;
  } else {
    result_.collapse_time = sim.time();
    result_.collapse_mode = reversed_ ? "I" : "II";
    record_crack(sim);
  }
}

// One look at the blocks: the peaks, the monitor's reversal, the damage
// time, the dislodged mass now (its excursions past collapse_mass_fraction)
// and whether collapse is certain.
void AssessmentMonitor::sample(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  double dislodged = 0, lost = 0;
  for (int i : b.free_blocks) {
    const Vec3 u = displacement(sim, i);
    const double d = u.norm();
    if (d > result_.peak_displacement) {
      result_.peak_displacement = d;
      result_.peak_displacement_block = b.props.name[i];
    }
    if (d > spec_.collapse_displacement) dislodged += b.props.mass[i];
    if (-u.dot(up_) > spec_.collapse_displacement) lost += b.props.mass[i];
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
  if (result_.damage_time < 0 && result_.peak_displacement > spec_.damage_displacement) {
    result_.damage_time = sim.time();
    result_.ground_acceleration_at_damage = sim.ground_motion().acceleration_at(sim.time());
  }
  if (collapsed_) return;
  const auto reaches = [&](double mass) { return mass > 0 && mass >= spec_.collapse_mass_fraction * free_mass_; };
  if (!reaches(dislodged)) {
    excursion_since_ = -1;
  } else if (excursion_since_ < 0) {
    excursion_since_ = sim.time();
    excursion_mode_ = reversed_ ? "I" : "II";
    record_crack(sim);
  }
  if (reaches(lost)) {
    mark_collapse(sim, "lost mass");
    return;
  }
  // The monitor's point of no return is reported (monitor_past_no_return)
  // but does not decide: its support test fires on a tip that rocks on a
  // course which itself rocks, and the tip then comes back.
}

void AssessmentMonitor::observe(const Simulation& sim) {
  if (sim.steps() % 16 == 0) sample(sim);
}

// The blocks dislodged and fallen at the end, and where they came from.
void AssessmentMonitor::list_lost(const Simulation& sim) {
  const Blocks& b = sim.blocks();
  Assessment& a = result_;
  a.dislodged_blocks.clear();
  a.fallen_blocks.clear();
  a.dislodged_mass = 0;
  double fallen_mass = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i : b.free_blocks) {
    if (!(displacement(sim, i).norm() > spec_.collapse_displacement)) continue;
    a.dislodged_blocks.push_back(b.props.name[i]);
    a.dislodged_mass += b.props.mass[i];
    if (fallen(sim, i)) {
      a.fallen_blocks.push_back(b.props.name[i]);
      fallen_mass += b.props.mass[i];
    }
    lo = std::min(lo, start_[i].dot(up_));
    hi = std::max(hi, start_[i].dot(up_));
  }
  a.dislodged_mass_fraction = free_mass_ > 0 ? a.dislodged_mass / free_mass_ : 0.0;
  a.fallen_mass_fraction = free_mass_ > 0 ? fallen_mass / free_mass_ : 0.0;
  if (!a.dislodged_blocks.empty()) {
    a.dislodged_low_z = lo;
    a.dislodged_high_z = hi;
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
  sample(sim);  // the final state, whatever step it falls on
  Assessment& a = result_;
  Vec3 v_base = reference_ >= 0 ? b.state.velocity[reference_] : Vec3::Zero();
  for (int i : b.free_blocks) {
    a.max_residual_displacement = std::max(a.max_residual_displacement, displacement(sim, i).norm());
    if (displacement(sim, i).dot(up_) + start_[i].dot(up_) < model_bottom_) continue;  // off the model
    const double v = (b.state.velocity[i] - v_base).norm() + b.state.angular_velocity[i].norm() * b.props.radius[i];
    if (v > a.fastest_speed) {
      a.fastest_speed = v;
      a.fastest_block = b.props.name[i];
    }
  }
  if (monitor_ >= 0) {
    a.monitor_residual_displacement = std::abs(displacement(sim, monitor_).dot(direction_));
    a.monitor_past_no_return = past_no_return(sim);
  }
  list_lost(sim);
  if (collapsed_) {
    a.status = "collapsed";
  } else if (a.fastest_speed > a.moving_speed_limit) {
    a.status = "undetermined";
    record_crack(sim);
  } else if (excursion_since_ >= 0) {  // the dislodged mass at the end reaches the fraction
    collapsed_ = true;
    a.status = "collapsed";
    a.collapse_reason = "lost mass";
    a.collapse_time = excursion_since_;
    a.collapse_mode = excursion_mode_;
  } else if (a.max_residual_displacement > spec_.damage_displacement || !a.dislodged_blocks.empty()) {
    a.status = "damaged";
    record_crack(sim);
  }
  return a;
}

void AssessmentMonitor::save(ByteWriter& w) const {
  w.put(collapsed_);
  w.put(static_cast<std::int32_t>(first_sign_));
  w.put(reversed_);
  w.put(excursion_since_);
  w.put(excursion_mode_);
  const Assessment& a = result_;
  w.put(a.status);
  w.put(a.collapse_mode);
  w.put(a.collapse_reason);
  for (double x : {a.collapse_time, a.damage_time, a.ground_acceleration_at_damage, a.peak_displacement}) w.put(x);
  w.put(a.peak_displacement_block);
  w.put(a.monitor_block);
  w.put(a.monitor_peak_displacement);
  w.put(a.moved_blocks);
  w.put(static_cast<std::int32_t>(a.opened_joints));
  for (double x : {a.crack_angle_deg, a.crack_low_z, a.crack_high_z}) w.put(x);
}

void AssessmentMonitor::load(ByteReader& r) {
  r.get(collapsed_);
  std::int32_t sign = 0;
  r.get(sign);
  first_sign_ = sign;
  r.get(reversed_);
  r.get(excursion_since_);
  r.get(excursion_mode_);
  Assessment& a = result_;
  r.get(a.status);
  r.get(a.collapse_mode);
  r.get(a.collapse_reason);
  for (double* x : {&a.collapse_time, &a.damage_time, &a.ground_acceleration_at_damage, &a.peak_displacement})
    r.get(*x);
  r.get(a.peak_displacement_block);
  r.get(a.monitor_block);
  r.get(a.monitor_peak_displacement);
  r.get(a.moved_blocks);
  std::int32_t opened = 0;
  r.get(opened);
  a.opened_joints = opened;
  for (double* x : {&a.crack_angle_deg, &a.crack_low_z, &a.crack_high_z}) r.get(*x);
}

}  // namespace polydem
