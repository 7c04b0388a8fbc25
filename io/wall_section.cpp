// [[wall]]: straight walls of brick or stone units (structures/wall.hpp), one
// per table, each with its openings as [[wall.opening]] tables. Block names
// start with the wall's name, so several walls live in one deck; groups
// come from what each block is (group_by) with an optional prefix.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[[wall]]`

Straight walls of brick or stone units, generated unit by unit
(`structures/wall.hpp`; pictures in `docs/structures.md`). Each `[[wall]]`
table is one wall; a deck may have several. Their blocks are appended after
any `[[block]]` tables, wall by wall; a `[[block]]` is usually the fixed
ground they stand on.

Frame: the wall's own (u, v, z): u along the wall from its start (u = 0) to
its end (u = `length`), v across it from −thickness/2 to +thickness/2 (to the
left looking along u), z up from the bed of the first course. The world
point of (u, v, z) is `origin` + u·e_u + v·e_v + z·e_z, e_u at azimuth
`direction`. Units are dry (no mortar): neighbours touch on shared joint
planes, and the blocks' volumes sum to the wall's (minus its openings) to
round-off.

Bonds: `"stretcher"` (or `"running"`): every unit a stretcher, `leaves`
leaves side by side, odd courses shifted by half a unit with half units at
their ends; `"header"`: every unit a header across the wall (thickness =
unit length), odd courses shifted by half a header; `"english"`: stretcher
courses (two leaves) alternating with header courses shifted by a quarter
unit (a queen closer, half a header, at each end); `"flemish"`: header,
stretcher, header ... in every course, odd courses shifted by 1.5 headers so
that each header sits centred on a stretcher (three-quarter units at the
ends). English and Flemish bonds need `unit_width` = `unit_length`/2: two
stretchers side by side fill a header's length, or the bond cannot close
across the wall. The sliver rule: no piece of a course is shorter than a
quarter of the unit length: a shorter leftover at a wall's end joins its
neighbour, and a joint an opening needs moves an existing joint closer than
a quarter unit onto itself rather than leave a sliver.

Blocks are named `NAME_courseCC_leafL_unitI` (one unit of leaf L, 0 at
v = −thickness/2), `NAME_courseCC_unitI` (a block through the whole wall: a
header, a through-stone, a jamb stone), `..._pieceP` (a unit cut by an
opening) and `NAME_openingK_lintel`, `NAME_openingK_voussoirJ` (J from 0 at
the left springing). Their `course` is the course they lie in (a head
block's: the lowest). Their `group` is `group` (a prefix, default empty)
followed by, according to `group_by`: `courseCC`; `leafL` or `through`; the
kind (`unit`, `header`, `through_stone`, `jamb`, `lintel`, `voussoir`, `apex`, `closer`); or
the wall's name.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `name` | string | – | `"wallN"` | The wall's name (N: its index from 1), the start of every block's name; unique among the walls, no spaces. |
| `origin` | [x, y, z] | m | `[0, 0, 0]` | World point of the start of the wall's centre line at its base. |
| `direction` | float | degrees | `0` | Azimuth of the wall's length, from +x counter-clockwise. |
| `length` | float | m | `2` | Length along the wall; must be > 0 and at least one unit length. |
| `start` | [x, y, z] | m | – | Instead of `origin`, `direction` and `length`: the start of the centre line at the base. Needs `end`. |
| `end` | [x, y, z] | m | – | The end of the centre line at the base, at the height of `start`. |
| `corner_with` | string | – | – | Instead of `origin` and `direction` (or `start` and `end`): this wall starts at a corner of the earlier `[[wall]]` of that name, at a right angle, and the two interlock course by course: one wall's units run through the corner square in each course and the other stops at it (quoins), in the courses both walls have. Both walls have the same course height on the same base, and either both are stretcher bond walls (the earlier wall owns the corner in even courses, this one in odd ones) or each is an English, Flemish or header bond wall: then both have the same `unit_size` with unit width = unit length / 2 (both one unit length thick), and in the courses a wall owns it starts at the quoin with a quoin header and a queen closer (a quarter unit in the face, kind `closer`), then its bond; in the others it stops at the corner and lays its bond from it, so that the joints of consecutive courses stay a quarter unit apart at the quoin. This wall's bond is then turned by one course if needed so that the two own the corner in alternate courses, and each wall must reach two unit lengths beyond its corner squares. Other pairs are refused ("bonds that cannot close a corner"). The corner square is part of both lengths, so `length` here is measured from the earlier wall's outer face. Openings keep a quarter unit clear of the corner. docs/structures.md ("Wall corners") shows English and Flemish corners. |
| `corner_at` | string | – | `"end"` | With `corner_with`: at the earlier wall's `"end"` or `"start"`; each end has at most one corner. |
| `turn` | string | – | `"left"` | With `corner_with`: this wall runs to the `"left"` (+v) or `"right"` (−v) of the earlier wall. |
| `height` | float | m | `1.5` | Height of the wall; the number of courses is the nearest whole number to height / unit height, and the course height is height / courses. Must be at least one unit height. |
| `courses` | integer | – | – | Instead of `height`: the number of courses (height = courses × unit height), in [1, 2000]. |
| `unit_size` | [length, height, width] | m | `[0.4, 0.2, 0.2]` | The unit: length along the wall (a stretcher's face), height, width across the wall (a stretcher's depth, a header's face width). A header is `length` deep. |
| `bond` | string | – | `"stretcher"` | `"stretcher"` (= `"running"`), `"header"`, `"english"` or `"flemish"` (above). |
| `leaves` | integer | – | `1` | Leaves side by side (stretcher bond only), in [1, 16]; the wall is leaves × unit width thick. The leaves share their vertical joints. |
| `gable_height` | float | m | `0` | A gable on top: the wall rises from `height` at its ends to `height` + gable_height at its middle. The courses continue above `height` at the same course height, each starting and ending where the slopes cross its bed (the sliver rule there) and its end units cut by the slopes; the top is one apex stone `NAME_apex` (kind `apex`), a triangle from the lowest bed joint at which the gable is less than 1.5 units wide. Openings stay below `height`. In [0, 100·height]. |
| `through_every` | integer | – | `0` | Stretcher bond with at least 2 leaves: every Nth unit of a course is one through-stone crossing all leaves, shifted by N/2 units in odd courses so that they stagger; `0` = none. |
| `density` | float | kg/m³ | `2600` | Density of every block of the wall; must be > 0. |
| `group_by` | string | – | `"course"` | What the blocks' group says: `"course"`, `"leaf"`, `"kind"` or `"wall"` (above). |
| `group` | string | – | `""` | Prefix of every group name of this wall (e.g. `"front_"`). |
| `opening` | tables | – | none | The wall's openings, one `[[wall.opening]]` table each (below). |

## `[[wall.opening]]`

An opening through the whole wall, in the `[[wall]]` written above it. Its
head carries the masonry above it under gravity with no tension: a lintel
(one block spanning the opening and `bearing` onto each jamb, from the head
up to the first bed joint at least half a course above it) or a semicircular
arch of voussoirs (radius width/2, springing at sill + height − width/2) with
radial joints through the arch's centre, reaching from the intrados (one
straight chord per voussoir) up to the first bed joint at least half a course
above the crown and `ring` beyond each jamb. In the courses the head spans,
the masonry between its ends below the head becomes one jamb stone each side,
through the wall. Openings, each with its head's extent, must not overlap,
must leave a quarter unit between them and at the wall's ends, and must
leave half a course above the head; the sill and the head (an arch's
springing) must lie on a bed joint or at least a quarter course above one.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `position` | float | m | required | u of the left jamb (from the wall's start). |
| `sill` | float | m | `0` | Height of the sill above the wall's base; `0` is a door. Must be ≥ 0. |
| `width` | float | m | required | Between the jambs; must be > 0. |
| `height` | float | m | required | From the sill to the top of the opening (an arch's crown); must be > 0, and for an arch at least width/2. |
| `head` | string | – | `"lintel"` | `"lintel"` or `"arch"`. |
| `bearing` | float | m | half a unit length | Lintel only: its length on each jamb; at least a quarter unit. |
| `voussoirs` | integer | – | `7` | Arch only: the number of voussoirs, in [3, 64]. |
| `ring` | float | m | half a unit length | Arch only: how far the voussoirs reach beyond each jamb; at least a quarter unit. |
*/
#include "io/generators.hpp"

#include "structures/wall.hpp"

#include <cmath>
#include <numbers>

namespace polydem {

namespace {

using namespace deck_reader;

// The [[wall]] keys, then its [[wall.opening]] keys as "opening.KEY" (so
// that deck_keys() lists them as wall.opening.KEY, as docs/deck.md does).
constexpr std::string_view kWallKeys[] = {
    "name",    "origin",        "direction",      "start",           "end",          "length",
    "height",  "courses",       "unit_size",      "bond",            "leaves",       "through_every",
    "density", "group_by",      "group",  "gable_height", "corner_with", "corner_at", "turn",          "opening",         "opening.position", "opening.sill",
    "opening.width", "opening.height", "opening.head", "opening.bearing", "opening.voussoirs", "opening.ring"};

constexpr std::pair<std::string_view, Grouping> kWallGroupings[] = {
    {"course", Grouping::course}, {"leaf", Grouping::leaf}, {"kind", Grouping::kind}, {"wall", Grouping::section}};

// A wall as its table gives it, and where it meets an earlier wall.
struct WallTable {
  WallSpec spec;
  // A corner with an earlier wall: its name, at its end or start, turning left or right.
  std::string corner_with;
  bool corner_at_end = true;
  bool turn_left = true;
};

WallTable read_wall(const GeneratorRules& rules, GeneratorTable& table) {
  const TableReader& r = table.reader();
  WallTable out;
  WallSpec& s = out.spec;
  s.name = table.name;

  // Where the wall stands: origin + direction + length, start + end, or at
  // a corner of an earlier wall (placed by WallSection::read).
  if (r.has("corner_with")) {
    for (const char* k : {"origin", "direction", "start", "end"})
      if (r.has(k)) r.fail(k, "a wall at a corner (corner_with) is placed by the wall it meets: give only its length");
    out.corner_with = *r.string("corner_with");
    out.corner_at_end = r.choice<bool>("corner_at", {{"end", true}, {"start", false}}, true);
    out.turn_left = r.choice<bool>("turn", {{"left", true}, {"right", false}}, true);
    s.length = r.number("length", s.length, Range::positive);
  } else if (r.has("corner_at") || r.has("turn")) {
    r.fail(r.has("corner_at") ? "corner_at" : "turn", "applies with corner_with only");
  } else if (r.has("start") || r.has("end")) {
    for (const char* k : {"origin", "direction", "length"})
      if (r.has(k)) r.fail(k, "give either start and end, or origin, direction and length");
    if (!r.has("start")) r.missing("start", "end is given: the wall runs from start to end");
    if (!r.has("end")) r.missing("end", "start is given: the wall runs from start to end");
    const Vec3 a = *r.vec3("start"), b = *r.vec3("end");
    if (std::abs(a.z() - b.z()) > 1e-12 * (1 + std::abs(a.z())))
      r.fail("end", "must be at the height of start (z = " + format_number(a.z()) + "): walls stand on a level bed");
    const Vec3 d = b - a;
    if (!(d.norm() > 0)) r.fail("end", "must differ from start");
    s.origin = a;
    s.length = d.norm();
    s.direction = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
  } else {
    s.origin = r.vec3("origin").value_or(s.origin);
    s.direction = r.number("direction", s.direction, Range::any);
    s.length = r.number("length", s.length, Range::positive);
  }
  s.height = r.number("height", s.height, Range::positive);
  if (r.has("courses")) {
    s.courses = integer_in(r, "courses", s.courses, 1, 2000);
    if (r.has("height")) r.fail("courses", "give height or courses (height = courses × unit height), not both");
  }
  if (const auto u = r.numbers("unit_size", 3, "[length, height, width]")) {
    for (std::size_t i = 0; i < 3; ++i)
      if (!((*u)[i] > 0)) r.fail("unit_size", "every size must be > 0 (got " + format_number((*u)[i]) + ")");
    s.unit_length = (*u)[0];
    s.unit_height = (*u)[1];
    s.unit_width = (*u)[2];
  }
  if (s.courses > 0) s.height = s.courses * s.unit_height;
  s.bond = r.choice<WallBond>("bond",
                              {{"stretcher", WallBond::stretcher},
                               {"running", WallBond::stretcher},
                               {"header", WallBond::header},
                               {"english", WallBond::english},
                               {"flemish", WallBond::flemish}},
                              s.bond);
  s.leaves = integer_in(r, "leaves", s.leaves, 1, 16);
  s.through_every = integer_in(r, "through_every", s.through_every, 0, 1000);
  s.gable_height = r.number("gable_height", s.gable_height, Range::non_negative);

  open_openings(rules, table, {"position", "width", "height"}, "an opening needs position, width and height");
  for (std::size_t i = 1; i < table.readers.size(); ++i) {
    const TableReader& o = table.readers[i];
    WallOpening op;
    op.position = o.number("position", 0.0, Range::any);
    read_opening(o, op);
    s.openings.push_back(op);
  }
  return out;
}

// Wall b at a corner of the earlier wall a: b's frame from a's, and the
// corner's cuts on both (structures/wall.hpp, WallCorner).
void place_at_corner(const TableReader& r, WallTable& b, WallTable& a) {
  WallSpec& A = a.spec;
  WallSpec& B = b.spec;
  const bool a_running = A.bond == WallBond::stretcher, b_running = B.bond == WallBond::stretcher;
  if (a_running != b_running)
    r.fail("corner_with", "bonds that cannot close a corner: a stretcher bond wall turns a corner with another "
                          "stretcher bond wall, and English, Flemish and header bond walls with one another (" +
                              in_quotes(A.name) + " and this one)");
  if (!a_running) {
    // Quoin headers and queen closers: the units must be the same, two
    // headers side by side a unit length (both walls a unit length thick).
    const auto same = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)); };
    if (!same(A.unit_length, B.unit_length) || !same(A.unit_width, B.unit_width))
      r.fail("unit_size", "bonds that cannot close a corner: the quoin headers and closers interlock only between "
                          "units of the same length and width (" + format_number(B.unit_length) + " x " +
                              format_number(B.unit_width) + " m here, " + format_number(A.unit_length) + " x " +
                              format_number(A.unit_width) + " m in " + in_quotes(A.name) + ")");
    if (!same(2 * B.unit_width, B.unit_length))
      r.fail("unit_size", "bonds that cannot close a corner: a quoin header and queen closer fit only when two "
                          "headers side by side make a unit length (unit width = unit length / 2)");
  }
  const int na = A.courses > 0 ? A.courses : std::max(1, static_cast<int>(std::lround(A.height / A.unit_height)));
  const int nb = B.courses > 0 ? B.courses : std::max(1, static_cast<int>(std::lround(B.height / B.unit_height)));
  const double cha = A.height / na, chb = B.height / nb;
  if (std::abs(cha - chb) > 1e-9 * cha)
    r.fail("corner_with", "the courses cannot interlock: course height " + format_number(chb) + " m here, " +
                              format_number(cha) + " m in " + in_quotes(A.name));
  for (const WallCorner& k : A.corners)
    if (k.at_end == b.corner_at_end)
      r.fail("corner_at", std::string("wall ") + in_quotes(A.name) + " already has a corner at its " +
                              (b.corner_at_end ? "end" : "start"));
  const double ta = wall_thickness(A), tb = wall_thickness(B);
  const double th = A.direction * std::numbers::pi / 180.0;
  const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0);
  const double along = b.corner_at_end ? A.length - 0.5 * tb : 0.5 * tb;
  B.origin = A.origin + along * eu + (b.turn_left ? -0.5 : 0.5) * ta * ev;
  B.direction = A.direction + (b.turn_left ? 90.0 : -90.0);
  const int shared = std::min(na, nb);
  if (a_running) {
    // a's units run through the corner in even courses, b's in odd ones.
    A.corners.push_back({b.corner_at_end, tb, 1, shared});
    B.corners.push_back({false, ta, 0, shared});
    return;
  }
  // Each wall owns the corner square in the courses of its quoin parity
  // (quoin header and closer there) and stops at it in the others: b's
  // bond is turned by a course if that parity would be a's.
  B.course_shift = 0;
  if (quoin_parity(B) == quoin_parity(A)) B.course_shift = 1;
  A.corners.push_back({b.corner_at_end, tb, 1 - quoin_parity(A), shared});
  B.corners.push_back({false, ta, 1 - quoin_parity(B), shared});
}
struct WallSection {
  using Spec = WallTable;

  static constexpr GeneratorRules rules{.section = "wall", .keys = kWallKeys, .order = 20, .single = false,
                                        .naming = Naming::owned, .motion_key = "", .grouping = Grouping::course,
                                        .group_by = kWallGroupings, .max_blocks = 0};

  static WallTable read(GeneratorTable& table, std::vector<WallTable>& earlier) {
    WallTable w = read_wall(rules, table);
    if (!w.corner_with.empty()) {
      std::size_t j = 0;
      while (j < earlier.size() && earlier[j].spec.name != w.corner_with) ++j;
      if (j == earlier.size())
        table.reader().fail("corner_with", "no [[wall]] above this one is named " + in_quotes(w.corner_with));
      place_at_corner(table.reader(), w, earlier[j]);
    }
    return w;
  }

  static WallModel build(const WallTable& w) { return build_wall(w.spec); }

  // The deck key of a field: the unit's sizes are one key, a corner's
  // fields the corner's, and the length or height the key that gave it.
  static std::string key_of(const GeneratorTable& table, const GeneratorSpecError& e) {
    const TableReader& r = table.reader();
    std::string key = e.field;
    if (key == "unit_length" || key == "unit_height" || key == "unit_width") key = "unit_size";
    if ((key == "corners" || key == "course_shift") && r.has("corner_with")) key = "corner_with";
    if (e.opening >= 0) return key;
    if (key == "length" && !r.has("length") && r.has("end")) key = "end";
    if (key == "height" && !r.has("height") && r.has("courses")) key = "courses";
    return key;
  }
};

const RegisteredSection registered(generator_section<WallSection>());

}  // namespace

}  // namespace polydem
