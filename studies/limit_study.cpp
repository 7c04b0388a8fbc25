#include "studies/limit_study.hpp"

#include <cmath>
#include <numbers>

namespace polydem {

std::optional<std::vector<FrictionPyramid>> friction_pyramids_named(const std::string& name) {
  if (name == "both") return std::vector{FrictionPyramid::circumscribed, FrictionPyramid::inscribed};
  if (name == "circumscribed") return std::vector{FrictionPyramid::circumscribed};
  if (name == "inscribed") return std::vector{FrictionPyramid::inscribed};
  return std::nullopt;
}

std::optional<LpMethod> lp_method_named(const std::string& name) {
  if (name == "simplex") return LpMethod::simplex;
  if (name == "interior") return LpMethod::interior_point;
  return std::nullopt;
}

LimitStudy limit_study(const SceneSpec& scene, const LimitStudyOptions& options) {
  LimitStudy study;
  study.deck = scene.deck_path;
  study.options = options;
  if (study.options.friction_angles_deg.empty()) study.options.friction_angles_deg = {scene.joint.friction_angle};
  study.model = limit_model(scene);
  for (char f : study.model.free) study.free_blocks += f;
  LimitAnalysisOptions lp;
  lp.pyramid_sides = options.pyramid_sides;
  lp.method = options.method;
  lp.lp_file = options.lp_file;
  for (double direction : study.options.directions_deg)
    for (double phi : study.options.friction_angles_deg) {
      LimitCase c;
      c.direction_deg = direction;
      c.friction_angle_deg = phi;
      const double a = direction * std::numbers::pi / 180.0;
      lp.direction = Vec3(std::cos(a), std::sin(a), 0.0);
      lp.friction_angle_deg = phi;
      for (const FrictionPyramid p : study.options.pyramids) {
        lp.pyramid = p;
        c.results.push_back(limit_analysis(study.model, lp));
      }
      study.cases.push_back(std::move(c));
    }
  return study;
}

}  // namespace polydem
