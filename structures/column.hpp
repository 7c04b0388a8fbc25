// A column of drums on a fixed base: the classical rocking column of
// classical temples (optionally a square plinth under the shaft and a capital
// on top), built block by block.
//
// Frame: z up, the column's axis the vertical through `origin`; z = origin.z
// is the top of the fixed base slab. From the bottom up:
//   base     the fixed slab, a square `base_width` wide (0: twice the widest
//            block above it), `base_thickness` thick, under z = 0;
//   plinth   (optional, plinth_height > 0) a square block plinth_width wide;
//   drums    `drums` drums of the shaft, each a right prism of the regular
//            polygon of `sides` sides INSCRIBED in the circle of `radius`
//            (its corners on the circle, at angles (2k+1)π/N from +x, so a
//            side faces +x, and −x for even N, ±y for N a multiple of 4:
//            the column rocks about an edge, not a corner, along those):
//            the circular section is replaced by the polygon, area
//            ½ N r² sin(2π/N) (2.5 % less than π r² at N = 16). Heights:
//            `drum_heights` one per drum, or `height` split into equal drums;
//   capital  (optional) "abacus": a square slab capital_width wide,
//            capital_height thick; "frustum": the echinus as a frustum of the
//            shaft's polygon widening from radius at its bed to
//            capital_width/2 at its top (similar polygons), capital_height
//            tall, its volume h/3 (A0 + A1 + √(A0 A1)).
// The square blocks' sides are along x and y. Every block is exact: prisms
// by make_prism, the frustum by the convex hull of its two polygons (CGAL).
#pragma once

#include <string>
#include <vector>

#include "structures/generated_block.hpp"

namespace polydem {

enum class ColumnCapital { none, abacus, frustum };

struct ColumnSpec {
  int drums = 4;
  double radius = 0.3;                 // of the drums' circumscribed circle, m
  int sides = 16;                      // of the drums' polygon, in [4, 128] (4: square drums)
  double height = 2.4;                 // of the shaft (all drums), when drum_heights is empty, m
  std::vector<double> drum_heights;    // bottom up, m; empty = height / drums each
  double plinth_height = 0;            // 0 = no plinth
  double plinth_width = 0;             // 0 = 2.5 radius (at least 2 radius)
  ColumnCapital capital = ColumnCapital::none;
  double capital_width = 0;            // abacus side, or the frustum's top diameter, m; 0 = 2.5 radius
  double capital_height = 0;           // m; 0 = radius
  double base_width = 0;               // 0 = twice the widest block above it
  double base_thickness = 0.3;         // m
  Vec3 origin = Vec3::Zero();
};

// An invalid ColumnSpec; `field` is the deck key of [[column]].
struct ColumnSpecError : GeneratorSpecError {
  ColumnSpecError(std::string field_name, std::string what)
      : GeneratorSpecError("column", std::move(field_name), -1, std::move(what)) {}
};

struct ColumnModel {
  // Base, plinth, drums bottom up, capital (their kinds); a drum's index 0..
  // from the bottom. Names "base", "plinth", "drum0", "capital" (the deck
  // prefixes its section's name).
  std::vector<GeneratedBlock> blocks;
  std::vector<double> drum_heights;
  double drum_area = 0;             // of the drums' polygon, m²
  double top = 0;                   // z of the top of the column above origin, m
};

// Checks every field; throws ColumnSpecError naming the first bad one.
void validate_column(const ColumnSpec& spec);

ColumnModel build_column(const ColumnSpec& spec);


}  // namespace polydem
