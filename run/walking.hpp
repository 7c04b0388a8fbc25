// What a run measures of its stones' walking (output.walking): plain data
// that the recorder fills (run/recorder.hpp), the summary writes and the
// studies read back (studies/point_result.hpp). The openings are those of
// the joints of the initial mesh, from the blocks' motion
// (run/joint_mesh.hpp), and the courses are its bed levels.
#pragma once

#include <string>
#include <vector>

namespace polydem {

// One course's walking. A closed joint counts as 0 in the mean (its
// opening is minus its overlap, µm).
struct CourseWalking {
  double level = 0;                        // m along up: the course's bed level at t = 0
  int bed_joints = 0, vertical_joints = 0;
  double bed_mean = 0, bed_largest = 0;            // m, at the end
  double vertical_mean = 0, vertical_largest = 0;  // m, at the end
  double peak_bed = 0, peak_vertical = 0;          // m, the largest during the run
};

// Walking (output.walking): largest opening of bed joints and of vertical
// joints, at the end and the largest seen, and per course from the bottom.
struct Walking {
  double bed_opening = 0, vertical_opening = 0;          // m, at the end
  double max_bed_opening = 0, max_vertical_opening = 0;  // m, during the run
  std::string bed_joint, vertical_joint;                 // "blockA|blockB" at the end
  std::vector<CourseWalking> courses;
};

}  // namespace polydem
