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
//
// Courses. A course is a layer of stones resting on one bed level: the
// level bed joints (normal within 10° of up) whose centres lie at one height
// at t = 0 (each within 0.1 % of the height the joints span of the next)
// make a level, at the lowest of their heights, and
// course k is what rests on level k, up to level k + 1. A joint belongs to
// the course its centre lies in, a bed joint on a level to the course it
// carries (the joint under it); a tilted bed joint (a window's voussoir)
// to the course around it. Walking is
// reported per course (run/recorder.hpp) as an engineer reads a masonry
// elevation: which courses the stones walked apart in.
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
  int course = 0;               // the course it belongs to (above)
  int first = 0, count = 0;
};

// The joints of the initial mesh and their openings at the force time.
struct JointMesh {
  std::vector<InitialJoint> joints;
  std::vector<Vec3> corners;  // incident frame
  std::vector<double> course_levels;  // m along up, increasing: the height of each course's bed level at t = 0
  static JointMesh from_contacts(const Simulation& sim, const Vec3& up, double tolerance);
  double opening(const Simulation& sim, const InitialJoint& j) const;  // m, > 0 open
  // The mean of its corners, world, at the force time.
  Vec3 centre(const Simulation& sim, const InitialJoint& j) const;
  // Sets course_levels and each joint's course from the pose at t = 0.
  void assign_courses(const Simulation& sim, const Vec3& up);
};

}  // namespace polydem
