// The limit-analysis collapse load of a deck's blocks and joints along a
// direction, for the verification tests that compare the DEM with it.
#pragma once

#include "core/scene_spec.hpp"
#include "studies/limit_analysis.hpp"

#include <gtest/gtest.h>

namespace polydem {

// λ (g) of the LP on `s`'s initial joint mesh at its friction angle, the
// load along `direction`; the solve must be optimal.
inline double lp_lambda(const SceneSpec& s, const Vec3& direction) {
  const LimitModel m = limit_model(s);
  LimitAnalysisOptions o;
  o.friction_angle_deg = s.joint.friction_angle;
  o.direction = direction;
  const LimitAnalysisResult r = limit_analysis(m, o);
  EXPECT_EQ(r.status, LimitStatus::optimal);
  return r.lambda;
}

}  // namespace polydem
