// What every generator in structures/ returns: its blocks, each one
// GeneratedBlock (the shape, what the block is in the masonry, where it lies
// and its name), and the error a spec that cannot be built throws.
//
// A field a generator does not use stays -1: a wall has leaves, a tower and
// the spire faces, an arch spans and rings; `index` is the block's place in
// its course, ring or column (the spire's stone, the arch's voussoir or
// support, the column's drum).
#pragma once

#include "geometry/polyhedron.hpp"

#include <string>

namespace polydem {

// What a block is, in a mason's words.
enum class BlockKind {
  unit,           // a wall's stretcher (or any unit of its bond)
  header,         // a wall's unit laid across it
  through_stone,  // a wall's unit through all its leaves
  closer,         // a queen closer at a wall's quoin
  apex,           // the top stone of a gable
  stone,          // a tower's or the spire's stone
  window_piece,   // a piece of a spire stone cut by a window, or a head block over it
  tip,            // the spire's solid tip
  jamb,           // the stone beside an opening under its head
  lintel,
  voussoir,
  base,           // the block or slab a structure stands on
  abutment,
  pier,
  plinth,
  drum,
  capital,
};

// "unit", "through_stone", ...: the kind's name in block groups and outputs.
const char* to_string(BlockKind kind);

struct GeneratedBlock {
  Polyhedron shape;  // world coordinates
  BlockKind kind = BlockKind::stone;
  // The generator's name for the block ("wall_course03_leaf1_unit4",
  // "course01_face0_stone1_piece2", "voussoir03", "drum0"); each
  // generator's header lists its names.
  std::string name;
  int course = -1;   // the (lowest) course it lies in; a pier's course; the spire's tip n_courses
  int face = -1;     // the tower's or spire's face, 0.. counter-clockwise from +x
  int leaf = -1;     // a wall's leaf, 0.. from v = -thickness/2; -1 through the whole wall
  int opening = -1;  // the opening whose head it is (lintel, voussoir)
  int span = -1;     // an arcade's span, 0.. from -x
  int ring = -1;     // a barrel vault's ring, 0.. from -y
  int index = -1;    // its place in the course, ring or column
  int piece = -1;    // among the pieces of a stone cut by a window (or the head's voussoirs)
};

// A generator's parameters that cannot be built (each generator derives its
// own type): what() is "GENERATOR: FIELD: DETAIL"; `opening` the index of
// the opening at fault, -1 when none.
struct GeneratorSpecError : GeometryError {
  GeneratorSpecError(const std::string& generator, std::string field_name, int opening_index, std::string what)
      : GeometryError(generator + ": " + field_name + ": " + what),
        field(std::move(field_name)),
        opening(opening_index),
        detail(std::move(what)) {}
  std::string field;    // e.g. "window_width"
  int opening = -1;
  std::string detail;   // the message without the "GENERATOR: FIELD: " prefix
};

}  // namespace polydem
