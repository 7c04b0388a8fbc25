#include "studies/limit_study.hpp"

#include "contact/joint_law.hpp"
#include "core/blocks.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

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

// The friction angle of the deck's joints, degrees: the one tan φ of every
// law that can act (the LP takes one φ per case).
double deck_friction_angle(const SceneSpec& scene) {
  const JointLaws laws = make_joint_laws(build_blocks(scene.blocks), scene.joint, scene.joint_pairs);
  const std::vector<int> acting = acting_laws(laws);
  const double tan_phi = laws.laws[static_cast<std::size_t>(acting.at(0))].tan_phi;
  for (const int k : acting)
    if (laws.laws[static_cast<std::size_t>(k)].tan_phi != tan_phi)
      throw std::invalid_argument(
          "the deck's joints have different friction angles ([[joint]] between): give the angles to analyse");
  if (tan_phi == make_joint_law(scene.joint).tan_phi) return scene.joint.friction_angle;
  return std::atan(tan_phi) * 180.0 / std::numbers::pi;
}

LimitStudy limit_study(const SceneSpec& scene, const LimitStudyOptions& options) {
  LimitStudy study;
  study.deck = scene.deck_path;
  study.options = options;
  if (study.options.friction_angles_deg.empty()) study.options.friction_angles_deg = {deck_friction_angle(scene)};
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
