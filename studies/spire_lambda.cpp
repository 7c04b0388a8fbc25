#include "studies/spire_lambda.hpp"

#include "structures/generator_specs.hpp"

#include <stdexcept>

namespace polydem {

namespace {

// The stones' density: the deck gives it per block; the spire's stones share
// one, the base block may differ.
double stone_density(const SceneSpec& scene, const SpireModel& model) {
  for (const auto& stone : model.blocks)
    for (const auto& b : scene.blocks)
      if (b.name == stone.name && stone.kind != BlockKind::base) return b.density;
  return 2600.0;
}

}  // namespace

SpireLambda spire_lambda(const SceneSpec& scene, double g) {
  const SpireSpec* spire = spire_of(scene.generators);
  if (!spire) throw std::invalid_argument("refined lambda: the deck " + scene.deck_path + " has no [spire]");
  const SpireSpec& sp = *spire;
  const SpireModel model = build_spire(sp);
  SpireLambda r;
  r.deck = scene.deck_path;
  r.blocks = static_cast<int>(model.blocks.size());
  r.courses = model.n_courses;
  r.windows = static_cast<int>(sp.window_faces.size());
  r.height = sp.height;
  r.base_inradius = sp.base_inradius;
  r.density = stone_density(scene, model);
  analytical::RefinedLambdaOptions options;
  options.g = g;
  r.refined = analytical::refined_lambda(model, r.density, options);
  r.lambda_eq1 = analytical::lambda_cone(sp.base_inradius, sp.height);
  r.eq2 = analytical::governing_crack(sp.base_inradius, sp.height);
  return r;
}

}  // namespace polydem
