// What `polydem analytic` (and the Python module's analytical models) read
// from decks and files: the scene of a --deck option, the semicircular
// arch of arch-thickness, and the ground-motion record of a rocking model.
#pragma once

#include "analytical/rocking_cases.hpp"
#include "core/scene_spec.hpp"

#include <string>
#include <vector>

namespace polydem {

// The name of the scene analytic_scene("") reads: a deck of one empty
// [spire], the paper's spire with the default materials.
inline constexpr const char* kDefaultSpireName = "<default [spire]>";

// The deck at `deck`, or the default spire when `deck` is empty; with
// no_windows, the override spire.window_faces=[]. Throws DeckError.
SceneSpec analytic_scene(const std::string& deck, bool no_windows);

// The same for the spire's models: throws std::runtime_error when the deck
// has no [spire].
SceneSpec analytic_spire_scene(const std::string& deck, bool no_windows);

// A semicircular [[arch]] of `voussoirs` stones, ring thickness t/R and
// centre-line radius R = 1 m (intrados radius 1 − t/2), depth 1 m, on a
// fixed base.
SceneSpec unit_semicircular_arch(int voussoirs, double t_over_R);

// A record for the rocking models, in any format read_record() reads (PEER
// .AT2, ESM .ASC, two-column .csv with its declared unit;
// io/ground_motion_record.hpp), at a uniform step (the ODE interpolates
// linearly between samples from t = 0), its acceleration in g (the record's
// g, 9.80665 m/s²). A record that starts later is shifted to t = 0.
struct UniformRecord {
  double dt = 0.0;                   // [s]
  std::vector<double> acceleration;  // [g]
  bool shifted = false;              // its first time was not 0
};

// Throws RecordError naming the file (and the line).
UniformRecord read_uniform_record(const std::string& path);

// The record at `path` as a rocking model's load.
analytical::LoadSpec record_load(const std::string& path);

}  // namespace polydem
