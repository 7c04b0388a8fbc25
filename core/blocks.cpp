#include "core/blocks.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace polydem {

int Blocks::find(const std::string& n) const {
  for (int i = 0; i < count; ++i)
    if (props.name[i] == n) return i;
  return -1;
}

int Blocks::find_group(const std::string& n) const {
  for (std::size_t g = 0; g < group_names.size(); ++g)
    if (group_names[g] == n) return static_cast<int>(g);
  return -1;
}

Blocks build_blocks(const std::vector<BlockSpec>& specs) {
  Blocks b;
  b.count = static_cast<int>(specs.size());
  const std::size_t n = specs.size();
  auto& s = b.state;
  auto& p = b.props;
  s.position.resize(n);
  s.orientation.resize(n);
  s.rotation.resize(n);
  s.velocity.resize(n);
  s.angular_momentum.resize(n);
  s.angular_velocity.resize(n);
  s.contact_force.assign(n, Vec3::Zero());
  s.contact_torque.assign(n, Vec3::Zero());
  p.name.resize(n);
  p.motion.resize(n);
  p.mass.resize(n);
  p.inv_mass.resize(n);
  p.principal_inertia.resize(n);
  p.inv_principal_inertia.resize(n);
  p.local_shape.resize(n);
  p.radius.resize(n);
  p.size.resize(n);
  p.course.resize(n);
  p.group.resize(n);
  p.deck_line.resize(n);

  for (std::size_t i = 0; i < n; ++i) {
    const BlockSpec& spec = specs[i];
    const MassProperties mp = mass_properties(spec.shape);
    const double m = spec.density * mp.volume;
    // Principal axes: the eigenvectors of the inertia tensor, ordered by the
    // solver (ascending), made right-handed so the frame is a rotation.
    Eigen::SelfAdjointEigenSolver<Mat3> eig(spec.density * mp.inertia);
    Mat3 axes = eig.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    const Quat q(axes);
    // Local shape: world shape moved so that the centroid is the origin and
    // the principal axes are the coordinate axes.
    p.local_shape[i] = transformed(spec.shape, axes.transpose(), -axes.transpose() * mp.centroid);

    s.position[i] = mp.centroid;
    s.orientation[i] = q.normalized();
    s.rotation[i] = s.orientation[i].toRotationMatrix();
    p.name[i] = spec.name;
    p.motion[i] = spec.motion;
    p.mass[i] = m;
    p.principal_inertia[i] = eig.eigenvalues();
    p.radius[i] = bounding_radius(p.local_shape[i], Vec3::Zero());
    p.size[i] = std::cbrt(mp.volume);
    p.course[i] = spec.course;
    p.group[i] = spec.group.empty() ? -1 : b.find_group(spec.group);
    if (!spec.group.empty() && p.group[i] < 0) {
      p.group[i] = static_cast<int>(b.group_names.size());
      b.group_names.push_back(spec.group);
    }
    p.deck_line[i] = spec.deck_line;
    const bool free = spec.motion == BlockMotion::free;
    p.inv_mass[i] = free ? 1.0 / m : 0.0;
    p.inv_principal_inertia[i] = free ? Vec3(p.principal_inertia[i].cwiseInverse()) : Vec3(Vec3::Zero());
    s.velocity[i] = spec.motion == BlockMotion::fixed ? Vec3::Zero() : spec.velocity;
    const Vec3 w = free ? spec.angular_velocity : Vec3::Zero();
    const Mat3& R = s.rotation[i];
    s.angular_momentum[i] = R * p.principal_inertia[i].cwiseProduct(R.transpose() * w);
    s.angular_velocity[i] = w;
    if (free) b.free_blocks.push_back(static_cast<int>(i));
    if (spec.motion == BlockMotion::kinematic) b.kinematic_blocks.push_back(static_cast<int>(i));
  }
  b.initial_position = s.position;
  b.initial_orientation = s.orientation;
  return b;
}

Polyhedron world_shape(const Blocks& b, int i) {
  return transformed(b.props.local_shape[i], b.state.rotation[i], b.state.position[i]);
}

}  // namespace polydem
