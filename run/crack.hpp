// The crack: which joints of the initial mesh have cracked, and the surface
// they make (the paper's section 3: the tall vertical crack of the spire's
// Mode II, a low sliding crack, ...).
//
// A joint of the initial mesh (run/joint_mesh.hpp) has cracked when its two
// faces have moved apart by more than `opening` somewhere: the largest
// displacement of its patch corners, fixed in the incident block, relative
// to the reference block, taken in the reference block's frame from where
// they were at t = 0. Opening and slip count alike (a bed joint that slid
// has cracked as much as one that opened), and a rigid motion of both
// blocks moves nothing. Everything is read from the blocks' poses: the
// contacts the search holds at that moment (and so the contact margin) play
// no part.
//
// Each cracked joint is placed where it was at t = 0 (the centre of its
// corners), so the crack is drawn on the structure as built however far its
// stones have gone. Its angle from horizontal is that of the principal axis
// of those points in the vertical plane of the ground motion (total least
// squares: a vertical crack is as well defined as a horizontal one), and its
// heights the range of theirs along "up".
#pragma once

#include "run/joint_mesh.hpp"

#include <vector>

namespace polydem {

struct Crack {
  int cracked_joints = 0;
  double angle_deg = -1;     // from horizontal; −1: fewer than two joints
  double low_z = 0, high_z = 0;  // m, along up
};

class CrackGauge {
 public:
  CrackGauge() = default;
  // The initial mesh as the scene stands now (t = 0, after any static stage).
  CrackGauge(const Simulation& sim, const Vec3& up, double tolerance);
  Crack measure(const Simulation& sim, const Vec3& direction, double opening) const;
  // The largest relative displacement of joint q's corners since t = 0, m.
  double separation(const Simulation& sim, std::size_t q) const;
  std::size_t size() const { return mesh_.joints.size(); }

 private:
  JointMesh mesh_;
  Vec3 up_ = Vec3::UnitZ();
  std::vector<Vec3> start_;   // each corner at t = 0, in its joint's reference frame
  std::vector<Vec3> centre_;  // each joint's centre at t = 0, world
};

}  // namespace polydem
