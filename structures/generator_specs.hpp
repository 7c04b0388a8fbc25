// The specs a deck's generator sections were given, as the scene keeps them
// (SceneSpec::generators, which core holds by name only): what the analyses
// that rebuild a structure's block model read, as the refined lambda and the
// DEM frequency rebuild the spire's. A generator whose spec no analysis
// reads has no field here.
#pragma once

#include "structures/spire.hpp"

#include <cstddef>
#include <memory>
#include <optional>

namespace polydem {

struct GeneratorSpecs {
  std::optional<SpireSpec> spire;  // [spire], when the deck has one
};

// The scene's [spire] (SceneSpec::generators), or nullptr when it has none.
inline const SpireSpec* spire_of(const std::shared_ptr<const GeneratorSpecs>& specs) {
  return specs && specs->spire ? &*specs->spire : nullptr;
}

// The faces of the scene's [spire] with a window; 0 without a spire.
inline std::size_t spire_windows(const std::shared_ptr<const GeneratorSpecs>& specs) {
  const SpireSpec* spire = spire_of(specs);
  return spire ? spire->window_faces.size() : 0;
}

}  // namespace polydem
