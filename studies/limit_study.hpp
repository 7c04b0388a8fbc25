// The limit-analysis LP (studies/limit_analysis.hpp) of one scene over a
// table of cases, as `polydem analytic limit-lp` runs it: for every load
// direction, every friction angle, the LP with every friction pyramid asked
// (circumscribed and inscribed bracket the exact cone's value).
#pragma once

#include "studies/limit_analysis.hpp"

#include <optional>
#include <string>
#include <vector>

namespace polydem {

struct LimitStudyOptions {
  std::vector<double> directions_deg{0.0};   // azimuths of the static force from +x [deg]
  std::vector<double> friction_angles_deg;   // φ [deg]; empty: the one φ of every law that can act
  std::vector<FrictionPyramid> pyramids{FrictionPyramid::circumscribed, FrictionPyramid::inscribed};
  int pyramid_sides = 16;
  LpMethod method = LpMethod::interior_point;
  std::string lp_file;  // each LP is written there before it is solved: the last case's stays
};

struct LimitCase {
  double direction_deg = 0.0, friction_angle_deg = 0.0;
  std::vector<LimitAnalysisResult> results;  // one per pyramid, in the options' order
};

struct LimitStudy {
  std::string deck;              // the scene's deck path or name
  LimitModel model;
  LimitStudyOptions options;     // the friction angles filled in
  int free_blocks = 0;
  std::vector<LimitCase> cases;  // direction by direction, friction angle by friction angle
};

// The command line's names: "both" (circumscribed, then inscribed),
// "circumscribed", "inscribed"; "simplex", "interior". None for another.
std::optional<std::vector<FrictionPyramid>> friction_pyramids_named(const std::string& name);
std::optional<LpMethod> lp_method_named(const std::string& name);

// Builds the scene's LimitModel and solves every case. Throws as
// limit_model() and limit_analysis() do.
LimitStudy limit_study(const SceneSpec& scene, const LimitStudyOptions& options);

}  // namespace polydem
