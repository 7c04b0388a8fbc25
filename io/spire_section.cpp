// [spire]: the octagonal spire of structures/spire.hpp (CGAL, exact), the
// materials its joints are made of (their series stiffness sets the joint
// defaults) and how its base block moves.
//
// The section's reference in docs/deck.md is the comment below
// (scripts/doc_tables.py copies it there).
/* docs/deck.md
## `[spire]`

The octagonal masonry spire of the paper (section 3.1), generated stone by
stone (`structures/spire.hpp`; the defaults and their sources are in
`examples/spire/README.md`). An empty `[spire]` section is the paper's
spire. The generated blocks are appended after any `[[block]]` tables.

Frame: z up, the spire's axis is the z axis, z = 0 is the bed of the first
course (the top of the base block), the apex is at z = `height`. Face k
(0..7) faces the horizontal direction at k·45° from +x, counter-clockwise
(face 0 faces +x, face 2 faces +y). The shell's outer surface is a regular
octagonal pyramid reaching the apex; its inner surface is the outer one moved
in by the wall thickness (measured horizontally, perpendicular to the face),
which varies linearly with z. The top `tip_height` is one solid block.

Blocks are named `base`, `tip`, `courseCC_faceF_stoneS` (course CC from 00 at
the bottom, face F, stone S from 0 at the face's clockwise corner) and, for a
stone that a window cuts, `courseCC_faceF_stoneS_pieceP`. A window's head is
built to carry the masonry above it under gravity (no tension, no cohesion):
a pointed head is an arch of voussoirs `courseCC_faceF_voussoirV` (V from 0
at the left springing; two with one segment per arc), which lean on each
other at the vertical crown joint and bear on the pieces beside the head
(the springers) through inclined joints normal to the arch; a flat head is a
lintel `courseCC_faceF_lintel` spanning the opening and bearing on both
jambs. The head blocks run from the springing (flat: the head) to the first
bed joint at least half a course above the head, and take the `course` of
the lowest course they span; in those courses no vertical joint lies over
the head (details: `examples/spire/README.md`). Their `course` is the
course index (the tip's is the number of courses; the base has none).
Their `group` is `base`, `tip`, or the course as `courseCC` (stones, window
pieces and head blocks alike).

| Key | Type | Unit | Default | Meaning |
|---|---|---|---|---|
| `height` | float | m | `9.4` | Height of the modelled section, base to apex; must be > 0. |
| `base_inradius` | float | m | `1.064` | Inradius (apothem) of the wall's mid-surface at z = 0: the distance from the axis to the middle of the wall, perpendicular to a face. It is the r_b of eq. 1 and 2 (1.064 m gives eq. 2's λ = 0.192). Must be > 0. |
| `wall_thickness` | float | m | `0.25` | Wall thickness at z = 0, horizontal, perpendicular to the face; in (0, 2·base_inradius). |
| `wall_thickness_top` | float | m | `0.15` | Wall thickness at the top of the shell (z = height − tip_height); the shell must stay hollow up to there. Must be > 0. |
| `course_height` | float | m | `0.3` | Nominal course height; the number of courses is the nearest whole number to (height − tip_height)/course_height, and the pitch is adjusted to fit. Must be > 0. |
| `tip_height` | float | m | `3.4` | Height of the solid tip (one rigid block); in (0, height). |
| `stones_per_face` | integer | – | `2` | Stones per face per course, in [1, 64] (staggered courses have one more: half stones at the corners). Courses x 8 x stones_per_face must stay at most 5000 (a deck cannot ask for millions of stones by accident). |
| `joint_pattern` | string | – | `"aligned_above_windows"` | `"staggered"`: odd courses shifted by half a stone; `"aligned"`: straight vertical joints; `"aligned_above_windows"`: staggered, but on window faces the joints continue the jambs vertically from the sill's course up (while the stones beside them keep a quarter of a nominal stone width), as in the paper's model. |
| `corner_stones` | string | – | `"halves"` | What the shifted (odd) courses of a staggered pattern put at each corner of the octagon. `"halves"`: a half stone on each side of the corner's mitre plane (the lightest stones of the model near the top, about 9 kg, which set the critical time step). `"merged"`: each half stone merged with its neighbour in the face (with two stones per face, one stone from mitre to mitre), so that no stone is narrower than a nominal one; the courses still bridge the joints below. Needs `stones_per_face` ≥ 2; changes nothing with `joint_pattern = "aligned"` (no shifted courses). |
| `window_faces` | [integer, ...] | – | `[0, 2, 4, 6]` | Faces (0..7, each at most once) with one window each; `[]` for none. |
| `window_sill` | float | m | `0.3` | Height of the sill; must be ≥ 0. |
| `window_width` | float | m | `0.3` | Width between the jambs (the window is centred on its face); must fit in the face at the inner surface at the head. |
| `window_head` | float | m | `1.5` | Height of the top of the opening (the apex of a pointed head); above the sill, at most height − tip_height. |
| `window_head_shape` | string | – | `"pointed"` | `"pointed"` (equilateral arch, rise = width·√3/2, which must fit above the sill; built of voussoirs) or `"flat"` (a lintel bearing on both jambs over half the wall left beside the opening). |
| `window_arch_segments` | integer | – | `1` | Straight segments per arc of a pointed head, in [1, 64]: one voussoir above each, between joints normal to the arch. More segments draw a rounder arch but give smaller voussoirs, which can lower the critical time step. |
| `base_thickness` | float | m | `0.3` | Thickness of the base block: a solid octagonal slab under course 0 with the shell's outer outline at z = 0. `0` = no base block. Must be ≥ 0. |
| `base_apothem` | float | m | `0` | Outer apothem (centre to face) of the base block's octagon. `0` = the shell's outer outline at z = 0. A wider base is a platform (the top of the tower) on which stones that fall off the spire come to rest; `examples/spire/pulse.toml` uses 60 m so that a collapse ends with the stones on it. Must be 0 or at least the shell's outer apothem at z = 0 (1.189 m for the defaults). |
| `origin` | [x, y, z] | m | `[0, 0, 0]` | Where the spire's frame origin (its axis at the bed of course 0) stands in the world: every block, the base block too, is moved by it. To stand the spire on a `[[tower]]`, give the tower's top (its `origin` plus `height` in z) and `base_thickness = 0`: the spire's first course then rests on the tower's top course (the spire's shell, outer apothem `base_inradius` + `wall_thickness`/2, must lie on the tower's wall). `polydem analytic` and `dem-frequency` work in the spire's own frame. |
| `base_motion` | string | – | `"fixed"` | Motion of the base block: `"fixed"` or `"kinematic"` (moves with the ground motion when `applied_as = "kinematic"`). |
| `density` | float | kg/m³ | `2600` | Density of every generated block (Table 1); must be > 0. |
| `stone_youngs_modulus` | float | Pa | `30e9` | E_stone (Table 1), for the joint stiffness; must be > 0. |
| `mortar_youngs_modulus` | float | Pa | `10e9` | E_mortar (Table 1), for the joint stiffness; must be > 0. |
| `mortar_thickness` | float | m | `0.01` | Mortar joint thickness t (section 3.1); in [0, course pitch). |
| `shear_stiffness_ratio` | float | – | `0.4` | ks/kn used when `[joint]` gives no `shear_stiffness`; must be > 0. |

Unless `[joint]` gives `normal_stiffness`, the joints get stone and mortar in
series over one course pitch h: 1/kn = (h − t)/E_stone + t/E_mortar
(93.75 GPa/m for the defaults; Table 1 prints 98 GPa/m). A geometry that
cannot be built (a window wider than its face, a wall that fills the spire
before the tip, ...) is an error naming the `[spire]` key responsible.
*/
#include "io/generators.hpp"

#include "core/materials.hpp"
#include "structures/spire.hpp"

namespace polydem {

namespace {

using namespace deck_reader;

constexpr std::string_view kSpireKeys[] = {
    "height",           "base_inradius",         "wall_thickness",      "wall_thickness_top",
    "course_height",    "tip_height",            "stones_per_face",     "joint_pattern",  "corner_stones",
    "window_faces",     "window_sill",           "window_width",        "window_head",
    "window_head_shape", "window_arch_segments", "base_thickness",      "base_apothem",        "base_motion",
    "density",          "stone_youngs_modulus",  "mortar_youngs_modulus", "mortar_thickness",
    "shear_stiffness_ratio", "origin"};

struct SpireSection {
  struct Spec {
    SpireSpec spire;
    Vec3 origin = Vec3::Zero();  // where the spire's frame origin (the axis at the bed of course 0) stands
  };

  static constexpr GeneratorRules rules{.section = "spire", .keys = kSpireKeys, .order = 10, .single = true,
                                        .naming = Naming::none, .motion_key = "base_motion",
                                        .grouping = Grouping::course, .group_by = {}, .max_blocks = 0};

  static Spec read(GeneratorTable& table, std::vector<Spec>&) {
    const TableReader& r = table.reader();
    const Deck& deck = r.deck();
    Spec out;
    SpireSpec& s = out.spire;
    s.height = r.number("height", s.height, Range::positive);
    s.base_inradius = r.number("base_inradius", s.base_inradius, Range::positive);
    s.wall_thickness = r.number("wall_thickness", s.wall_thickness, Range::positive);
    s.wall_thickness_top = r.number("wall_thickness_top", s.wall_thickness_top, Range::positive);
    s.course_height = r.number("course_height", s.course_height, Range::positive);
    s.tip_height = r.number("tip_height", s.tip_height, Range::positive);
    s.stones_per_face = integer_in(r, "stones_per_face", s.stones_per_face, 1, 64);
    s.joint_pattern = r.choice<SpireJointPattern>("joint_pattern",
                                                  {{"staggered", SpireJointPattern::staggered},
                                                   {"aligned", SpireJointPattern::aligned},
                                                   {"aligned_above_windows", SpireJointPattern::aligned_above_windows}},
                                                  s.joint_pattern);
    s.corner_stones = r.choice<SpireCornerStones>(
        "corner_stones", {{"halves", SpireCornerStones::halves}, {"merged", SpireCornerStones::merged}}, s.corner_stones);
    if (const toml::node* n = r.table().get("window_faces")) {
      const auto* arr = n->as_array();
      if (!arr) r.fail("window_faces", "must be an array of face indices 0..7 (got " + describe(*n) + ")");
      s.window_faces.clear();
      for (std::size_t i = 0; i < arr->size(); ++i) {
        const toml::node& e = *arr->get(i);
        const auto* v = e.as_integer();
        const std::string path = indexed(r.key_path("window_faces"), i + 1);
        if (!v) deck.fail(path, &e, "must be an integer face index 0..7 (got " + describe(e) + ")");
        if (v->get() < 0 || v->get() > 7)
          deck.fail(path, &e, "face indices are 0..7, face 0 facing +x (got " + std::to_string(v->get()) + ")");
        if (std::find(s.window_faces.begin(), s.window_faces.end(), v->get()) != s.window_faces.end())
          deck.fail(path, &e, "face " + std::to_string(v->get()) + " is listed twice (one window per face)");
        s.window_faces.push_back(static_cast<int>(v->get()));
      }
    }
    s.window_sill = r.number("window_sill", s.window_sill, Range::non_negative);
    s.window_width = r.number("window_width", s.window_width, Range::positive);
    s.window_head = r.number("window_head", s.window_head, Range::positive);
    s.window_head_shape = r.choice<WindowHead>("window_head_shape",
                                               {{"pointed", WindowHead::pointed}, {"flat", WindowHead::flat}},
                                               s.window_head_shape);
    s.window_arch_segments = integer_in(r, "window_arch_segments", s.window_arch_segments, 1, 64);
    s.base_thickness = r.number("base_thickness", s.base_thickness, Range::non_negative);
    s.base_apothem = r.number("base_apothem", s.base_apothem, Range::non_negative);
    if (r.has("base_apothem") && s.base_thickness == 0)
      r.fail("base_apothem", "there is no base block (base_thickness = 0)");
    if (r.has("base_motion") && s.base_thickness == 0)
      r.fail("base_motion", "there is no base block (base_thickness = 0)");
    out.origin = r.vec3("origin").value_or(out.origin);
    return out;
  }

  static SpireModel build(const Spec& s) { return build_spire(s.spire); }

  // The spire stands at `origin`; its materials set the joints' defaults.
  static void finish(const GeneratorTable& table, const Spec& s, SpireModel& model, Generated& out) {
    const TableReader& r = table.reader();
    if (!s.origin.isZero())
      for (GeneratedBlock& b : model.blocks) b.shape = transformed(b.shape, Mat3::Identity(), s.origin);
    // Table 1: E_stone 30 GPa, E_mortar 10 GPa; section 3.1: 1 cm of mortar.
    const double e_stone = r.number("stone_youngs_modulus", 30e9, Range::positive);
    const double e_mortar = r.number("mortar_youngs_modulus", 10e9, Range::positive);
    const double mortar = r.number("mortar_thickness", 0.01, Range::non_negative);
    if (!(mortar < model.course_height))
      r.fail("mortar_thickness", "must be less than the course pitch " + format_number(model.course_height) +
                                     " m (got " + format_number(mortar) + ")");
    JointDefaults joint;
    joint.normal_stiffness = series_joint_normal_stiffness(model.course_height, mortar, e_stone, e_mortar);
    joint.shear_ratio = r.number("shear_stiffness_ratio", joint.shear_ratio, Range::positive);
    out.joint = joint;
    out.specs.spire = s.spire;
  }
};

const RegisteredSection registered(generator_section<SpireSection>());

}  // namespace

}  // namespace polydem
