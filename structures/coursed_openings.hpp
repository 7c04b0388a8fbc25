// What a coursed masonry face and its openings share between the [[wall]]
// and [[tower]] builders (structures/wall.cpp, structures/tower.cpp): the row of
// units of one course along the face, the joints an opening forces into it,
// the rectangles left of a unit beside or under an opening, and the
// voussoirs of an arched head. Everything here is in the face's own plane
// (u along the face, z up); the builders turn it into blocks through the
// thickness. Internal to structures/.
#pragma once

#include <string>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace polydem::masonry {

// No piece of a course is shorter than this fraction of the unit (stone)
// length, and no piece beside or under an opening thinner than this
// fraction of the course height.
constexpr double kSliver = 0.25;

// One unit of a course along the face: [u0, u1]; `through` = one block
// through the whole thickness (else one per leaf); `kind` is the builder's.
struct Segment {
  double u0, u1;
  bool through;
  int kind;
};

// Puts a joint at x. An existing joint closer than min_len moves onto x
// (unless it is the face's end, the first u0 or the last u1) rather than
// leave a sliver.
void force_joint(std::vector<Segment>& segs, double x, double min_len, double tol);

// An opening in the face's (u, z) plane, and the head over it.
struct Opening {
  double a = 0, b = 0;    // jambs u = a (left), u = b (right)
  double sill = 0;
  double head = 0;        // top of the rectangular part: the lintel's bed, or the springing
  double top = 0;         // sill + height: the lintel's bed or the crown
  double zone_a = 0, zone_b = 0;  // the head's extent along u (a - bearing, b + bearing)
  int head_lo = -1, head_hi = -1; // the courses the head blocks span; head_hi < 0: no room above
  double head_top = 0;    // z of the top of the head blocks
  bool arch = false;
  int voussoirs = 0;
  double radius = 0, centre = 0;  // arch: radius (width/2) and u of the centre (at z = head)
};

// `extent`: the lintel's bearing or the arch's ring beyond each jamb.
// Courses of height ch from z = 0.
Opening make_opening(double position, double sill, double width, double height, bool arch, double extent,
                     int voussoirs, int courses, double ch);

// The area of the opening in the face (an arch bounded by its chords).
double opening_area(const Opening& o);

// Empty if the opening's levels are sound, else the key ("sill" or
// "height") and why: the head must leave half a course above it (the top
// course not cut), the sill and the head (springing) must lie on a bed
// joint or at least a quarter course above one. `wall_height` for messages.
struct LevelProblem {
  std::string key;
  std::string what;
};
std::vector<LevelProblem> level_problems(const Opening& o, double height_key_value, double ch, double wall_height);

// The courses the opening touches: in a head course the segments between
// the head's ends become one through segment of kind `jamb_kind` (after
// forcing joints at the ends); in a course beside the opening (between sill
// and head) joints are forced at the jambs.
void fit_course(std::vector<Segment>& segs, const Opening& o, int course, double z0, double z1, double ch,
                double min_len, double tol, int jamb_kind);

// A rectangle of the (u, z) plane.
struct Rect {
  double u0, u1, z0, z1;
};

// What is left of the rectangle r of a unit after the openings it meets
// take their opening and head: the parts left of, under and right of each
// opening (none if the unit lies wholly in an opening or its head). `cut`
// tells whether any opening met it.
std::vector<Rect> cut_by_openings(const Rect& r, const std::vector<Opening>& openings, double ch, double tol,
                                  bool& cut);

// a u + b z <= d.
struct HalfPlane {
  double a, b, d;
};

// Voussoir j (0 at the left springing) of an arched head: between the radial
// joints at angles π - jπ/n and π - (j+1)π/n about the centre (centre,
// head), outside the chord of the intrados, within the head's zone and
// under head_top. `interior` receives a point strictly inside.
std::vector<HalfPlane> voussoir(const Opening& o, int j, Vec2& interior);

// a·x <= d in a plane.
struct Line {
  Vec2 a;
  double d;
};

// The convex polygon cut by a line (Sutherland-Hodgman; empty if nothing is left).
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Line& l);

// Drops repeated and collinear corners within tol (make_prism refuses them).
std::vector<Vec2> cleaned(const std::vector<Vec2>& poly, double tol);

}  // namespace polydem::masonry
