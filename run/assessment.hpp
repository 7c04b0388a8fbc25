// Judging a run the way the paper does (section 3): intact, damaged
// (visible residual displacement) or collapsed, the collapse mode (I after an
// impact, II without; Zhang & Makris 2001), and the crack: which blocks moved
// and the angle of the surface that separates them from the rest.
#pragma once

#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"
#include "run/crack.hpp"

#include <string>
#include <vector>

namespace polydem {

struct Assessment {
  std::string status = "intact";  // intact | damaged | collapsed
  std::string collapse_mode;      // "I", "II" or "" (not collapsed)
  double collapse_time = -1;      // s, first time a block moved collapse_displacement
  double damage_time = -1;        // s, first time a block moved damage_displacement
  double ground_acceleration_at_damage = 0;  // m/s², a_g at damage_time (onset under a ramp)
  double max_displacement = 0;    // m, largest displacement of any free block during the run
  std::string max_displacement_block;
  double max_residual_displacement = 0;  // m, at the end
  std::string monitor_block;
  // m, largest |displacement| of the monitor block along the ground motion
  // (the peak tip displacement of a spire), sampled as max_displacement is.
  double monitor_peak_displacement = 0;
  // When the run collapsed (or at the end if damaged): the blocks that had
  // moved more than damage_displacement, and the crack (run/crack.hpp) —
  // the joints of the initial mesh whose faces moved apart, open or slid, by
  // more than half of it — with the angle from horizontal of its principal
  // axis in the vertical plane of the ground motion (degrees) and the height
  // range it spans.
  std::vector<std::string> moved_blocks;
  int opened_joints = 0;
  double crack_angle_deg = -1;
  double crack_low_z = 0, crack_high_z = 0;  // m
  // Stones dislodged, reported apart from collapse: the free blocks that
  // moved farther than collapse_displacement at some time (sampled as
  // max_displacement is), their mass, its fraction of the free blocks' mass,
  // the first time one did, and where they came from (heights of their
  // starting centroids along "up").
  std::vector<std::string> dislodged_blocks;
  double dislodged_mass = 0;           // kg
  double dislodged_mass_fraction = 0;  // of the free blocks' mass
  double first_dislodged_time = -1;    // s, -1: none
  double dislodged_low_z = 0, dislodged_high_z = 0;  // m
};

class AssessmentMonitor {
 public:
  // `gravity` gives "up" (the monitor block is the highest free block
  // against it; the crack's heights are measured along it).
  // `joint_tolerance`: how close two blocks' faces must be at t = 0 to make a
  // joint of the initial mesh (simulation.overlap_tolerance), on which the
  // crack is judged (run/crack.hpp).
  AssessmentMonitor(const AssessmentSpec& spec, const Simulation& sim, const Vec3& gravity, double joint_tolerance);
  void observe(const Simulation& sim);  // cheap: samples every 16th step
  bool collapsed() const { return collapsed_; }
  Assessment finish(const Simulation& sim);
  // Checkpoints: what observe() has accumulated (the start positions come
  // from the scene at t = 0, where a restart builds the monitor).
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  Vec3 displacement(const Simulation& sim, int i) const;
  bool track_dislodged(const Simulation& sim);
  void list_dislodged(const Simulation& sim);
  void record_crack(const Simulation& sim);

  AssessmentSpec spec_;
  Vec3 up_;
  CrackGauge crack_;
  Vec3 direction_;
  int monitor_ = -1;
  int reference_ = -1;  // a kinematic base block: displacements are relative to it
  Vec3 reference_start_ = Vec3::Zero();
  std::vector<Vec3> start_;
  bool collapsed_ = false;
  int first_sign_ = 0;
  double free_mass_ = 0;
  std::vector<std::uint8_t> dislodged_;  // by block index
  bool reversed_ = false;
  Assessment result_;
};

}  // namespace polydem
