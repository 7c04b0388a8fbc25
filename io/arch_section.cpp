// [[arch]]: arches, barrel vaults and arcades of structures/arch.hpp, one per
// table. Each table's `name` prefixes its blocks' names ("nave_voussoir03"),
// so several arches in one deck stay apart; the blocks' groups say what they
// are ("voussoir", "pier", "abutment", "base") and the voussoirs' and piers'
// `course` their ring or course.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[[arch]]`

Arches of voussoirs with radial joints, barrel vaults and arcades
(`structures/arch.hpp`; what each block is, pictures and the verification:
docs/structures.md, "Arches"). Each `[[arch]]` table builds one arch (or one
arcade of `spans` arches); a deck may hold several. The blocks are appended
after any `[[block]]` tables, named `NAME_…` with the table's `name`:
`NAME_voussoirVV` (VV from 00 at the left springing), with `spanS_` and
`ringR_` before it when there are several spans or rings, `NAME_abutmentI`,
`NAME_pierI` (`NAME_pierI_courseC` with several courses; I from 0 at −x) and
`NAME_base`. Their `group` is `voussoir`, `abutment`, `pier` or `base`;
a voussoir's `course` is its ring, a pier block's its course. Two tables
whose blocks would share a name are an error.

Frame: x along the span (`direction`), z up, y along the arch's axis; the
origin is the middle of the springing line (of the whole arcade) at
mid-depth. Every voussoir is the quadrilateral of its two joints' ends
extruded over its ring's depth: the intrados and extrados arcs are replaced by
chords, so the voussoirs fill the polygonal ring through the joints exactly.

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `name` | string | – | `"arch"` (`"archN"` when the deck has several) | Prefix of the blocks' names; must not be empty. |
| `shape` | string | – | `"circular"` | `"circular"` (one circle, any `embrace`), `"segmental"` (by `span` and `rise`) or `"pointed"` (two centres, by `span` and `pointedness`). |
| `span` | float | m | `2` | Clear span between the springings at the intrados; > 0. A circular arch takes `span` or `radius`, not both. |
| `radius` | float | m | from `span` | Circular only: the intrados radius R; > 0. span = 2 R sin(embrace/2). |
| `embrace` | float | deg | `180` | Circular only: the arc's angle, in (0, 360): 180 a semicircle on the springing line, less a segmental arch, more a horseshoe. |
| `rise` | float | m | required | Segmental only: the intrados rise from the springing line to the crown, in (0, span/2). |
| `pointedness` | float | – | `1` | Pointed only: each arc's centre lies on the springing line at c = pointedness × span/2 from the middle, on the far side (radius span/2 + c); 1 the equilateral arch, < 1 a drop arch, > 1 a lancet. In (0, 2]. |
| `voussoirs` | integer | – | `9` | Voussoirs per ring, in [3, 1000], of equal angle (pointed: per arc, half each; an even count puts a vertical crown joint at the apex, an odd one a keystone with flat chords under and over the apex). |
| `thickness` | float | m | `0.3` | Ring thickness t along the radius; > 0 and less than the intrados radius. |
| `depth` | float | m | `1` | Width of the arch along its axis (all rings together); > 0. |
| `rings` | integer | – | `1` | A barrel vault: rings of equal depth along the axis, in [1, 200]. Odd rings are shifted by half a voussoir (`voussoirs` + 1 voussoirs, a half one at each springing). |
| `spans` | integer | – | `1` | Arches side by side along x, `pier_width` apart, sharing their interior supports; in [1, 50]. |
| `supports` | string | – | `"abutments"` | `"abutments"`: a fixed block under each springing; `"piers"`: free piers in `pier_courses` courses on one fixed base slab; `"base"`: one fixed slab under the arch (horizontal springing joints only: semicircular or pointed arches). A horseshoe arch takes abutments. |
| `pier_width` | float | m | `2 × thickness` | Width of each support along the span, its inner face flush with the intrados springing; at least the springing joint's horizontal run t cos θ (θ its angle above the horizontal), twice that for an interior pier. Not for horseshoe arches (their abutments are as wide as the springing joint). |
| `pier_height` | float | m | `span / 2` | Height of the abutments or piers below the springing line; > 0. Not with `supports = "base"`. |
| `pier_courses` | integer | – | `1` | Piers only: courses of equal height, in [1, 100]. |
| `base_thickness` | float | m | `thickness` | Piers or base: thickness of the fixed base slab, which reaches half a pier width beyond what it carries on every side; > 0. |
| `support_motion` | string | – | `"fixed"` | Motion of the abutments or the base slab: `"fixed"` or `"kinematic"` (moves with the ground motion when `applied_as = "kinematic"`). |
| `origin` | [x, y, z] | m | `[0, 0, 0]` | Where the middle of the springing line goes. |
| `direction` | [x, y, z] | – | `[1, 0, 0]` | The span's direction; its horizontal part is used (must not be zero). |
| `density` | float | kg/m³ | `2600` | Density of every block of the table; > 0. |

A geometry that cannot be built (a voussoir count below 3, a ring thicker
than the radius, an embrace of 360°, a pier too narrow for its springing
joints, ...) is an error naming the `[[arch]]` key responsible. Spans run
from 1 mm to 100 km; one table builds at most about 5000 blocks and all the
`[[arch]]` tables of a deck at most 20000 (a short deck cannot ask for
millions by accident).
*/
#include "io/generators.hpp"

#include "structures/arch.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kArchKeys[] = {
    "name",        "shape",       "span",         "radius",        "embrace",      "rise",
    "pointedness", "voussoirs",   "thickness",    "depth",         "rings",        "spans",
    "supports",    "pier_width",  "pier_height",  "pier_courses",  "base_thickness", "support_motion",
    "origin",      "direction",   "density"};

// A key that the chosen shape or supports do not use is an error, not a
// silent no-op.
void refuse(const TableReader& r, std::string_view key, const std::string& why) {
  if (r.has(key)) r.fail(key, why);
}

struct ArchSection {
  using Spec = ArchSpec;

  static constexpr GeneratorRules rules{.section = "arch", .keys = kArchKeys, .order = 40, .single = false,
                                        .naming = Naming::prefix, .motion_key = "support_motion",
                                        .grouping = Grouping::kind, .group_by = {}, .max_blocks = 20000};

  static ArchSpec read(GeneratorTable& table, std::vector<ArchSpec>&) {
    const TableReader& r = table.reader();
    ArchSpec s;
    s.shape = r.choice<ArchShape>("shape",
                                  {{"circular", ArchShape::circular},
                                   {"segmental", ArchShape::segmental},
                                   {"pointed", ArchShape::pointed}},
                                  s.shape);
    const std::string shape_name = r.string("shape").value_or("circular");
    const std::string not_for = "is not used by shape = \"" + shape_name + "\"";
    switch (s.shape) {
      case ArchShape::circular:
        refuse(r, "rise", not_for + " (a segmental arch: shape = \"segmental\")");
        refuse(r, "pointedness", not_for + " (shape = \"pointed\")");
        if (r.has("span") && r.has("radius"))
          r.fail("radius", "give span or radius, not both (span = 2 radius sin(embrace/2))");
        s.radius = r.number("radius", 0.0, Range::positive);
        s.span = r.number("span", r.has("radius") ? 0.0 : 2.0, Range::positive);
        s.embrace = r.number("embrace", s.embrace, Range::positive);
        break;
      case ArchShape::segmental:
        refuse(r, "radius", not_for + ": a segmental arch is given by span and rise");
        refuse(r, "embrace", not_for + ": a segmental arch is given by span and rise");
        refuse(r, "pointedness", not_for);
        s.span = r.number("span", 2.0, Range::positive);
        if (!r.has("rise")) r.missing("rise", "a segmental arch needs its rise (intrados, springing line to crown)");
        s.rise = r.number("rise", 0.0, Range::positive);
        break;
      case ArchShape::pointed:
        refuse(r, "radius", not_for + ": a pointed arch is given by span and pointedness");
        refuse(r, "embrace", not_for);
        refuse(r, "rise", not_for);
        s.span = r.number("span", 2.0, Range::positive);
        s.pointedness = r.number("pointedness", s.pointedness, Range::positive);
        break;
    }
    s.voussoirs = integer_in(r, "voussoirs", s.voussoirs, 3, 1000);
    s.thickness = r.number("thickness", s.thickness, Range::positive);
    s.depth = r.number("depth", s.depth, Range::positive);
    s.rings = integer_in(r, "rings", s.rings, 1, 200);
    s.spans = integer_in(r, "spans", s.spans, 1, 50);
    s.supports = r.choice<ArchSupports>("supports",
                                        {{"abutments", ArchSupports::abutments},
                                         {"piers", ArchSupports::piers},
                                         {"base", ArchSupports::base}},
                                        s.supports);
    if (s.supports != ArchSupports::piers)
      refuse(r, "pier_courses", "only piers have courses (supports = \"piers\")");
    if (s.supports == ArchSupports::base)
      refuse(r, "pier_height", "there are no piers on a fixed base (supports = \"base\")");
    if (s.supports == ArchSupports::abutments)
      refuse(r, "base_thickness", "abutments stand on nothing: there is no base slab (supports = \"abutments\")");
    s.pier_width = r.number("pier_width", 0.0, Range::positive);
    s.pier_height = r.number("pier_height", 0.0, Range::positive);
    s.pier_courses = integer_in(r, "pier_courses", s.pier_courses, 1, 100);
    s.base_thickness = r.number("base_thickness", 0.0, Range::positive);
    s.origin = r.vec3("origin").value_or(s.origin);
    s.direction = r.vec3("direction").value_or(s.direction);
    return s;
  }

  static ArchModel build(const ArchSpec& s) { return build_arch(s); }
};

// All the [[arch]] tables of a deck together build at most 20000 blocks
// (each at most 5000): a short deck cannot ask for millions.
const RegisteredSection registered(generator_section<ArchSection>());

}  // namespace

}  // namespace polydem
