// [[tower]]: hollow square or octagonal masonry towers
// (structures/tower.hpp), one per table, each with its openings as
// [[tower.opening]] tables. Block names start with the tower's name; groups
// come from what each block is (group_by) with an optional prefix.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[[tower]]`

Hollow square or octagonal masonry towers, generated stone by stone
(`structures/tower.hpp`; pictures in `docs/structures.md`). Each `[[tower]]`
table is one tower; a deck may have several; their blocks are appended after
any `[[block]]` tables. A `[spire]` stands on a tower with `[spire] origin`
(above).

Frame: z up; the axis is the vertical through `origin`, whose z is the bed of
course 0. Face k (0..3 or 0..7) faces azimuth k·360°/sides from +x,
counter-clockwise (face 0 faces +x; an octagonal tower's faces are the
spire's). The courses are all height / courses high, courses the nearest
whole number to height / course_height. The corners interlock course by
course: at each corner one face's end stone runs past the corner to the other
face's outer surface (a square tower's quoins), even faces in even courses,
odd faces in odd ones. A face has `stones_per_face` stones in the courses in
which it owns its corners and one more in the others (half stones beside the
corners, less what the corners take), so the vertical joints of one course
sit half a stone from the next's; a joint closer than a quarter stone to the
inner corner is dropped. Openings are those of `[[wall.opening]]`, centred on
their faces, with the nominal stone (the mid-wall face width /
stones_per_face) for the unit; one opening per face.

Blocks are named `NAME_courseCC_faceF_stoneS` (S from the face's clockwise
end), `..._pieceP` beside or under an opening, `NAME_faceF_openingK_lintel`
and `NAME_faceF_openingK_voussoirJ`. Their `group` is `group` (a prefix)
followed by, according to `group_by`: `courseCC`, `faceF`, the kind
(`stone`, `jamb`, `lintel`, `voussoir`) or the tower's name.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `name` | string | – | `"towerN"` | The tower's name (N: its index from 1), the start of every block's name; unique among the towers, no spaces. |
| `shape` | string | – | `"octagonal"` | `"square"` or `"octagonal"`. |
| `origin` | [x, y, z] | m | `[0, 0, 0]` | The axis at the bed of course 0. |
| `outer_apothem` | float | m | `1.5` | From the axis to the outer face (a square tower: half its outer width); must be > 0. |
| `wall_thickness` | float | m | `0.5` | Between the outer and the inner faces; less than 0.9 × outer_apothem. |
| `height` | float | m | `6` | From the bed of course 0 to the top; must be > 0. |
| `course_height` | float | m | `0.3` | Nominal; the course height is height / courses. Must be > 0 and at most height. |
| `stones_per_face` | integer | – | `2` | Stones per face in the courses in which the face owns its corners, in [1, 32]. |
| `density` | float | kg/m³ | `2600` | Density of every block of the tower; must be > 0. |
| `group_by` | string | – | `"course"` | `"course"`, `"face"`, `"kind"` or `"tower"` (above). |
| `group` | string | – | `""` | Prefix of every group name of this tower. |
| `opening` | tables | – | none | The tower's openings, one `[[tower.opening]]` table each (below). |

## `[[tower.opening]]`

An opening through the wall of the faces listed, centred on each, in the
`[[tower]]` written above it: the rules of `[[wall.opening]]` (lintel or
semicircular arch of voussoirs, the head's extent, the sill and head at a bed
joint or a quarter course above one, half a course of wall above the head);
the opening with its head's extent must leave a quarter stone at each end of
the face's inner width.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `faces` | [integer, ...] | – | required | The faces (0..sides−1) with this opening; each face at most one opening. |
| `sill` | float | m | `0` | Height of the sill above the tower's base; must be ≥ 0. |
| `width` | float | m | required | Between the jambs; must be > 0. |
| `height` | float | m | required | From the sill to the top of the opening (an arch's crown); for an arch at least width/2. |
| `head` | string | – | `"lintel"` | `"lintel"` or `"arch"`. |
| `bearing` | float | m | half a nominal stone | Lintel only: its length on each jamb; at least a quarter stone. |
| `voussoirs` | integer | – | `7` | Arch only: the number of voussoirs, in [3, 64]. |
| `ring` | float | m | half a nominal stone | Arch only: how far the voussoirs reach beyond each jamb; at least a quarter stone. |
*/
#include "io/generators.hpp"

#include "structures/tower.hpp"

#include <algorithm>

namespace polydem {

namespace {

using namespace deck_reader;

// The [[tower]] keys, then its [[tower.opening]] keys as "opening.KEY".
constexpr std::string_view kTowerKeys[] = {
    "name",          "shape",          "origin",       "outer_apothem",     "wall_thickness", "height",
    "course_height", "stones_per_face", "density",     "group_by",          "group",          "opening",
    "opening.faces", "opening.sill",   "opening.width", "opening.height",   "opening.head",   "opening.bearing",
    "opening.voussoirs", "opening.ring"};

constexpr std::pair<std::string_view, Grouping> kTowerGroupings[] = {
    {"course", Grouping::course}, {"face", Grouping::face}, {"kind", Grouping::kind}, {"tower", Grouping::section}};

struct TowerSection {
  using Spec = TowerSpec;

  static constexpr GeneratorRules rules{.section = "tower", .keys = kTowerKeys, .order = 30, .single = false,
                                        .naming = Naming::owned, .motion_key = "", .grouping = Grouping::course,
                                        .group_by = kTowerGroupings, .max_blocks = 0};

  static TowerSpec read(GeneratorTable& table, std::vector<TowerSpec>&) {
    const TableReader& r = table.reader();
    TowerSpec s;
    s.name = table.name;
    s.sides = r.choice<int>("shape", {{"square", 4}, {"octagonal", 8}}, s.sides);
    s.origin = r.vec3("origin").value_or(s.origin);
    s.outer_apothem = r.number("outer_apothem", s.outer_apothem, Range::positive);
    s.wall_thickness = r.number("wall_thickness", s.wall_thickness, Range::positive);
    s.height = r.number("height", s.height, Range::positive);
    s.course_height = r.number("course_height", s.course_height, Range::positive);
    s.stones_per_face = integer_in(r, "stones_per_face", s.stones_per_face, 1, 32);
    open_openings(rules, table, {"faces", "width", "height"}, "an opening needs faces, width and height");
    for (std::size_t i = 1; i < table.readers.size(); ++i) {
      const TableReader& o = table.readers[i];
      TowerOpening op;
      const toml::node* fn = o.table().get("faces");
      const auto* arr = fn->as_array();
      if (!arr) o.fail("faces", "must be an array of face indices (got " + describe(*fn) + ")");
      for (std::size_t j = 0; j < arr->size(); ++j) {
        const toml::node& e = *arr->get(j);
        const auto* v = e.as_integer();
        const std::string path = indexed(o.key_path("faces"), j + 1);
        if (!v) r.deck().fail(path, &e, "must be an integer face index (got " + describe(e) + ")");
        if (v->get() < 0 || v->get() >= s.sides)
          r.deck().fail(path, &e,
                        "face indices are 0.." + std::to_string(s.sides - 1) + ", face 0 facing +x (got " +
                            std::to_string(v->get()) + ")");
        op.faces.push_back(static_cast<int>(v->get()));
      }
      read_opening(o, op);
      s.openings.push_back(op);
    }
    return s;
  }

  static TowerModel build(const TowerSpec& s) { return build_tower(s); }

  static std::string key_of(const GeneratorTable&, const GeneratorSpecError& e) {
    return e.field == "sides" ? "shape" : e.field;
  }
};

const RegisteredSection registered(generator_section<TowerSection>());

}  // namespace

}  // namespace polydem
