// The wall builder: course by course, unit by unit (see wall.hpp).
//
// A course is a row of "segments" along u, [u0, u1], each either one unit
// per leaf (the leaves share the course's vertical joints) or one block
// through the whole wall (a header, a through-stone, a jamb stone). The
// bond's pattern gives the segments (a period repeated and shifted per
// course, cut at the wall's ends, end pieces under a quarter unit joined to
// their neighbour); each opening then forces the joints it needs (at its
// jambs in the courses beside the opening, at the ends of its head in the
// courses the head spans) and, in the head's courses, merges everything
// between the head's ends into one segment.
//
// Units and the pieces of them beside and under an opening are boxes in the
// wall's frame: an opening and the regions around it are rectangles in the
// (u, z) plane,
//   left   u <= position,                    z <= head (arch: springing)
//   below  position <= u <= position + width, z <= sill
//   right  u >= position + width,             z <= head (arch: springing)
// and a unit that meets an opening's zone (its head's extent times the
// opening's height, up to the top of the head) is replaced by its
// intersections with those three. The head blocks fill the rest of the zone
// above the head: a lintel (a box) or voussoirs, each the intersection of
// half-spaces (the chord of the intrados, the two radial joints through the
// arch's centre, the zone's ends and top) built by halfspace_intersection
// (CGAL, exact predicates). Boxes are built in the wall frame with
// coordinates computed once per joint, so neighbours share their faces
// exactly before the rigid motion to the world.
//
// A corner shortens the courses of one parity at one end (course_ends); a
// gable's courses are the bond's segments between the slopes' crossings of
// their bed, each unit's (u, z) rectangle cut by the slopes (2D clipping,
// the corners on the slopes computed from the same formula by both
// neighbours) and extruded through the wall.
#include "structures/generator_text.hpp"
#include "structures/wall.hpp"

#include "structures/coursed_openings.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <sstream>

namespace polydem {

namespace {

using generator_text::num;
using generator_text::zero_padded;

constexpr double kPi = std::numbers::pi;

void require(bool ok, const char* field, int opening, const std::string& what) {
  if (!ok) throw WallSpecError(field, opening, what);
}

using masonry::Segment;
using masonry::kSliver;

int kind_id(BlockKind k) { return static_cast<int>(k); }

struct PatternElement {
  double s, e;
  bool through;
  int kind;
};

struct Pattern {
  double period;
  double offset;
  std::vector<PatternElement> elements;
};

int n_courses(const WallSpec& s) {
  return s.courses > 0 ? s.courses : std::max(1, static_cast<int>(std::lround(s.height / s.unit_height)));
}

int leaves_of(const WallSpec& s) { return s.bond == WallBond::stretcher ? s.leaves : 2; }

bool closes_with_closers(const WallSpec& s) { return s.bond != WallBond::stretcher; }

// The bond's role of course c: 0 or 1 (the pattern of an even or an odd
// course of a wall without corners).
int course_role(const WallSpec& s, int c) { return (c + s.course_shift) % 2; }

// The role of the courses that own a corner square (start at the quoin with
// a quoin header and a queen closer): header courses in English and header
// bond, the courses starting with a header in Flemish bond.
int quoin_role(const WallSpec& s) { return s.bond == WallBond::flemish ? 0 : 1; }

// at_quoin: the course is laid from a corner (u = 0 in the frame it is laid
// in); Flemish bond then moves its pattern by a quarter unit so that a
// quoin header and closer fit before the first stretcher.
Pattern course_pattern(const WallSpec& s, int c, bool at_quoin) {
  const bool odd = course_role(s, c) == 1;
  const double L = s.unit_length, w = s.unit_width;
  if (s.bond == WallBond::flemish && at_quoin)
    return {3 * w, (odd ? 1.5 * w : 0.0) + 0.5 * w,
            {{0, w, true, kind_id(BlockKind::header)}, {w, 3 * w, false, kind_id(BlockKind::unit)}}};
  switch (s.bond) {
    case WallBond::stretcher: return {L, odd ? 0.5 * L : 0.0, {{0, L, false, kind_id(BlockKind::unit)}}};
    case WallBond::header: return {w, odd ? 0.5 * w : 0.0, {{0, w, true, kind_id(BlockKind::header)}}};
    case WallBond::english:
      if (!odd) return {L, 0.0, {{0, L, false, kind_id(BlockKind::unit)}}};
      return {w, 0.5 * w, {{0, w, true, kind_id(BlockKind::header)}}};
    case WallBond::flemish:
      return {3 * w, odd ? 1.5 * w : 0.0,
              {{0, w, true, kind_id(BlockKind::header)}, {w, 3 * w, false, kind_id(BlockKind::unit)}}};
  }
  return {};
}

// The bond's segments of course c between u = a and u = b (the wall's ends,
// or where a gable's slopes cross the course's bed), end slivers joined.
// at_quoin: laid from a corner at u = 0 (English, Flemish, header bonds);
// in the courses that own it the first pieces are the quoin header [0, w]
// and the queen closer [w, 1.5 w].
std::vector<Segment> bond_segments(const WallSpec& s, int c, double a, double b, bool at_quoin = false) {
  const Pattern p = course_pattern(s, c, at_quoin);
  const double L = b, tol = 1e-12 * s.length;
  std::vector<Segment> out;
  const long k0 = static_cast<long>(std::floor((a - p.offset) / p.period)) - 1;
  for (long k = k0;; ++k) {
    const double base = p.offset + static_cast<double>(k) * p.period;
    if (base >= L - tol) break;
    for (const auto& e : p.elements) {
      const double u0 = std::max(a, base + e.s), u1 = std::min(L, base + e.e);
      if (u1 - u0 > tol) out.push_back({u0, u1, e.through, e.kind});
    }
  }
  std::sort(out.begin(), out.end(), [](const Segment& x, const Segment& y) { return x.u0 < y.u0; });
  out.front().u0 = a;
  out.back().u1 = L;
  if (at_quoin && course_role(s, c) == quoin_role(s) && a == 0) {
    // The pattern (moved for Flemish bond) puts a joint at half a header
    // (w/2) and the next at 1.5 w: the quoin header takes [0, w], the
    // closer [w, 1.5 w].
    const double w = s.unit_width;
    if (out.size() < 2 || std::abs(out[0].u1 - 0.5 * w) > 1e-9 * w || std::abs(out[1].u1 - 1.5 * w) > 1e-9 * w)
      throw GeometryError("wall: internal: the quoin's course does not start with half a header");
    out[0] = {0.0, w, true, kind_id(BlockKind::header)};
    out[1] = {w, out[1].u1, true, kind_id(BlockKind::closer)};
  }
  // Through-stones: every Nth unit of a course, staggered course by course.
  if (s.bond == WallBond::stretcher && s.through_every > 0) {
    const int N = s.through_every;
    const int shift = c % 2 == 1 ? N / 2 : 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      if ((static_cast<int>(i) + shift) % N == 0) out[i].through = true, out[i].kind = kind_id(BlockKind::through_stone);
  }
  // The sliver rule at the ends.
  const double min_len = kSliver * s.unit_length * (1 - 1e-9);
  auto merge_into = [&](std::size_t keep, std::size_t drop) {
    Segment& k = out[keep];
    const Segment& d = out[drop];
    k.u0 = std::min(k.u0, d.u0);
    k.u1 = std::max(k.u1, d.u1);
    if (d.through && !k.through) k.through = true, k.kind = d.kind;
    out.erase(out.begin() + static_cast<long>(drop));
  };
  if (out.size() > 1 && out.front().u1 - out.front().u0 < min_len) merge_into(1, 0);
  if (out.size() > 1 && out.back().u1 - out.back().u0 < min_len) merge_into(out.size() - 2, out.size() - 1);
  return out;
}

double bearing_of(const WallSpec& s, const WallOpening& o) {
  if (o.head == OpeningHead::lintel) return o.bearing > 0 ? o.bearing : 0.5 * s.unit_length;
  return o.ring > 0 ? o.ring : 0.5 * s.unit_length;
}

masonry::Opening opening_of(const WallSpec& s, const WallOpening& o, int courses, double ch) {
  return masonry::make_opening(o.position, o.sill, o.width, o.height, o.head == OpeningHead::arch, bearing_of(s, o),
                               o.voussoirs, courses, ch);
}

// Where course c starts and ends along u (a corner may shorten it).
std::pair<double, double> course_ends(const WallSpec& s, int c) {
  double a = 0, b = s.length;
  for (const WallCorner& k : s.corners)
    if (c < k.courses && c % 2 == k.parity) (k.at_end ? b : a) = k.at_end ? s.length - k.depth : k.depth;
  return {a, b};
}

// The segments of course c between its ends ca and cb (course_ends). A
// stretcher bond wall, or a wall without corners, is laid from u = 0. An
// English, Flemish or header bond wall is laid from its corner: from u = 0
// with a corner at its start, from u = length (mirrored) with a corner at
// its end only; with corners at both ends the joints before the middle come
// from the start's laying and those after it from the end's, and a piece
// under a quarter unit where they meet joins its neighbour.
std::vector<Segment> course_segments(const WallSpec& s, int c, double ca, double cb) {
  bool at_start = false, at_end = false;
  if (closes_with_closers(s))
    for (const WallCorner& k : s.corners) (k.at_end ? at_end : at_start) = true;
  if (!at_end) return bond_segments(s, c, ca, cb, at_start);
  const double L = s.length;
  // Laid from the end: in the mirrored frame u' = L - u, then mapped back
  // (each joint once, so neighbours share it exactly).
  std::vector<Segment> from_end = bond_segments(s, c, L - cb, L - ca, true);
  std::reverse(from_end.begin(), from_end.end());
  for (Segment& g : from_end) {
    const double u0 = L - g.u1, u1 = L - g.u0;
    g.u0 = u0, g.u1 = u1;
  }
  from_end.front().u0 = ca;
  from_end.back().u1 = cb;
  if (!at_start) return from_end;
  const std::vector<Segment> from_start = bond_segments(s, c, ca, cb, true);
  const double mid = 0.5 * L;
  std::vector<Segment> out;
  for (const Segment& g : from_start)
    if (g.u1 <= mid) out.push_back(g);
  const double seam = out.empty() ? ca : out.back().u1;
  std::vector<Segment> tail;
  for (const Segment& g : from_end)
    if (g.u0 >= mid) tail.push_back(g);
  const double seam_end = tail.empty() ? cb : tail.front().u0;
  if (seam_end > seam) {
    // Between the two layings: the start's pieces up to the end's first joint after the middle.
    for (const Segment& g : from_start) {
      if (g.u1 <= seam || g.u0 >= seam_end) continue;
      out.push_back({std::max(g.u0, seam), std::min(g.u1, seam_end), g.through, g.kind});
    }
  }
  out.insert(out.end(), tail.begin(), tail.end());
  const double min_len = kSliver * s.unit_length * (1 - 1e-9);
  for (std::size_t i = 0; i < out.size() && out.size() > 1;) {
    if (out[i].u1 - out[i].u0 >= min_len) {
      ++i;
      continue;
    }
    const std::size_t keep = i > 0 ? i - 1 : i + 1;
    Segment& k = out[keep];
    k.u0 = std::min(k.u0, out[i].u0);
    k.u1 = std::max(k.u1, out[i].u1);
    if (out[i].through && !k.through) k.through = true, k.kind = out[i].kind;
    out.erase(out.begin() + static_cast<long>(i));
    if (i > 0) --i;
  }
  return out;
}

// The gable's courses and its apex stone (see wall.hpp), appended to m.
template <class PlaceUz>
void build_gable(const WallSpec& s, WallModel& m, const PlaceUz& place_uz) {
  const double L = s.length, H = s.height, g = s.gable_height, ch = m.course_height, T = m.thickness;
  const double tol = 1e-12 * L;
  const int leaves = leaves_of(s);
  const double leaf_w = T / leaves;
  auto width_at = [&](double z) { return L * (1.0 - (z - H) / g); };
  // The slopes: z <= H + (2g/L) u and z <= H + (2g/L)(L - u).
  const masonry::Line left{Vec2(-2 * g / L, 1), H}, right{Vec2(2 * g / L, 1), H + 2 * g};
  int c = m.n_courses;
  double z0 = H;
  const int digits = std::max(2, static_cast<int>(std::to_string(m.n_courses + static_cast<int>(g / ch) + 1).size()));
  while (z0 + ch < H + g - 1e-9 * ch && width_at(z0) >= 1.5 * s.unit_length * (1 - 1e-9)) {
    const double z1 = z0 + ch;
    const double a = 0.5 * (L - width_at(z0)), b = L - a;
    const std::vector<Segment> segs = bond_segments(s, c, a, b);
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const Segment& seg = segs[i];
      std::vector<Vec2> poly = {{seg.u0, z0}, {seg.u1, z0}, {seg.u1, z1}, {seg.u0, z1}};
      poly = masonry::cleaned(masonry::clip(masonry::clip(poly, left), right), tol);
      const std::string base = s.name + "_course" + zero_padded(c, digits);
      const auto make = [&](double v0, double v1, int leaf, const std::string& name) {
        GeneratedBlock blk;
        try {
          blk.shape = place_uz(poly, v0, v1);
        } catch (const GeometryError& e) {
          throw GeometryError("wall: cannot build " + name + ": " + e.what());
        }
        blk.kind = static_cast<BlockKind>(seg.kind);
        blk.course = c;
        blk.leaf = leaf;
        blk.name = name;
        m.blocks.push_back(std::move(blk));
      };
      if (seg.through) {
        make(-0.5 * T, 0.5 * T, -1, base + "_unit" + std::to_string(i));
      } else {
        for (int l = 0; l < leaves; ++l) {
          const double v0 = -0.5 * T + l * leaf_w, v1 = l + 1 == leaves ? 0.5 * T : v0 + leaf_w;
          make(v0, v1, l, base + "_leaf" + std::to_string(l) + "_unit" + std::to_string(i));
        }
      }
    }
    ++c;
    z0 = z1;
  }
  m.gable_courses = c - m.n_courses;
  const double a = 0.5 * (L - width_at(z0));
  GeneratedBlock apex;
  apex.shape = place_uz({{a, z0}, {L - a, z0}, {0.5 * L, H + g}}, -0.5 * T, 0.5 * T);
  apex.kind = BlockKind::apex;
  apex.course = c;
  apex.name = s.name + "_apex";
  m.blocks.push_back(std::move(apex));
}

}  // namespace

int quoin_parity(const WallSpec& s) {
  if (!closes_with_closers(s)) return -1;
  return (quoin_role(s) + s.course_shift) % 2;
}

double wall_thickness(const WallSpec& s) {
  return s.bond == WallBond::stretcher ? s.leaves * s.unit_width : s.unit_length;
}

void validate_wall(const WallSpec& s) {
  auto finite_positive = [&](double v, const char* field) {
    require(std::isfinite(v) && v > 0, field, -1, "must be > 0 and finite (got " + num(v) + ")");
  };
  require(!s.name.empty(), "name", -1, "must not be empty");
  finite_positive(s.length, "length");
  finite_positive(s.height, "height");
  finite_positive(s.unit_length, "unit_length");
  finite_positive(s.unit_height, "unit_height");
  finite_positive(s.unit_width, "unit_width");
  require(std::isfinite(s.direction), "direction", -1, "must be finite");
  require(s.origin.allFinite(), "origin", -1, "must be finite");
  require(s.unit_length <= s.length * (1 + 1e-12), "unit_length", -1,
          "a unit (" + num(s.unit_length) + " m) is longer than the wall (" + num(s.length) + " m)");
  require(s.unit_height <= s.height * (1 + 1e-12), "unit_height", -1,
          "a unit (" + num(s.unit_height) + " m) is taller than the wall (" + num(s.height) + " m)");
  require(s.courses >= 0 && s.courses <= 2000, "courses", -1,
          "must be in [1, 2000] (got " + std::to_string(s.courses) + ")");
  require(s.leaves >= 1 && s.leaves <= 16, "leaves", -1, "must be in [1, 16] (got " + std::to_string(s.leaves) + ")");
  require(s.leaves == 1 || s.bond == WallBond::stretcher, "leaves", -1,
          "only a stretcher bond has several leaves (header, English and Flemish bond walls are one unit length "
          "thick)");
  require(std::isfinite(s.gable_height) && s.gable_height >= 0 && s.gable_height <= 100 * s.height, "gable_height",
          -1, "must be in [0, 100·height] (got " + num(s.gable_height) + ")");
  require(s.through_every >= 0, "through_every", -1, "must be >= 0 (got " + std::to_string(s.through_every) + ")");
  require(s.through_every == 0 || (s.bond == WallBond::stretcher && s.leaves >= 2), "through_every", -1,
          "through-stones cross the leaves of a stretcher bond wall with at least 2 leaves");
  if (s.bond == WallBond::english || s.bond == WallBond::flemish)
    require(std::abs(2 * s.unit_width - s.unit_length) <= 1e-9 * s.unit_length, "unit_width", -1,
            std::string("an ") + (s.bond == WallBond::english ? "English" : "Flemish") +
                " bond cannot close across the wall unless two stretchers side by side fill a header's length: "
                "unit_width must be unit_length/2 = " +
                num(0.5 * s.unit_length) + " (got " + num(s.unit_width) + ")");
  const int courses = n_courses(s);
  const double ch = s.height / courses;
  const double units_per_course = s.length / std::min(s.unit_length, s.unit_width) + 2;
  const double blocks = units_per_course * (courses + std::ceil(s.gable_height / ch)) * leaves_of(s);
  require(blocks <= 20000, "length", -1,
          "with these unit sizes the wall would have about " + num(std::round(blocks)) + " blocks (at most 20000)");
  require(s.openings.size() <= 64, "opening", -1, "at most 64 openings per wall");

  const double min_len = kSliver * s.unit_length;
  double start_clear = 0, end_clear = 0;  // what corners take from the ends
  require(s.course_shift == 0 || s.course_shift == 1, "course_shift", -1,
          "must be 0 or 1 (got " + std::to_string(s.course_shift) + ")");
  for (const WallCorner& k : s.corners) {
    if (closes_with_closers(s)) {
      require(std::abs(2 * s.unit_width - s.unit_length) <= 1e-9 * s.unit_length, "unit_width", -1,
              "cannot close a corner: a header bond wall turns a corner with quoin headers and queen closers only "
              "when two headers side by side make a unit length: unit_width must be unit_length/2 = " +
                  num(0.5 * s.unit_length) + " (got " + num(s.unit_width) + ")");
      require(std::abs(k.depth - s.unit_length) <= 1e-9 * s.unit_length, "unit_length", -1,
              "cannot close a corner: the other wall must be one unit length (" + num(s.unit_length) +
                  " m) thick like this one (got " + num(k.depth) + " m)");
      require(k.parity == 1 - quoin_parity(s), "corners", -1,
              "the corner's courses where the wall stops must be the ones it does not own (parity " +
                  std::to_string(1 - quoin_parity(s)) + ")");
    }
    require(std::isfinite(k.depth) && k.depth >= min_len * (1 - 1e-9) && k.depth <= 0.5 * s.length, "length", -1,
            "a corner takes " + num(k.depth) + " m (the other wall's thickness) from the wall's " +
                (k.at_end ? "end" : "start") + ": it must be between a quarter unit and half the length");
    require(s.gable_height == 0, "gable_height", -1, "a wall with a corner has no gable here (not built)");
    (k.at_end ? end_clear : start_clear) = k.depth;
  }
  if (closes_with_closers(s) && !s.corners.empty())
    require(s.length >= start_clear + end_clear + 2 * s.unit_length * (1 - 1e-9), "length", -1,
            "a wall with closers at a corner needs at least two unit lengths (" + num(2 * s.unit_length) +
                " m) beyond its corner squares (got " + num(s.length - start_clear - end_clear) + " m)");
  std::vector<masonry::Opening> done;
  for (std::size_t i = 0; i < s.openings.size(); ++i) {
    const WallOpening& o = s.openings[i];
    const int k = static_cast<int>(i);
    require(std::isfinite(o.width) && o.width > 0, "width", k, "must be > 0 (got " + num(o.width) + ")");
    require(std::isfinite(o.height) && o.height > 0, "height", k, "must be > 0 (got " + num(o.height) + ")");
    require(std::isfinite(o.sill) && o.sill >= 0, "sill", k, "must be >= 0 (got " + num(o.sill) + ")");
    require(std::isfinite(o.position), "position", k, "must be finite");
    require(std::isfinite(o.bearing) && o.bearing >= 0, "bearing", k, "must be >= 0 (got " + num(o.bearing) + ")");
    require(std::isfinite(o.ring) && o.ring >= 0, "ring", k, "must be >= 0 (got " + num(o.ring) + ")");
    const double e = bearing_of(s, o);
    const char* e_key = o.head == OpeningHead::lintel ? "bearing" : "ring";
    require(e >= min_len * (1 - 1e-9), e_key, k,
            "must be at least a quarter unit (" + num(min_len) + " m) (got " + num(e) + ")");
    if (o.head == OpeningHead::arch) {
      require(o.voussoirs >= 3 && o.voussoirs <= 64, "voussoirs", k,
              "must be in [3, 64] (got " + std::to_string(o.voussoirs) + ")");
      require(o.height >= 0.5 * o.width * (1 - 1e-12), "height", k,
              "a semicircular arch of width " + num(o.width) + " m rises " + num(0.5 * o.width) +
                  " m: height must be at least that (got " + num(o.height) + ")");
    }
    require(o.position - e >= start_clear + min_len * (1 - 1e-9), "position", k,
            "the opening and its head's " + std::string(e_key) + " (" + num(e) +
                " m each side) must leave at least a quarter unit (" + num(min_len) +
                " m) of wall before it (after any corner): position must be at least " +
                num(start_clear + e + min_len) + " (got " +
                num(o.position) + ")");
    require(o.position + o.width + e <= s.length - end_clear - min_len * (1 - 1e-9), "width", k,
            "the opening and its head's " + std::string(e_key) + " reach u = " + num(o.position + o.width + e) +
                ", leaving less than a quarter unit (" + num(min_len) + " m) of the wall (length " + num(s.length) +
                (end_clear > 0 ? ", less " + num(end_clear) + " m for a corner" : std::string()) + ") after it");
    const masonry::Opening g = opening_of(s, o, courses, ch);
    for (const auto& problem : masonry::level_problems(g, o.height, ch, s.height))
      throw WallSpecError(problem.key, k, problem.what);
    for (std::size_t j = 0; j < done.size(); ++j) {
      const masonry::Opening& h = done[j];
      const bool apart = g.zone_a >= h.zone_b + min_len * (1 - 1e-9) || h.zone_a >= g.zone_b + min_len * (1 - 1e-9);
      require(apart, "position", k,
              "the opening with its head (u from " + num(g.zone_a) + " to " + num(g.zone_b) + ") overlaps opening " +
                  std::to_string(j) + " with its head (u from " + num(h.zone_a) + " to " + num(h.zone_b) +
                  ") or leaves less than a quarter unit (" + num(min_len) + " m) between them");
    }
    done.push_back(g);
  }
}

WallModel build_wall(const WallSpec& s) {
  validate_wall(s);
  WallModel m;
  m.n_courses = n_courses(s);
  m.course_height = s.height / m.n_courses;
  m.thickness = wall_thickness(s);
  const double th = s.direction * kPi / 180.0;
  const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0), ez(0, 0, 1);
  m.rotation.col(0) = eu;
  m.rotation.col(1) = ev;
  m.rotation.col(2) = ez;
  const double ch = m.course_height, T = m.thickness, L = s.length;
  const double tol = 1e-12 * L;
  const double min_len = kSliver * s.unit_length * (1 - 1e-9);
  const int leaves = leaves_of(s);
  const double leaf_w = T / leaves;
  const int course_digits = std::max(2, static_cast<int>(std::to_string(m.n_courses - 1).size()));

  std::vector<masonry::Opening> openings;
  m.solid_volume = L * s.height * T + 0.5 * L * s.gable_height * T;
  for (const WallCorner& k : s.corners)
    for (int c = 0; c < std::min(k.courses, m.n_courses); ++c)
      if (c % 2 == k.parity) m.solid_volume -= k.depth * ch * T;
  for (const auto& o : s.openings) {
    openings.push_back(opening_of(s, o, m.n_courses, ch));
    m.solid_volume -= masonry::opening_area(openings.back()) * T;
  }

  auto place = [&](const Polyhedron& local) { return transformed(local, m.rotation, s.origin); };
  auto box = [&](double u0, double u1, double v0, double v1, double z0, double z1) {
    return place(make_box(Vec3(u1 - u0, v1 - v0, z1 - z0), Vec3(0.5 * (u0 + u1), 0.5 * (v0 + v1), 0.5 * (z0 + z1))));
  };
  // A (u, z) polygon through the wall from v0 to v1: make_prism extrudes
  // along its third axis w, and (x, y, w) -> (u, v, z) = (x, -w, y) is a
  // rotation, so the prism's faces stay outward.
  const auto place_uz = [&](const std::vector<Vec2>& poly, double v0, double v1) {
    Mat3 turn;
    turn << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    return transformed(make_prism(poly, -v1, -v0), m.rotation * turn, s.origin);
  };

  for (int c = 0; c < m.n_courses; ++c) {
    const double z0 = c * ch, z1 = c + 1 == m.n_courses ? s.height : (c + 1) * ch;
    const auto [ca, cb] = course_ends(s, c);
    std::vector<Segment> segs = course_segments(s, c, ca, cb);
    // The joints the openings need in this course.
    for (const auto& g : openings)
      masonry::fit_course(segs, g, c, z0, z1, ch, min_len, tol, kind_id(BlockKind::jamb));
    int unit_index = 0;
    for (const auto& seg : segs) {
      const int i = unit_index++;
      bool cut = false;
      const std::vector<masonry::Rect> rects = masonry::cut_by_openings({seg.u0, seg.u1, z0, z1}, openings, ch, tol, cut);
      const std::string base_name =
          s.name + "_course" + zero_padded(c, course_digits);
      for (std::size_t p = 0; p < rects.size(); ++p) {
        const masonry::Rect& r = rects[p];
        const std::string piece = cut ? "_piece" + std::to_string(p) : std::string();
        if (seg.through) {
          GeneratedBlock b;
          b.shape = box(r.u0, r.u1, -0.5 * T, 0.5 * T, r.z0, r.z1);
          b.kind = static_cast<BlockKind>(seg.kind);
          b.course = c;
          b.name = base_name + "_unit" + std::to_string(i) + piece;
          m.blocks.push_back(std::move(b));
        } else {
          for (int l = 0; l < leaves; ++l) {
            GeneratedBlock b;
            const double v0 = -0.5 * T + l * leaf_w, v1 = l + 1 == leaves ? 0.5 * T : v0 + leaf_w;
            b.shape = box(r.u0, r.u1, v0, v1, r.z0, r.z1);
            b.kind = static_cast<BlockKind>(seg.kind);
            b.course = c;
            b.leaf = l;
            b.name = base_name + "_leaf" + std::to_string(l) + "_unit" + std::to_string(i) + piece;
            m.blocks.push_back(std::move(b));
          }
        }
      }
    }
    // The head blocks of the openings whose head starts in this course.
    for (std::size_t k = 0; k < openings.size(); ++k) {
      const masonry::Opening& g = openings[k];
      if (g.head_lo != c) continue;
      const std::string prefix = s.name + "_opening" + std::to_string(k);
      if (!g.arch) {
        GeneratedBlock b;
        b.shape = box(g.zone_a, g.zone_b, -0.5 * T, 0.5 * T, g.head, g.head_top);
        b.kind = BlockKind::lintel;
        b.course = c;
        b.opening = static_cast<int>(k);
        b.name = prefix + "_lintel";
        m.blocks.push_back(std::move(b));
        continue;
      }
      for (int j = 0; j < g.voussoirs; ++j) {
        Vec2 inside;
        std::vector<Vec3> normals;
        std::vector<double> offsets;
        // Each (u, z) half-plane a u + b z <= d extruded through the wall.
        for (const masonry::HalfPlane& h : masonry::voussoir(g, j, inside)) {
          normals.push_back(m.rotation * Vec3(h.a, 0, h.b));
          offsets.push_back(h.d + normals.back().dot(s.origin));
        }
        // The wall's two faces.
        const Vec3 face = m.rotation * Vec3(0, 1, 0);
        normals.push_back(face), offsets.push_back(0.5 * T + face.dot(s.origin));
        normals.push_back(-face), offsets.push_back(0.5 * T - face.dot(s.origin));
        const Vec3 interior = s.origin + m.rotation * Vec3(inside.x(), 0, inside.y());
        GeneratedBlock b;
        const std::string name = prefix + "_voussoir" + std::to_string(j);
        try {
          b.shape = halfspace_intersection(normals, offsets, interior);
        } catch (const GeometryError& e) {
          throw GeometryError("wall: cannot build " + name + ": " + e.what());
        }
        b.kind = BlockKind::voussoir;
        b.course = c;
        b.opening = static_cast<int>(k);
        b.name = name;
        m.blocks.push_back(std::move(b));
      }
    }
  }
  if (s.gable_height > 0) build_gable(s, m, place_uz);
  return m;
}

}  // namespace polydem
