// The joints of the initial mesh (joint_mesh.hpp).
#include "run/joint_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {

JointMesh JointMesh::from_contacts(const Simulation& sim, const Vec3& up, double tolerance) {
  JointMesh m;
  const ContactSet& c = sim.contacts();
  const auto& st = sim.blocks().state;
  for (const ContactPair& p : c.pairs) {
    if (p.count == 0) continue;
    bool touching = false;
    for (int s = p.first; s < p.first + p.count; ++s) touching = touching || c.sub.geometric_overlap(s) >= -tolerance;
    if (!touching) continue;  // a gap within the contact margin is not a joint
    InitialJoint j;
    j.a = p.a;
    j.b = p.b;
    j.ref = p.ref_block;
    j.inc = p.ref_block == p.a ? p.b : p.a;
    j.normal_local = c.sub.ref_normal_local[p.first];
    // The geometric plane: a pair's crush (the same for all its subcontacts)
    // moved the spring's zero, not the face.
    j.offset_local = c.sub.ref_offset_local[p.first] + c.sub.crush[p.first];
    j.bed = std::abs((st.rotation[j.ref] * j.normal_local).dot(up)) > std::sqrt(0.5);
    j.first = static_cast<int>(m.corners.size());
    for (int s = p.first; s < p.first + p.count; ++s) m.corners.push_back(c.sub.inc_point_local[s]);
    j.count = p.count;
    m.joints.push_back(j);
  }
  m.assign_courses(sim, up);
  return m;
}

void JointMesh::assign_courses(const Simulation& sim, const Vec3& up) {
  course_levels.clear();
  if (joints.empty()) return;
  const double level_cosine = std::cos(10.0 * M_PI / 180.0);
  const auto& st = sim.blocks().state;
  std::vector<double> height(joints.size()), bed_heights;
  for (std::size_t q = 0; q < joints.size(); ++q) {
    const InitialJoint& j = joints[q];
    height[q] = centre(sim, j).dot(up);
    if (std::abs((st.rotation[j.ref] * j.normal_local).dot(up)) >= level_cosine) bed_heights.push_back(height[q]);
  }
  const auto [lo, hi] = std::minmax_element(height.begin(), height.end());
  const double tolerance = 1e-3 * (*hi - *lo);
  // A level: level bed joints whose heights follow each other within the
  // tolerance; its height, the lowest of them.
  std::sort(bed_heights.begin(), bed_heights.end());
  for (std::size_t k = 0; k < bed_heights.size(); ++k)
    if (k == 0 || bed_heights[k] > bed_heights[k - 1] + tolerance) course_levels.push_back(bed_heights[k]);
  if (course_levels.empty()) course_levels.push_back(*lo);  // no bed joint: one course
  for (std::size_t q = 0; q < joints.size(); ++q) {
    // The last level starting at or below the joint (its own level for a
    // level bed joint, whose height is at most its level's top).
    const auto above = std::upper_bound(course_levels.begin(), course_levels.end(), height[q]);
    joints[q].course = std::max(0, static_cast<int>(above - course_levels.begin()) - 1);
  }
}

double JointMesh::opening(const Simulation& sim, const InitialJoint& j) const {
  const Mat3 Rr = sim.orientation_at_force_time(j.ref).toRotationMatrix();
  const Mat3 Rc = sim.orientation_at_force_time(j.inc).toRotationMatrix();
  const Vec3 xr = sim.position_at_force_time(j.ref);
  const Vec3 xc = sim.position_at_force_time(j.inc);
  const Vec3 n = Rr * j.normal_local;
  double gap = -std::numeric_limits<double>::infinity();
  for (int k = j.first; k < j.first + j.count; ++k) gap = std::max(gap, n.dot(xc + Rc * corners[k] - xr) - j.offset_local);
  return gap;
}

Vec3 JointMesh::centre(const Simulation& sim, const InitialJoint& j) const {
  const Mat3 Rc = sim.orientation_at_force_time(j.inc).toRotationMatrix();
  const Vec3 xc = sim.position_at_force_time(j.inc);
  Vec3 sum = Vec3::Zero();
  for (int k = j.first; k < j.first + j.count; ++k) sum += Rc * corners[k];
  return xc + sum / j.count;
}

}  // namespace polydem
