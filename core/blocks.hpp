// The blocks of a scene: hot state in contiguous arrays, cold data apart.
//
// Each block moves as a rigid body. Its body frame has its origin at the
// centroid and its axes along the principal axes of inertia, so the inertia
// tensor is diagonal in the body frame and the full world tensor is
// R·diag(I)·Rᵀ. Leapfrog central differences keep positions and orientations
// at whole steps (t) and velocities and angular momenta at half steps
// (t − dt/2), so `velocity` and `angular_momentum` lag half a step.
#pragma once

#include "core/scene_spec.hpp"
#include "geometry/polyhedron.hpp"

#include <string>
#include <vector>

namespace polydem {

// Hot state: touched every step, by index, in parallel loops.
struct BlockState {
  std::vector<Vec3> position;          // centroid, world, at t
  std::vector<Quat> orientation;       // body → world, at t
  std::vector<Mat3> rotation;          // orientation as a matrix (cached each step)
  std::vector<Vec3> velocity;          // at t − dt/2
  std::vector<Vec3> angular_momentum;  // world, at t − dt/2
  std::vector<Vec3> angular_velocity;  // world, at t − dt/2 (derived from the momentum)
  std::vector<Vec3> contact_force;     // sum of joint forces at t
  std::vector<Vec3> contact_torque;    // about the centroid, at t
};

// Cold data: set once when the scene is built.
struct BlockProperties {
  std::vector<std::string> name;
  std::vector<BlockMotion> motion;
  std::vector<double> mass;
  std::vector<double> inv_mass;
  std::vector<Vec3> principal_inertia;      // body frame, kg·m²
  std::vector<Vec3> inv_principal_inertia;  // zero for blocks that do not rotate
  std::vector<Polyhedron> local_shape;      // vertices in the body frame
  std::vector<double> radius;               // bounding radius about the centroid
  std::vector<double> size;                 // cube root of volume, m
  std::vector<int> course;
  std::vector<int> group;                   // index into Blocks::group_names, -1 = no group
  std::vector<int> deck_line;
};

struct Blocks {
  int count = 0;
  BlockState state;
  BlockProperties props;
  std::vector<int> free_blocks;       // indices integrated by the time step
  std::vector<int> kinematic_blocks;  // moved by the prescribed base motion
  std::vector<Vec3> initial_position;
  std::vector<Quat> initial_orientation;
  // The groups' names, in the order of their first block (BlockSpec::group).
  std::vector<std::string> group_names;

  bool is_free(int i) const { return props.motion[i] == BlockMotion::free; }
  int find(const std::string& name) const;  // -1 if absent
  int find_group(const std::string& name) const;  // -1 if absent
};

// Builds blocks from the deck's shapes: mass properties, principal frame,
// body-frame vertices. Throws GeometryError naming the block.
Blocks build_blocks(const std::vector<BlockSpec>& specs);

// World coordinates of block i's vertex v at the current state.
inline Vec3 world_vertex(const Blocks& b, int i, int v) {
  return b.state.position[i] + b.state.rotation[i] * b.props.local_shape[i].vertices[v];
}

// The block's shape in world coordinates at the current state (for output).
Polyhedron world_shape(const Blocks& b, int i);

}  // namespace polydem
