// Judging a run the way the paper does (section 3): intact, damaged
// (visible residual displacement, stones lost) or collapsed, the collapse
// mode (I after an impact, II without; Zhang & Makris 2001), and the crack:
// which blocks moved and the angle of the surface that separates them from
// the rest.
//
// The verdict rests on where the blocks end up, not on how far they swung.
// A block is dislodged when at the end it is away from its place by more
// than assessment.collapse_displacement; it has fallen when it has dropped
// below its place by more than that (it is no longer carried where it was).
// A rocking body that swung out and came back is neither. The structure has
// collapsed when
//   - the blocks dislodged at the end make up collapse_mass_fraction of the
//     free mass, or
//   - collapse is certain during the run: the fallen blocks make up that
//     fraction.
// The monitored body's point of no return is reported, not counted: once
// the loads no longer change, the vertical through its centre of mass
// (along gravity plus the steady ground acceleration's inertial load)
// passes outside the contact points it rests on, along the ground motion or
// across it, and it still moves outward. On a spire's tip, which rocks on a
// course that rocks too, the test fires on swings that come back.
// assessment.stop_on_collapse stops a run only on a certain collapse. A run
// that ends, without a certain collapse, with a free block still moving
// faster than √(2·g·damage_displacement/10) relative to the base is
// `undetermined`: run it longer (or let simulation.settle_velocity end it
// once everything is at rest). That speed is what a block gains falling a
// tenth of the damage displacement: a block tipping slowly over an edge
// goes faster than that long before it falls, and a stone that has fallen
// inside a shell and still rolls is counted too, since it can knock others
// out (both seen on the spire after a 0.25 g pulse). A block whose centre
// has dropped below the bottom of the model as built has fallen off it and
// is not counted.
//
// The peak excursions stay as peaks (peak_displacement, the monitor's peak):
// they describe the response, not the damage.
#pragma once

#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"
#include "run/crack.hpp"

#include <limits>
#include <string>
#include <vector>

namespace polydem {

struct Assessment {
  std::string status = "intact";  // intact | damaged | collapsed | undetermined
  std::string collapse_mode;      // "I", "II" or "" (not collapsed)
  // Why it collapsed: "lost mass" (the blocks dislodged at the end, or
  // fallen during the run, reached collapse_mass_fraction), "point of no
  // return" (the monitored body's counted with them); "" when not.
  std::string collapse_reason;
  // s, when the collapse began: the start of the last stretch during which
  // the dislodged mass stayed at collapse_mass_fraction or more, or the
  // moment collapse became certain if that came first; -1: none.
  double collapse_time = -1;
  double damage_time = -1;        // s, first time a block moved damage_displacement
  double ground_acceleration_at_damage = 0;  // m/s², a_g at damage_time (onset under a ramp)
  double peak_displacement = 0;   // m, largest displacement of any free block during the run
  std::string peak_displacement_block;
  double max_residual_displacement = 0;  // m, the largest at the end
  std::string monitor_block;
  // m, largest |displacement| of the monitor block along the ground motion
  // (the peak tip displacement of a spire), sampled every 16th step, and
  // its |displacement| along the motion at the end.
  double monitor_peak_displacement = 0;
  double monitor_residual_displacement = 0;
  bool monitor_past_no_return = false;  // at the end (or when the run stopped)
  // The fastest free block at the end: its speed relative to the base
  // (speed plus spin times radius), m/s, and the speed above which the run
  // is undetermined, √(2·g·damage_displacement/10).
  double fastest_speed = 0;
  std::string fastest_block;
  double moving_speed_limit = 0;
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
  // Stones lost, reported apart from collapse: the free blocks dislodged at
  // the end (fallen ones included), their mass, its fraction of the free
  // blocks' mass, where they came from (heights of their starting centroids
  // along "up"), and which of them fell.
  std::vector<std::string> dislodged_blocks;
  double dislodged_mass = 0;           // kg
  double dislodged_mass_fraction = 0;  // of the free blocks' mass
  double dislodged_low_z = 0, dislodged_high_z = 0;  // m
  std::vector<std::string> fallen_blocks;
  double fallen_mass_fraction = 0;

  int stones_lost() const { return static_cast<int>(dislodged_blocks.size()); }
};

class AssessmentMonitor {
 public:
  // `gravity` gives "up" (the monitor block is the highest free block
  // against it; the crack's heights are measured along it).
  // `joint_tolerance`: how close two blocks' faces must be at t = 0 to make a
  // joint of the initial mesh (simulation.overlap_tolerance), on which the
  // crack is judged (run/crack.hpp).
  AssessmentMonitor(const AssessmentSpec& spec, const Simulation& sim, const Vec3& gravity, double joint_tolerance);
  // From this time on the loads no longer change (run_scene's
  // loads_final_time): the point of no return is tested from then on.
  // Infinite (never) unless set.
  void set_loads_final_time(double t) { loads_final_time_ = t; }
  void observe(const Simulation& sim);  // cheap: samples every 16th step
  bool collapsed() const { return collapsed_; }  // certain: stop_on_collapse may stop
  Assessment finish(const Simulation& sim);
  // Checkpoints: what observe() has accumulated (the start positions come
  // from the scene at t = 0, where a restart builds the monitor).
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  Vec3 displacement(const Simulation& sim, int i) const;
  bool fallen(const Simulation& sim, int i) const;
  bool past_no_return(const Simulation& sim) const;
  void sample(const Simulation& sim);
  void list_lost(const Simulation& sim);
  void record_crack(const Simulation& sim);
  void mark_collapse(const Simulation& sim, const char* reason);

  AssessmentSpec spec_;
  Vec3 up_;
  CrackGauge crack_;
  Vec3 gravity_;
  Vec3 direction_;
  int monitor_ = -1;
  int reference_ = -1;  // a kinematic base block: displacements are relative to it
  Vec3 reference_start_ = Vec3::Zero();
  std::vector<Vec3> start_;
  double model_bottom_ = 0;  // along up_, the lowest vertex of the model as built
  double loads_final_time_ = std::numeric_limits<double>::infinity();
  bool collapsed_ = false;
  int first_sign_ = 0;
  double free_mass_ = 0;
  bool reversed_ = false;
  // The current stretch with the dislodged mass at collapse_mass_fraction or
  // more: since when (-1: none), its mode, its crack recorded at its start.
  double excursion_since_ = -1;
  std::string excursion_mode_;
  Assessment result_;
};

}  // namespace polydem
