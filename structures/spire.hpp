// The octagonal masonry spire of the paper (section 3.1), built stone by stone.
//
// Frame: z up, the spire axis is the z axis, z = 0 is the bed of the first
// course (the top of the base block), the apex is at z = height. Face k
// (k = 0..7) faces the horizontal direction at azimuth k·45° from +x,
// counter-clockwise, so face 0 faces +x, face 2 faces +y. Courses are
// numbered from 0 at the bottom; stones within a face from 0 at the face's
// clockwise (lower azimuth) corner.
//
// The shell is a frustum of a regular octagonal pyramid: the outer surface is
// one plane per face reaching the apex; the inner surface is one plane per face
// too, the wall thickness (measured horizontally, perpendicular to the face)
// varying linearly from `wall_thickness` at z = 0 to `wall_thickness_top` at
// the top of the shell, z = height - tip_height. Above that the solid tip is
// one block (the paper: "the top 3.4 m of spire is solid ... modelled as a
// single rigid block"). Every stone is the intersection of half-spaces: outer
// face plane, inner face plane, the two bed planes of its course, and at each
// side either a corner (mitre) plane — the vertical plane through the axis
// and the octagon's corner — or a vertical joint plane perpendicular to the
// face. A window is a prism through the wall, perpendicular to its face; a
// stone it cuts is replaced by the convex pieces left over (left and right of
// the jambs, below the sill). The head carries the masonry above it under
// gravity, without tension or cohesion:
//   pointed  voussoirs: one block above each straight segment of the arch,
//            between joints normal to the arch (at the springing normal to
//            the first segment, inclined; at the apex the vertical crown
//            joint where the two arcs lean on each other). The pieces beside
//            the head (the springers) get the matching inclined face.
//   flat     a lintel spanning the opening and bearing on both jambs.
// The head blocks span from the springing (flat: the head) to the first bed
// joint at least half a course above the head, so the crown joint is at
// least half a course tall and no bed joint cuts a voussoir; in those
// courses the face's vertical joints around the head are replaced by one
// joint each side at the edge of the head blocks. Above that,
// aligned_above_windows continues the jambs' joints as before.
//
// Sizes, defaults and their sources: examples/spire/README.md.
// No CGAL here; the builder (structures/spire.cpp) uses it through
// halfspace_intersection and convex_hull.
#pragma once

#include <string>
#include <vector>

#include "structures/generated_block.hpp"

namespace polydem {

// How vertical joints sit from one course to the next.
enum class SpireJointPattern {
  // Odd courses shifted by half a stone: stones_per_face stones in even
  // courses, stones_per_face + 1 in odd ones (half stones at the corners).
  staggered,
  // Every course has the joints of the even courses: straight vertical joints.
  aligned,
  // Staggered, except on the faces with a window: from the sill's course up,
  // the joints continue the window jambs vertically (the poor interlock above
  // the windows that the paper blames for its near-vertical crack) for as long
  // as the stones beside them keep at least a quarter of a nominal stone
  // width at the inner surface; above that, staggered again.
  aligned_above_windows,
};

enum class WindowHead { flat, pointed };

// What the shifted courses of a staggered pattern put at each corner.
enum class SpireCornerStones {
  // A half stone on each side of the corner's mitre plane: two small
  // pieces, the model's lightest stones near the top (9 kg at z ≈ 5.7 m for
  // the defaults), which set the critical time step.
  halves,
  // Each half stone merged with its neighbour in the face (a stone and a
  // half; with two stones per face, one stone from mitre to mitre): no
  // stone narrower than a nominal one, the courses still bridging the
  // joints below. Needs stones_per_face ≥ 2 (with one, merging would align
  // the joints); changes nothing under the aligned pattern (no shifted
  // courses).
  merged,
};

// All lengths in m. Defaults: the paper's spire (see examples/spire/README.md).
struct SpireSpec {
  double height = 9.4;             // modelled section, base to apex (paper 3.1)
  // Mid-wall inradius (apothem: distance from the axis to the middle of the
  // wall, perpendicular to a face) at z = 0. This is the r_b of eq. 1 and 2:
  // 1.064 m gives eq. 2's λ = 0.192 with H = 9.4 m.
  double base_inradius = 1.064;
  double wall_thickness = 0.25;      // at z = 0, horizontal, perpendicular to the face
  double wall_thickness_top = 0.15;  // at the top of the shell (z = height - tip_height)
  double course_height = 0.3;        // nominal; adjusted so a whole number of courses fills the shell
  double tip_height = 3.4;           // the solid tip, one block (paper 3.1)
  int stones_per_face = 2;           // per course (even courses for the staggered patterns)
  SpireJointPattern joint_pattern = SpireJointPattern::aligned_above_windows;
  SpireCornerStones corner_stones = SpireCornerStones::halves;
  std::vector<int> window_faces = {0, 2, 4, 6};  // one window on each of these faces (0..7)
  double window_sill = 0.3;          // z of the sill
  double window_width = 0.3;         // between the jambs, centred on the face
  double window_head = 1.5;          // z of the top of the opening (apex of a pointed head)
  WindowHead window_head_shape = WindowHead::pointed;  // pointed: equilateral arch, rise = width·√3/2
  int window_arch_segments = 1;      // straight segments per arc of a pointed head = voussoirs per arc
  double base_thickness = 0.3;       // the base block under course 0; 0 = no base block
  // Outer apothem of the base block's octagon; 0 = the shell's outer outline
  // at z = 0. A wider base is a platform (the top of the tower) on which
  // stones that fall off the spire land instead of falling for ever.
  double base_apothem = 0;
};

// An invalid SpireSpec. `field` is the SpireSpec member (= the deck key of
// [spire]) that is wrong, so the deck reader can name file, line and key.
struct SpireSpecError : GeneratorSpecError {
  SpireSpecError(std::string field_name, std::string what)
      : GeneratorSpecError("spire", std::move(field_name), -1, std::move(what)) {}
};

// Checks every field and the combinations (inner surface still hollow at the
// top of the shell, window inside its face and the shell, ...). Throws
// SpireSpecError naming the first bad field.
void validate_spire(const SpireSpec& spec);

struct SpireModel {
  // The base (if any), then course by course, face by face, then the tip.
  // Kinds base, stone, window_piece (pieces and head blocks), tip; course
  // 0.. for stones and pieces, n_courses for the tip; face 0..7; a stone's
  // index within its face and course (pieces keep their stone's, head
  // blocks have none), a piece's or head voussoir's `piece`. Names "base",
  // "tip", "course03_face5_stone1", "course01_face0_stone1_piece2", and the
  // head blocks "course04_face0_voussoir1" (0.. from the left springing;
  // course = the lowest course they span), "course05_face0_lintel".
  std::vector<GeneratedBlock> blocks;
  int n_courses = 0;
  double course_height = 0;        // the actual pitch: (height - tip_height) / n_courses
  double shell_top = 0;            // z of the top of the shell = bottom of the tip
  int stones_cut_by_windows = 0;   // stones replaced by pieces (or by head blocks); 0: no window splitting
  int window_pieces = 0;           // pieces and head blocks (voussoirs, lintels)
};

// Validates (validate_spire) and builds. Every block has passed validate().
// Throws SpireSpecError for a bad spec, GeometryError if a block cannot be
// built (which a valid spec should not cause).
SpireModel build_spire(const SpireSpec& spec);

// The shell's surfaces, for callers that want to check or describe the
// geometry: horizontal apothems (distance from the axis to the outer / inner
// face plane, perpendicular to the face) at height z.
double spire_outer_inradius(const SpireSpec& spec, double z);
double spire_inner_inradius(const SpireSpec& spec, double z);


}  // namespace polydem
