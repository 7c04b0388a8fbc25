// A hollow masonry tower, square or octagonal, built stone by stone.
//
// Frame: z up; the tower's axis is the vertical through `origin`, whose z
// is the bed of course 0; the top of the last course is at origin.z +
// height. Face k (0..sides-1) faces the horizontal direction at azimuth
// k·360°/sides from +x, counter-clockwise (face 0 faces +x; for an
// octagon the spire's faces, structures/spire.hpp). Along a face, s runs
// towards increasing azimuth from the face's middle (s = 0).
//
// The wall is `wall_thickness` thick between the outer faces (apothem
// `outer_apothem`) and the inner ones. Every course is the same height,
// height / courses with courses the nearest whole number to height /
// course_height. Corners interlock course by course: at each corner one of
// the two faces' end stones runs past the corner to the other face's outer
// surface, ending on the plane through the inner corner perpendicular to
// the other face (for a square, the other face's inner surface: a quoin);
// even faces do so in even courses, odd faces in odd courses. Between its
// ends a face has `stones_per_face` stones in the courses where it owns its
// corners and stones_per_face + 1 (half stones beside the corners, less what
// the corners take) where it does not, so the vertical joints of one course
// sit half a stone from those of the next. A joint closer than a quarter
// stone to the inner corner is dropped (the sliver rule of the walls).
//
// Openings go through the wall perpendicular to their face, centred on it,
// with a lintel or a semicircular arch of voussoirs above (the rules and
// the head blocks of structures/wall.hpp's openings, with the stone length for
// the unit length); one opening per face.
// No CGAL here; tower.cpp uses it through halfspace_intersection.
#pragma once

#include <string>
#include <vector>

#include "structures/generated_block.hpp"
#include "structures/wall.hpp"

namespace polydem {

struct TowerOpening {
  std::vector<int> faces;  // the faces with this opening, 0..sides-1
  double sill = 0;         // above the tower's base
  double width = 0;
  double height = 0;       // sill to the top of the opening (an arch's crown)
  OpeningHead head = OpeningHead::lintel;
  double bearing = 0;      // lintel: on each jamb; 0 = half the nominal stone
  int voussoirs = 7;
  double ring = 0;         // arch: 0 = half the nominal stone
};

struct TowerSpec {
  std::string name = "tower";
  int sides = 8;                    // 4 (square) or 8 (octagonal)
  Vec3 origin = Vec3::Zero();       // the axis at the bed of course 0
  double outer_apothem = 1.5;       // axis to the outer face (a square: half its outer width)
  double wall_thickness = 0.5;
  double height = 6.0;
  double course_height = 0.3;       // nominal
  int stones_per_face = 2;
  std::vector<TowerOpening> openings;
};

struct TowerSpecError : GeneratorSpecError {
  TowerSpecError(std::string field_name, int opening_index, std::string what)
      : GeneratorSpecError("tower", std::move(field_name), opening_index, std::move(what)) {}
};

struct TowerModel {
  // Kinds stone, jamb, lintel, voussoir; course, face, and the opening of a
  // head block. Names "<name>_courseCC_faceF_stoneS", "..._pieceP" beside or
  // under an opening, "<name>_faceF_openingK_lintel",
  // "<name>_faceF_openingK_voussoirJ".
  std::vector<GeneratedBlock> blocks;
  int n_courses = 0;
  double course_height = 0;
  double stone_length = 0;   // nominal: the mid-wall face width / stones_per_face
  double solid_volume = 0;   // the hollow prism minus the openings
  double top = 0;            // world z of the top of the last course
};

void validate_tower(const TowerSpec& spec);
TowerModel build_tower(const TowerSpec& spec);

}  // namespace polydem
