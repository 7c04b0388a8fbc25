#include "studies/ensemble.hpp"

#include "analytical/probability.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace polydem {

namespace {

double record_step(const std::vector<double>& time) {
  if (time.size() < 2) return 0.0;
  return (time.back() - time.front()) / static_cast<double>(time.size() - 1);
}

bool active(const GroundMotionSpec& g) { return g.kind != GroundMotionKind::none; }

void scale_law(JointSpec& j, const EnsembleDraw& d) {
  j.friction_angle = std::clamp(j.friction_angle + d.friction_angle_shift, 0.0, std::nextafter(90.0, 0.0));
  j.normal_stiffness *= d.normal_stiffness_factor;
  j.shear_stiffness *= d.shear_stiffness_factor;
}

}  // namespace

double motion_sample_step(const SceneSpec& spec) {
  const GroundMotionSpec& g = spec.ground_motion;
  if (g.kind == GroundMotionKind::record) return record_step(g.record_time);
  for (const GroundMotionSpec& c : g.components)
    if (c.kind == GroundMotionKind::record) return record_step(c.record_time);
  return spec.ensemble.sample_step;
}

Perturbation draw_perturbation(const SceneSpec& spec, long replica, std::uint64_t seed) {
  Perturbation p;
  p.velocity.assign(spec.blocks.size(), Vec3::Zero());
  if (replica <= 0) return p;
  const EnsembleSpec& e = spec.ensemble;
  analytical::RandomStream stream(analytical::mix_seed(seed, static_cast<std::uint64_t>(replica)));
  const auto symmetric = [&](double half_width) { return half_width * (2.0 * stream.uniform() - 1.0); };
  p.drawn.friction_angle_shift = symmetric(e.friction_angle);
  p.drawn.normal_stiffness_factor = 1.0 + symmetric(e.stiffness);
  p.drawn.shear_stiffness_factor = 1.0 + symmetric(e.stiffness);
  const double u = stream.uniform();
  bool moving = active(spec.ground_motion);
  for (const GroundMotionSpec& c : spec.ground_motion.components) moving = moving || active(c);
  p.drawn.time_shift = moving ? u * e.time_shift * motion_sample_step(spec) : 0.0;
  for (std::size_t i = 0; i < spec.blocks.size(); ++i) {
    if (spec.blocks[i].motion != BlockMotion::free) continue;
    // A direction uniform on the sphere (z uniform in [−1, 1], the azimuth
    // uniform) and a speed uniform below the bound.
    const double z = 2.0 * stream.uniform() - 1.0;
    const double azimuth = 2.0 * std::numbers::pi * stream.uniform();
    const double speed = e.velocity * stream.uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    p.velocity[i] = speed * Vec3(r * std::cos(azimuth), r * std::sin(azimuth), z);
    p.drawn.largest_initial_speed = std::max(p.drawn.largest_initial_speed, speed);
  }
  return p;
}

void apply_perturbation(SceneSpec& spec, const Perturbation& p) {
  spec.ensemble.drawn = p.drawn;
  scale_law(spec.joint, p.drawn);
  for (JointPairSpec& pair : spec.joint_pairs) scale_law(pair.joint, p.drawn);
  if (p.drawn.time_shift != 0) {
    spec.ground_motion.start_time += p.drawn.time_shift;
    for (GroundMotionSpec& c : spec.ground_motion.components) c.start_time += p.drawn.time_shift;
  }
  for (std::size_t i = 0; i < spec.blocks.size() && i < p.velocity.size(); ++i)
    spec.blocks[i].velocity += p.velocity[i];
}

Distribution distribution(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return std::isnan(x); }), values.end());
  Distribution d;
  d.n = static_cast<long>(values.size());
  if (values.empty()) return d;
  d.p16 = analytical::percentile(values, 0.16);
  d.median = analytical::percentile(values, 0.5);
  d.p84 = analytical::percentile(values, 0.84);
  return d;
}

namespace {

constexpr EnsembleQuantity kQuantities[] = {
    {"ground_acceleration_at_damage_g", [](const PointResult& r) { return r.ground_acceleration_at_damage_g; }},
    {"peak_tip_displacement_m", [](const PointResult& r) { return r.peak_tip_displacement; }},
    {"residual_displacement_m", [](const PointResult& r) { return r.residual_displacement; }},
    {"max_bed_opening_m", [](const PointResult& r) { return r.max_bed_opening; }},
    {"max_vertical_opening_m", [](const PointResult& r) { return r.max_vertical_opening; }},
    {"residual_bed_opening_m", [](const PointResult& r) { return r.residual_bed_opening; }},
    {"residual_vertical_opening_m", [](const PointResult& r) { return r.residual_vertical_opening; }},
};

constexpr CourseQuantity kCourseQuantities[] = {
    {"residual_bed_mean_m", [](const CourseWalking& c) { return c.bed_mean; }},
    {"residual_bed_largest_m", [](const CourseWalking& c) { return c.bed_largest; }},
    {"residual_vertical_mean_m", [](const CourseWalking& c) { return c.vertical_mean; }},
    {"residual_vertical_largest_m", [](const CourseWalking& c) { return c.vertical_largest; }},
    {"max_bed_m", [](const CourseWalking& c) { return c.peak_bed; }},
    {"max_vertical_m", [](const CourseWalking& c) { return c.peak_vertical; }},
};

bool measured(const PointResult& r) { return r.status != "error" && r.status != "unstable"; }

std::vector<CourseDistribution> course_distributions(const std::vector<PointResult>& replicas) {
  std::vector<CourseDistribution> out;
  const PointResult* first = nullptr;
  for (const PointResult& r : replicas)
    if (measured(r) && !r.courses.empty()) {
      first = &r;
      break;
    }
  if (!first) return out;
  const std::size_t n = first->courses.size();
  for (std::size_t k = 0; k < n; ++k) {
    CourseDistribution d;
    d.level = first->courses[k].level;
    d.bed_joints = first->courses[k].bed_joints;
    d.vertical_joints = first->courses[k].vertical_joints;
    for (const CourseQuantity& q : kCourseQuantities) {
      std::vector<double> values;
      for (const PointResult& r : replicas)
        if (measured(r) && r.courses.size() == n) values.push_back(q.of(r.courses[k]));
      d.quantities.push_back(distribution(std::move(values)));
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace

std::span<const EnsembleQuantity> ensemble_quantities() { return kQuantities; }
std::span<const CourseQuantity> course_quantities() { return kCourseQuantities; }

EnsembleOutcome summarise_ensemble(const std::vector<PointResult>& replicas) {
  EnsembleOutcome out;
  out.replicas = static_cast<long>(replicas.size());
  std::map<std::string, long> counts;
  for (const PointResult& r : replicas) {
    ++counts[r.status];
    if (r.collapse_mode == "I") ++out.mode_I;
    if (r.collapse_mode == "II") ++out.mode_II;
  }
  out.status_counts.assign(counts.begin(), counts.end());
  for (const EnsembleQuantity& q : kQuantities) {
    std::vector<double> values;
    for (const PointResult& r : replicas)
      if (measured(r)) values.push_back(q.of(r));
    out.quantities.push_back(distribution(std::move(values)));
  }
  out.courses = course_distributions(replicas);
  return out;
}

}  // namespace polydem
