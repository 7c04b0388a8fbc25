// The crack on the initial mesh's joints (crack.hpp).
#include "run/crack.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace polydem {

namespace {

// Joint j's corners in its reference block's frame, at the force time.
struct JointPose {
  Mat3 Rr, Rc;
  Vec3 xr, xc;
  JointPose(const Simulation& sim, const InitialJoint& j)
      : Rr(sim.orientation_at_force_time(j.ref).toRotationMatrix()),
        Rc(sim.orientation_at_force_time(j.inc).toRotationMatrix()),
        xr(sim.position_at_force_time(j.ref)),
        xc(sim.position_at_force_time(j.inc)) {}
  Vec3 in_reference(const Vec3& corner) const { return Rr.transpose() * (xc + Rc * corner - xr); }
};

}  // namespace

CrackGauge::CrackGauge(const Simulation& sim, const Vec3& up, double tolerance)
    : mesh_(JointMesh::from_contacts(sim, up, tolerance)), up_(up) {
  start_.reserve(mesh_.corners.size());
  for (const InitialJoint& j : mesh_.joints) {
    const JointPose pose(sim, j);
    for (int k = j.first; k < j.first + j.count; ++k)
      start_.push_back(pose.in_reference(mesh_.corners[static_cast<std::size_t>(k)]));
    centre_.push_back(mesh_.centre(sim, j));
  }
}

double CrackGauge::separation(const Simulation& sim, std::size_t q) const {
  const InitialJoint& j = mesh_.joints[q];
  const JointPose pose(sim, j);
  double worst = 0;
  for (int k = j.first; k < j.first + j.count; ++k) {
    const auto c = static_cast<std::size_t>(k);
    worst = std::max(worst, (pose.in_reference(mesh_.corners[c]) - start_[c]).norm());
  }
  return worst;
}

Crack CrackGauge::measure(const Simulation& sim, const Vec3& direction, double opening) const {
  Crack c;
  double n = 0, ms = 0, mz = 0;
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  std::vector<std::pair<double, double>> pts;
  for (std::size_t q = 0; q < mesh_.joints.size(); ++q) {
    if (!(separation(sim, q) > opening)) continue;
    const double sx = centre_[q].dot(direction), z = centre_[q].dot(up_);
    pts.emplace_back(sx, z);
    n += 1;
    ms += sx;
    mz += z;
    zmin = std::min(zmin, z);
    zmax = std::max(zmax, z);
  }
  c.cracked_joints = static_cast<int>(pts.size());
  if (pts.empty()) return c;
  c.low_z = zmin;
  c.high_z = zmax;
  if (pts.size() < 2) return c;
  ms /= n;
  mz /= n;
  double css = 0, csz = 0, czz = 0;
  for (const auto& [sx, z] : pts) {
    css += (sx - ms) * (sx - ms);
    csz += (sx - ms) * (z - mz);
    czz += (z - mz) * (z - mz);
  }
  const double theta = 0.5 * std::atan2(2 * csz, css - czz);  // principal axis from the s axis
  c.angle_deg = std::abs(theta) * 180.0 / std::numbers::pi;
  return c;
}

}  // namespace polydem
