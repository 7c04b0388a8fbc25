// Masonry arches of voussoirs with radial joints, on abutments, on piers or
// springing from a fixed base; a barrel vault as the arch extruded in rings;
// an arcade as several spans side by side on shared piers.
//
// Frame of the arch ("local"): x along the span, z up, y along the arch's
// axis (its depth). z = 0 is the springing line; x = 0 the middle of the
// arcade (of the span when there is one); y = 0 the middle of the depth.
// The local frame is turned about the vertical so that x points along
// `direction` and moved to `origin`.
//
// The profile (the curve of the intrados, the arch's underside):
//   circular   one circle of radius R (the intrados radius) whose arc spans
//              the embrace angle β, symmetric about x = 0: β = 180° the
//              semicircle (centre on the springing line), β < 180° a
//              segmental arch (centre below it), β > 180° a horseshoe
//              (centre above it). span = 2 R sin(β/2) between the springings.
//   segmental  the circular arch given by its span and its rise (intrados,
//              springing line to crown): R = (span²/4 + rise²) / (2 rise),
//              β = 4 atan(2 rise / span); rise < span/2.
//   pointed    two circles of radius R = span/2 + c whose centres sit on the
//              springing line at ±c from the middle (each arc's centre on the
//              other side): c = pointedness · span/2; pointedness = 1 the
//              equilateral arch (R = span), below 1 a drop arch, above 1 a
//              lancet. The arcs meet at the apex x = 0 at height √(R² − c²).
// The extrados (the top of the ring) is the same curve offset by the ring
// thickness t along the radius: circles of radius R + t about the same
// centres; in a pointed arch the two extrados arcs meet at the extrados apex.
//
// Voussoirs. A position s from 0 (left springing) to n (right springing)
// runs along the arch, equal steps of angle about the circle's centre
// (pointed: about each arc's centre, s = n/2 the apex). Each joint is radial:
// the segment from the intrados point a(s) to the extrados point e(s) on the
// same radius (pointed arch, at the apex: the vertical crown joint from the
// intrados apex to the extrados apex). A voussoir between joints s0 and s1 is
// the convex quadrilateral a(s0), a(s1), e(s1), e(s0) extruded over its
// ring's depth: its intrados and extrados arcs are REPLACED BY CHORDS. The
// "solid" the voussoirs fill is therefore the polygonal ring (the polygon
// through the joints' ends), not the circular one: with n voussoirs over an
// embrace β the ring's area is n · ½ sin(β/n) ((R+t)² − R²) against the
// circular ½ β ((R+t)² − R²) (2.0 % less at n = 9, β = 180°). A pointed
// arch's keystone (odd n) has flat chords under and over the apex (the
// sharp apex is cut off: a block straddling the apex and following its point
// would not be convex).
//
// Barrel vault (rings > 1): the arch is extruded in `rings` rings of equal
// depth along y. Even rings (0, 2, ...) have the joints s = 0, 1, ..., n;
// odd rings are shifted by half a voussoir: joints s = 0, ½, 1½, ..., n − ½,
// n, so n + 1 voussoirs with a half voussoir at each springing (as a
// running bond: no joint runs straight through two neighbouring rings, and
// the smallest block is half a voussoir, never a sliver). Each ring's
// voussoirs follow the chords through its own joints, so an odd ring's
// polygon differs from an even ring's by up to the chord sag R(1 − cos(β/2n))
// (30 mm on a 2 m radius, 9 voussoirs over 180°: a step in the intrados
// between rings); the rings meet on the planes between them.
//
// Supports (all as deep as the arch, y in [−depth/2, depth/2]):
//   abutments  one fixed block under each springing;
//   piers      free piers, each `pier_courses` courses of equal height,
//              standing on one fixed base slab;
//   base       one fixed slab under the whole arch (springing joints must be
//              horizontal: semicircular or pointed arches).
// A support's top course carries the springing joint(s) it supports as its
// top face (a skewback, inclined for a segmental arch) and is horizontal
// beside them at the height of the extrados springing point. An end support
// is `pier_width` wide, its inner face flush with the intrados springing;
// with `spans` > 1 the spans stand side by side, `pier_width` apart, and each
// interior pier carries the springings of the two spans beside it. A horseshoe
// arch (β > 180°) springs from abutments exactly as wide as its springing
// joints (a wider support would need a re-entrant corner). The base slab
// reaches half a pier width beyond everything it carries, on every side, and
// is `base_thickness` thick.
//
// Every block is a right prism of a convex polygon (make_prism, exact), moved
// to world coordinates by one rotation and translation; neighbours share
// their joint's corner points exactly. No CGAL here.
#pragma once

#include <string>
#include <vector>

#include "structures/generated_block.hpp"

namespace polydem {

enum class ArchShape { circular, segmental, pointed };
enum class ArchSupports { abutments, piers, base };

struct ArchSpec {
  ArchShape shape = ArchShape::circular;
  // Clear span between the springings at the intrados, m. Circular: give span
  // or radius (the other follows from the embrace); 0 = not given.
  double span = 0;
  double radius = 0;          // intrados radius, circular only, m
  double embrace = 180;       // circular: the arc's angle, degrees, in (0, 360)
  double rise = 0;            // segmental: intrados rise, m, in (0, span/2)
  double pointedness = 1;     // pointed: c / (span/2), in (0, 2]
  int voussoirs = 9;          // per ring (odd rings of a vault have one more)
  double thickness = 0.3;     // ring thickness t, along the radius, m
  double depth = 1.0;         // along the arch's axis, m (all rings together)
  int rings = 1;              // of a barrel vault, along the axis
  int spans = 1;              // side by side, on shared supports
  ArchSupports supports = ArchSupports::abutments;
  double pier_width = 0;      // along the span, m; 0 = 2 t
  double pier_height = 0;     // from the springing line down, m; 0 = span/2
  int pier_courses = 1;       // piers only
  double base_thickness = 0;  // the base slab (piers, base), m; 0 = t
  Vec3 origin = Vec3::Zero();
  Vec3 direction{1.0, 0.0, 0.0};  // of the span; its horizontal part is used
};

// An invalid ArchSpec. `field` is the deck key of [[arch]] that is wrong.
struct ArchSpecError : GeneratorSpecError {
  ArchSpecError(std::string field_name, std::string what)
      : GeneratorSpecError("arch", std::move(field_name), -1, std::move(what)) {}
};

// The arch's profile, resolved from the spec (local frame, metres).
struct ArchProfile {
  double span = 0;        // clear span at the intrados
  double radius = 0;      // intrados radius R (pointed: of each arc)
  double embrace = 0;     // radians: circular; pointed: each arc's angle springing to apex
  double centre_z = 0;    // circular: z of the centre
  double centre_offset = 0;  // pointed: c
  double rise = 0;        // springing line to the intrados crown
  double springing_angle = 0;  // radians: the springing joint's angle above the horizontal, outward
};

struct ArchModel {
  // Span by span, ring by ring, voussoirs left to right; then the supports,
  // then the base. Kinds voussoir, abutment, pier, base; a voussoir's span,
  // ring and index (0.. from the left springing), a support's index (0..
  // from -x) and a pier's course (0.. from the bottom). Names "voussoir03",
  // "ring1_voussoir03", "span1_voussoir03", "abutment0", "pier1",
  // "pier1_course2", "base" (the deck prefixes its section's name).
  std::vector<GeneratedBlock> blocks;
  ArchProfile profile;
  double pier_width = 0, pier_height = 0, base_thickness = 0;  // as built (defaults resolved)
  // The polygonal ring's area in each ring (the chords through its joints),
  // m²: the voussoirs of ring r of each span fill ring_area[r] · depth/rings.
  std::vector<double> ring_area;
  Mat3 rotation = Mat3::Identity();  // local -> world: x_world = rotation x_local + origin
};

// Resolves the profile and checks every field and their combinations.
// Throws ArchSpecError naming the first bad field.
ArchProfile arch_profile(const ArchSpec& spec);

// Validates and builds. Every block has passed validate().
ArchModel build_arch(const ArchSpec& spec);

// The intrados and extrados points of the joint at position s in [0, n]
// (local frame, (x, z)), for a profile with n voussoirs and ring thickness t.
struct ArchJoint {
  Vec2 intrados, extrados;
};
ArchJoint arch_joint(const ArchSpec& spec, const ArchProfile& profile, double s);


}  // namespace polydem
