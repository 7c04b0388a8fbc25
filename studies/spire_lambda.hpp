// The refined static collapse multiplier of a deck's spire
// (analytical/refined_lambda.hpp: rigid parts above plane and stepped cracks
// through a base pivot, 16 directions) beside eq. 1 and 2 for the spire's
// height and base radius, as `polydem analytic refined-lambda` reports it.
#pragma once

#include "analytical/refined_lambda.hpp"
#include "analytical/static_overturning.hpp"
#include "core/scene_spec.hpp"

#include <string>

namespace polydem {

struct SpireLambda {
  std::string deck;                // the deck's path or name
  int blocks = 0, courses = 0, windows = 0;
  double height = 0.0;             // H of eq. 1-2 [m]
  double base_inradius = 0.0;      // r_b of eq. 1-2: the mid-wall apothem at the base [m]
  double density = 0.0;            // of the stones (the first non-base block's) [kg/m³]
  double lambda_eq1 = 0.0;
  analytical::GoverningCrack eq2;  // eq. 2's minimum over the crack height
  analytical::RefinedLambdaResult refined;
};

// The spire of `scene` built as for a run. Throws std::invalid_argument
// when the scene has no [spire].
SpireLambda spire_lambda(const SceneSpec& scene, double g = analytical::standard_gravity);

}  // namespace polydem
