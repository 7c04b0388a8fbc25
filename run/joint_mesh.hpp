// The joints of the initial mesh, and how far each is open, from the blocks'
// motion alone.
//
// The joints are every pair of blocks touching at t = 0 (within
// simulation.overlap_tolerance), each with its reference plane fixed in one
// block and its patch corners fixed in the other, as the first detection
// found them. A joint's opening is the largest distance of its corners from
// the plane, n·(p − x_ref) − offset, with both blocks at their current pose:
// exact for a rigid block whatever the opening (1 mm or 1 m), while a
// detected contact exists only within the contact margin and its plane and
// points change with each detection. A closed joint reads minus its overlap
// (µm under self-weight). The walking openings (run/recorder.hpp), the crack
// (run/assessment.hpp) and the limit analysis's joints
// (studies/limit_analysis.hpp) are read on it.
#pragma once

#include "integrators/simulation.hpp"

#include <vector>

namespace polydem {

// A joint of the initial mesh: the reference plane n·x = offset in the
// reference block's frame and the patch corners in the other block's frame
// (corners[first, first + count)).
struct InitialJoint {
  int a = 0, b = 0;             // the blocks, a < b
  int ref = 0, inc = 0;         // reference and incident block
  Vec3 normal_local;            // unit, reference frame
  double offset_local = 0;      // m
  bool bed = false;             // normal within 45° of up at t = 0
  int first = 0, count = 0;
};

// The joints of the initial mesh and their openings at the force time.
struct JointMesh {
  std::vector<InitialJoint> joints;
  std::vector<Vec3> corners;  // incident frame
  static JointMesh from_contacts(const Simulation& sim, const Vec3& up, double tolerance);
  double opening(const Simulation& sim, const InitialJoint& j) const;  // m, > 0 open
  // The mean of its corners, world, at the force time.
  Vec3 centre(const Simulation& sim, const InitialJoint& j) const;
};

}  // namespace polydem
