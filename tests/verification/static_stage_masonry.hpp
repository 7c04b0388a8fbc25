// The static stage's masonry cases (static_stage_masonry_test.cpp and its
// slow twin): a dry wall of small units and a 25-voussoir arch, whose blocks
// sit close to the step's frequency bound, solved at the default safety
// factor (integrators/static_stage.hpp: the stage's inertia under local
// damping).
#pragma once

#include "io/deck.hpp"
#include "limit_lambda.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem::static_stage_masonry {

// examples/verification/wall_pushover.toml with units 0.25 x 0.056 x 0.2 m:
// 1.5 m long, 1.568 m high (28 courses), 182 units, one leaf 0.2 m thick.
// Out of plane it tips about its base as one body at b/h = 0.2/1.568.
inline SceneSpec small_unit_wall() {
  return read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/wall_pushover.toml",
                   {"wall[1].unit_size=[0.25, 0.056, 0.2]", "wall[1].length=1.5", "wall[1].height=1.568"});
}

// examples/structures/arch_semicircular.toml (span 3 m, ring 0.35 m, on
// piers) with 25 voussoirs.
inline SceneSpec arch_of_25() {
  return read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/structures/arch_semicircular.toml",
                   {"arch[1].voussoirs=25"});
}

}  // namespace polydem::static_stage_masonry
