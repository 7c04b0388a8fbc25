// A straight masonry wall of brick or stone units, built unit by unit.
//
// Frame: the wall's own (u, v, z). u runs along the wall from its start
// (u = 0) to its end (u = length); v across it, from -thickness/2 to
// +thickness/2 (v = z × u, so v points to the left looking along u); z up
// from the bed of course 0 (z = 0) to the top (z = height). The world
// position is origin + u·e_u + v·e_v + z·e_z with e_u at azimuth `direction`
// (degrees from +x, counter-clockwise) and e_v = e_z × e_u.
//
// Units are dry (no mortar): neighbours touch exactly on shared joint
// planes. Every course is the same height, height / courses. A unit is
// `unit_length` along the wall, `unit_height` tall and `unit_width` deep
// (its bed is unit_length × unit_width). The bond fixes what lies in each
// course and how the vertical joints of one course sit over the next:
//   stretcher  every unit a stretcher (length along the wall), `leaves`
//              leaves side by side (thickness leaves·unit_width); odd
//              courses shifted by half a unit (half units at their ends).
//              With `through_every` = N, every Nth unit of a course is one
//              through-stone crossing all leaves (shifted by N/2 units in
//              odd courses, so they stagger).
//   header     every unit a header (length across the wall: thickness
//              unit_length, face width unit_width); odd courses shifted by
//              half a header (a half-header closer at each end).
//   english    stretcher courses (two leaves of stretchers) alternating with
//              header courses (shifted by a quarter unit: a queen closer,
//              half a header, at the ends). Thickness unit_length, which
//              must be 2·unit_width: two stretchers side by side fill a
//              header's length.
//   flemish    each course header, stretcher, header, ...; odd courses
//              shifted by 1.5 headers so that each header sits centred on a
//              stretcher (three-quarter units at the ends). Thickness and
//              unit_length = 2·unit_width as for english.
// A course's pattern is cut at the wall's ends. No piece of a course is
// shorter than a quarter of unit_length (the "sliver rule"): a piece left
// shorter at an end joins its neighbour, and a joint that an opening needs
// at a jamb or at the end of its head moves an existing joint closer than a
// quarter unit onto it rather than leaving a sliver.
//
// An opening goes through the whole thickness: from `sill` to `sill +
// height`, between the jambs u = position and u = position + width. Its
// head carries the masonry above it under gravity, with no tension:
//   lintel  one block spanning the opening and `bearing` onto each jamb,
//           from the head up to the first bed joint at least half a course
//           above the head;
//   arch    a semicircular arch of `voussoirs` voussoirs (radius width/2,
//           springing at sill + height - width/2) with radial joints (the
//           planes through the arch's centre axis); the voussoirs reach from
//           the intrados (straight chords) up to the first bed joint at
//           least half a course above the crown and `ring` beyond the jambs
//           on each side, where the wall's courses meet them.
// In the courses the head spans, the units between the head's ends become
// one jamb stone per side below the head (each running through the wall).
// The sill and the head (or springing) must lie on a bed joint or at least a
// quarter course above one: no piece is thinner than a quarter course.
//
// A gable (gable_height > 0) continues the courses above `height` at the
// same course height, each cut at its bed by the two slopes (its ends where
// the slopes cross its bed, with the sliver rule there) and its end units
// by the slopes themselves (trapezoids or triangles through the wall). The
// top of the gable is one apex stone, a triangle from the lowest bed joint at
// which the gable is less than 1.5 units wide. Openings stay below `height`.
//
// Corners: two walls of the same course height meet at a right angle with
// one wall's units running through the corner square in even courses and
// the other's in odd ones (WallCorner): the quoins interlock course by
// course. Two stretcher bond walls (any leaves) simply alternate. English,
// Flemish and header bond walls (same unit sizes, unit_length =
// 2·unit_width, so both are one unit length thick) close the corner as a
// bricklayer does, with closers:
//   - in the courses it owns, a wall's course starts at the quoin with a
//     quoin header (a header at the corner's outer end, running across the
//     wall: on the return wall's face it shows its long side, like a
//     stretcher) followed by a queen closer (a header split lengthwise, a
//     quarter unit in the face, kind `closer`), then the bond: headers in an
//     English or header bond header course, stretcher, header, ... in
//     Flemish bond;
//   - in the other courses it stops at the corner square, its bond anchored
//     at the corner: English stretchers from the corner, Flemish header,
//     stretcher, ....
// The quoin's header and closer leave the vertical joints of consecutive
// courses a quarter unit apart on both faces at the corner. An English or
// header bond wall owns its corners in its header courses, a Flemish bond
// wall in the courses whose pattern starts with a header; `course_shift`
// (set by the deck reader on the second wall of a corner) turns the
// second wall's pattern by one course so that the two walls own the corner
// square in alternate courses. The bond is anchored at the wall's corner
// (at its end, if only its end has one: the course is then laid from the
// end); with a corner at each end each half of a course is laid from its
// own corner and the two meet in the middle, where a piece under a quarter
// unit joins its neighbour (the bond may break there, as a bricklayer's
// does between two quoins when the length is not a whole number of units).
//
// Sizes and the rules above are checked by validate_wall(): each failure is
// a WallSpecError naming the WallSpec field (= the [[wall]] deck key) and,
// for an opening, its index. No CGAL here; wall.cpp uses it through
// halfspace_intersection for the voussoirs.
#pragma once

#include <string>
#include <vector>

#include "structures/generated_block.hpp"

namespace polydem {

enum class WallBond { stretcher, header, english, flemish };
enum class OpeningHead { lintel, arch };

struct WallOpening {
  double position = 0;  // u of the left jamb
  double sill = 0;      // z of the sill (0: a door)
  double width = 0;     // between the jambs
  double height = 0;    // sill to the top of the opening (the crown of an arch)
  OpeningHead head = OpeningHead::lintel;
  double bearing = 0;   // lintel: length on each jamb; 0 = half a unit length
  int voussoirs = 7;    // arch: voussoirs, in [3, 64]
  double ring = 0;      // arch: extent of the voussoirs beyond each jamb; 0 = half a unit length
};

// Where another wall meets this one at a right angle (a corner or return):
// in the courses below `courses` whose parity is `parity` (0 even, 1 odd),
// this wall stops `depth` short of its start or end, where the other wall's
// units run through the corner. Set by the deck reader for both walls of a
// corner (io/wall_section.cpp), so that they interlock course by course.
struct WallCorner {
  bool at_end = true;
  double depth = 0;   // the other wall's thickness
  int parity = 1;
  int courses = 0;
};

struct WallSpec {
  std::string name = "wall";         // prefix of every block's name
  Vec3 origin = Vec3::Zero();        // world point of (u, v, z) = 0: the start of the centre line at the base
  double direction = 0;              // azimuth of e_u, degrees from +x, counter-clockwise
  double length = 2.0;               // along the wall
  double height = 1.5;               // base to top
  int courses = 0;                   // 0: the nearest whole number to height / unit_height
  double unit_length = 0.4;          // along the wall (a stretcher's face length)
  double unit_height = 0.2;
  double unit_width = 0.2;           // across the wall (a stretcher's depth)
  WallBond bond = WallBond::stretcher;
  int leaves = 1;                    // stretcher bond only
  int through_every = 0;             // stretcher bond, leaves >= 2: every Nth unit a through-stone; 0 = none
  // A gable on top: the wall rises from `height` at its ends to height +
  // gable_height at its middle, the courses cut by the two slopes; 0 = none.
  double gable_height = 0;
  std::vector<WallOpening> openings;
  std::vector<WallCorner> corners;   // at most one per end
  // English, Flemish and header bonds: course c is laid with the pattern of
  // course c + course_shift (0 or 1). The deck reader sets it on the second
  // wall of a corner so that the two walls own the corner square in
  // alternate courses (see quoin_parity).
  int course_shift = 0;
};

// An invalid WallSpec: `field` is the WallSpec (or WallOpening) member =
// the deck key, `opening` the opening's index or -1.
struct WallSpecError : GeneratorSpecError {
  WallSpecError(std::string field_name, int opening_index, std::string what)
      : GeneratorSpecError("wall", std::move(field_name), opening_index, std::move(what)) {}
};

struct WallModel {
  // Course by course, unit by unit; head blocks after their lowest course.
  // Kinds unit, header, through_stone, closer (a queen closer at a quoin),
  // jamb, lintel, voussoir, apex; course, leaf, and the opening of a head
  // block. Names "<name>_course03_leaf1_unit4", "<name>_course03_unit4"
  // (through the wall), "..._piece1" for a piece beside or under an
  // opening, "<name>_opening0_lintel", "<name>_opening0_voussoir3",
  // "<name>_apex".
  std::vector<GeneratedBlock> blocks;
  int n_courses = 0;         // up to `height`
  int gable_courses = 0;     // above it, under the slopes (the apex stone not counted)
  double course_height = 0;
  double thickness = 0;
  // The solid the blocks fill: length·height·thickness minus the openings
  // (an arch's opening bounded by its chords), plus the gable's triangle.
  // The blocks' volumes sum to it.
  double solid_volume = 0;
  Mat3 rotation = Mat3::Identity();  // columns e_u, e_v, e_z
};

double wall_thickness(const WallSpec& spec);

void validate_wall(const WallSpec& spec);

// English, Flemish and header bonds: the parity (0 even, 1 odd) of the
// courses in which the wall's units run through its corner squares (its
// quoin header and closer); a WallCorner's `parity` (where the wall stops)
// must be the other one. Walls meeting at a corner need different quoin
// parities. -1 for a stretcher bond (its corners take either parity).
int quoin_parity(const WallSpec& spec);

// Validates and builds. Every block has passed validate().
WallModel build_wall(const WallSpec& spec);


}  // namespace polydem
