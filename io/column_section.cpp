// [[column]]: columns of drums of structures/column.hpp, one per table. Each
// table's `name` prefixes its blocks' names ("portico1_drum03"); the groups
// are "base", "plinth", "drum" and "capital", and a drum's `course` is its
// index from the bottom.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[[column]]`

A column of drums on a fixed base, optionally with a square plinth and a
capital (`structures/column.hpp`; docs/structures.md, "Columns"). Each table
builds one column; a deck may hold several. Blocks: `NAME_base`,
`NAME_plinth`, `NAME_drumDD` (DD from 00 at the bottom), `NAME_capital`;
groups `base`, `plinth`, `drum`, `capital`; a drum's `course` is its index.
The drums are right prisms of the regular polygon of `sides` sides inscribed
in the circle of `radius` (corners at angles (2k+1)·180°/N from +x, so a side faces +x: the column rocks about an edge), stacked on the vertical axis
through `origin`, whose z is the top of the base slab.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `name` | string | – | `"column"` (`"columnN"` when the deck has several) | Prefix of the blocks' names; must not be empty. |
| `drums` | integer | – | `4` (or the length of `drum_heights`) | Number of drums, in [1, 1000]. |
| `radius` | float | m | `0.3` | Radius of the circle the drums' polygon is inscribed in; > 0. |
| `sides` | integer | – | `16` | Sides of the drums' polygon, in [4, 128]; 4 gives square drums (a pillar of stones, sides facing ±x and ±y). |
| `height` | float | m | `2.4` | Height of the shaft, split into equal drums; > 0. Not with `drum_heights`. |
| `drum_heights` | [float, ...] | m | equal drums | One height per drum, bottom up, each > 0. |
| `plinth_height` | float | m | `0` | Height of a square plinth under the shaft; 0 = none. |
| `plinth_width` | float | m | `2.5 × radius` | Side of the plinth; at least the drums' diameter. Needs a plinth. |
| `capital` | string | – | `"none"` | `"none"`, `"abacus"` (a square slab) or `"frustum"` (the shaft's polygon widening to `capital_width`/2 at the top). |
| `capital_width` | float | m | `2.5 × radius` | Abacus: its side; frustum: its top diameter (not the shaft's). Needs a capital. |
| `capital_height` | float | m | `radius` | Height of the capital. Needs a capital. |
| `base_width` | float | m | twice the widest block | Side of the square fixed base slab; at least as wide as the block on it. |
| `base_thickness` | float | m | `0.3` | Thickness of the base slab; > 0. |
| `base_motion` | string | – | `"fixed"` | `"fixed"` or `"kinematic"` (moves with the ground motion when `applied_as = "kinematic"`). |
| `origin` | [x, y, z] | m | `[0, 0, 0]` | The foot of the column's axis (top of the base slab). |
| `density` | float | kg/m³ | `2600` | Density of every block of the table; > 0. |

Every length is at most 1000 radii (the shaft at most 100 km); all the
`[[column]]` tables of a deck build at most 20000 blocks.
*/
#include "io/generators.hpp"

#include "structures/column.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kColumnKeys[] = {
    "name",          "drums",        "radius",         "sides",          "height",
    "drum_heights",  "plinth_width", "plinth_height",  "capital",        "capital_width",
    "capital_height", "base_width",  "base_thickness", "base_motion",    "origin",
    "density"};

struct ColumnSection {
  using Spec = ColumnSpec;

  static constexpr GeneratorRules rules{.section = "column", .keys = kColumnKeys, .order = 50, .single = false,
                                        .naming = Naming::prefix, .motion_key = "base_motion",
                                        .grouping = Grouping::kind, .group_by = {}, .max_blocks = 20000};

  static ColumnSpec read(GeneratorTable& table, std::vector<ColumnSpec>&) {
    const TableReader& r = table.reader();
    ColumnSpec s;
    s.drums = integer_in(r, "drums", s.drums, 1, 1000);
    s.radius = r.number("radius", s.radius, Range::positive);
    s.sides = integer_in(r, "sides", s.sides, 4, 128);
    if (r.has("height") && r.has("drum_heights"))
      r.fail("drum_heights", "give height (equal drums) or drum_heights, not both");
    s.height = r.number("height", s.height, Range::positive);
    if (const toml::node* n = r.table().get("drum_heights")) {
      const auto* arr = n->as_array();
      if (!arr) r.fail("drum_heights", "must be an array of heights, one per drum, bottom up (got " + describe(*n) + ")");
      if (arr->empty()) r.fail("drum_heights", "must list at least one drum's height (or give height)");
      for (std::size_t i = 0; i < arr->size(); ++i) {
        const toml::node& e = *arr->get(i);
        const std::string p = indexed(r.key_path("drum_heights"), i + 1);
        double v = 0;
        if (const auto* f = e.as_floating_point())
          v = f->get();
        else if (const auto* k = e.as_integer())
          v = static_cast<double>(k->get());
        else
          r.deck().fail(p, &e, "must be a number (got " + describe(e) + ")");
        if (!(std::isfinite(v) && v > 0)) r.deck().fail(p, &e, "must be > 0 (got " + format_number(v) + ")");
        s.drum_heights.push_back(v);
      }
      if (!r.has("drums")) s.drums = static_cast<int>(s.drum_heights.size());
    }
    s.plinth_height = r.number("plinth_height", s.plinth_height, Range::positive);
    s.plinth_width = r.number("plinth_width", s.plinth_width, Range::positive);
    s.capital = r.choice<ColumnCapital>("capital",
                                        {{"none", ColumnCapital::none},
                                         {"abacus", ColumnCapital::abacus},
                                         {"frustum", ColumnCapital::frustum}},
                                        s.capital);
    s.capital_width = r.number("capital_width", s.capital_width, Range::positive);
    s.capital_height = r.number("capital_height", s.capital_height, Range::positive);
    s.base_width = r.number("base_width", s.base_width, Range::positive);
    s.base_thickness = r.number("base_thickness", s.base_thickness, Range::positive);
    s.origin = r.vec3("origin").value_or(s.origin);
    return s;
  }

  static ColumnModel build(const ColumnSpec& s) { return build_column(s); }
};

// All the [[column]] tables of a deck together build at most 20000 blocks:
// a short deck cannot ask for millions.
const RegisteredSection registered(generator_section<ColumnSection>());

}  // namespace

}  // namespace polydem
