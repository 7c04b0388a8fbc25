// `polydem mesh DECK.toml --out DIR`: build a deck's blocks (e.g. the
// [spire]) without running anything, write them to DIR/blocks.vtu for
// ParaView and print what they add up to: block count, mass, centroid
// height and, for a [spire], the λ of the equivalent conical shell (paper
// eq. 1 and 2).
#pragma once

#include <string>
#include <vector>

#include "core/scene_spec.hpp"

namespace polydem {

struct MeshOptions {
  std::string deck_path;
  std::string out_dir = "mesh";
  std::vector<std::string> overrides;  // "key=value", as for `run`
};

// What `mesh` prints. Mass and centroid are over the free blocks (the
// structure; fixed and kinematic blocks are its support).
struct MeshSummary {
  int blocks = 0;
  int free_blocks = 0;
  int courses = 0;                  // distinct course indices >= 0
  double free_mass = 0;             // kg
  double support_mass = 0;          // kg, fixed and kinematic blocks
  double centroid_height = 0;       // m, z of the free blocks' centre of mass
  bool has_cone = false;            // a [spire]: the equivalent cone below is set
  double cone_radius = 0;           // r_b = the spire's base_inradius, m
  double cone_height = 0;           // H = the spire's height, m
  double lambda_eq1 = 0;            // eq. 1
  double lambda_eq2 = 0;            // eq. 2 at the governing crack
  double crack_height = 0;          // h_c of that crack, m
};
MeshSummary summarize_mesh(const SceneSpec& scene);

// Exit codes as `run`: 0, or 2 (exit_bad_input) for a bad deck or an
// output directory that cannot be written.
int mesh_command(const MeshOptions& options);

}  // namespace polydem
