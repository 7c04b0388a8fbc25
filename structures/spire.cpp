// The spire builder: course by course, face by face, stone by stone.
//
// Every block is a list of half-spaces n·x <= d turned into a polyhedron by
// halfspace_intersection() (CGAL hull of the dual points, exact predicates).
// Neighbours share their joint planes exactly (the same Plane value), so
// they meet without gaps or overlaps up to round-off in the corners.
//
// A window is the convex prism O = {|s| <= w/2, z >= sill, z <= h(s)} in the
// face's frame (s along the face, horizontal; h the head profile: flat, or a
// pointed arch as straight chords, concave). Every region below is a prism
// perpendicular to the face: half-planes a s + b z <= d of the (s, z) plane.
//
// The head is built so that it carries the masonry above it under gravity:
//   pointed  voussoirs. The joint at each corner P_j of the left arc is the
//            plane through P_j normal to the arc's tangent there: at the
//            springing P_0 normal to the first chord (the springing joint,
//            inclined, so the voussoir bears on the springer beside the
//            opening), between chords along the bisector of the two chords
//            (the circle's radius), at the apex the vertical crown joint
//            s = 0, where the two arcs lean on each other. Voussoir j is
//            {above chord j, after joint j, before joint j+1}; the right arc
//            is the mirror image.
//   flat     a lintel {|s| <= w/2 + b, z >= head} bearing b on each jamb.
// The head blocks (voussoirs, lintel) span the "head courses", from the
// course holding the springing (the head, flat) up to the first bed joint at
// least half a course above the head, as single blocks: no bed joint crosses
// a voussoir and the crown joint is at least half a course tall. In a head
// course the face's vertical joints are replaced around the head: one "zone"
// stone spans everything that the head blocks take from that course (joints
// at ±s_zone, or none if the stones outside would be slivers). The zone stone
// and every stone that O meets become the convex pieces
//   left  S ∩ {s <= -w/2} ∩ {before the springing joint}   (flat: z <= head)
//   below S ∩ {|s| <= w/2, z <= sill}
//   right the mirror of left
// which with O and the head blocks tile the face's courses. The pieces are
// cut from S by clip(): S's corners on the kept side plus the crossings of
// its edges, hulled again (convex_hull, CGAL).
#include "structures/generator_text.hpp"
#include "structures/spire.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace polydem {

namespace {

using generator_text::num;
using generator_text::zero_padded;

constexpr double kPi = std::numbers::pi;
const double kTan8 = std::tan(kPi / 8.0);  // half the face width over the apothem

struct Plane {
  Vec3 n;    // need not be unit
  double d;  // n·x <= d is inside
};

// Horizontal unit normal and tangent (towards increasing azimuth) of face k.
Vec3 face_normal(int k) {
  const double th = k * kPi / 4.0;
  return {std::cos(th), std::sin(th), 0.0};
}
Vec3 face_tangent(int k) {
  const double th = k * kPi / 4.0;
  return {-std::sin(th), std::cos(th), 0.0};
}

double outer_apothem_at_base(const SpireSpec& s) { return s.base_inradius + 0.5 * s.wall_thickness; }
double shell_top(const SpireSpec& s) { return s.height - s.tip_height; }
double thickness_at(const SpireSpec& s, double z) {
  return s.wall_thickness + (s.wall_thickness_top - s.wall_thickness) * z / shell_top(s);
}

// Planes of face k (inside = wall side).
Plane outer_plane(const SpireSpec& s, int k) {
  const double A = outer_apothem_at_base(s);
  return {face_normal(k) + Vec3(0, 0, A / s.height), A};
}
Plane inner_plane(const SpireSpec& s, int k) {
  // n_k·x >= a_i(z) = (A - t0) - c z
  const double A = outer_apothem_at_base(s);
  const double c = A / s.height + (s.wall_thickness_top - s.wall_thickness) / shell_top(s);
  return {-face_normal(k) - Vec3(0, 0, c), -(A - s.wall_thickness)};
}
// The mitre planes through the axis and the octagon's corners at azimuth
// θ_k ∓ π/8; inside = towards the face.
Plane low_corner_plane(int k) {
  const double phi = k * kPi / 4.0 - kPi / 8.0;
  return {Vec3(std::sin(phi), -std::cos(phi), 0.0), 0.0};
}
Plane high_corner_plane(int k) {
  const double phi = k * kPi / 4.0 + kPi / 8.0;
  return {Vec3(-std::sin(phi), std::cos(phi), 0.0), 0.0};
}
Plane s_at_least(int k, double s0) { return {-face_tangent(k), -s0}; }
Plane s_at_most(int k, double s1) { return {face_tangent(k), s1}; }
Plane z_at_least(double z0) { return {Vec3(0, 0, -1), -z0}; }
Plane z_at_most(double z1) { return {Vec3(0, 0, 1), z1}; }

Polyhedron intersect(const std::vector<Plane>& planes, const Vec3& interior) {
  std::vector<Vec3> n;
  std::vector<double> d;
  for (const auto& p : planes) n.push_back(p.n), d.push_back(p.d);
  return halfspace_intersection(n, d, interior);
}

// p ∩ {plane}: nullopt if nothing with volume is left; p itself if the
// plane does not cut it. Corners within tol of the plane count as on it.
std::optional<Polyhedron> clip(const Polyhedron& p, const Plane& plane) {
  const double len = plane.n.norm();
  const Vec3 n = plane.n / len;
  const double d = plane.d / len;
  const double tol = 1e-9 * bounding_box_diagonal(p.vertices);
  std::vector<double> dist;
  bool any_in = false, any_out = false;
  for (const auto& v : p.vertices) {
    dist.push_back(n.dot(v) - d);
    any_in = any_in || dist.back() < -tol;
    any_out = any_out || dist.back() > tol;
  }
  if (!any_out) return p;
  if (!any_in) return std::nullopt;
  std::vector<Vec3> pts;
  for (size_t i = 0; i < p.vertices.size(); ++i)
    if (dist[i] <= tol) pts.push_back(p.vertices[i]);
  for (const auto& e : p.edges) {
    const double da = dist[e[0]], db = dist[e[1]];
    if ((da < -tol && db > tol) || (da > tol && db < -tol)) {
      const double t = da / (da - db);
      pts.push_back(p.vertices[e[0]] + t * (p.vertices[e[1]] - p.vertices[e[0]]));
    }
  }
  return convex_hull(pts);
}

std::optional<Polyhedron> clip_all(const Polyhedron& p, const std::vector<Plane>& planes) {
  std::optional<Polyhedron> cur = p;
  for (const auto& pl : planes) {
    cur = clip(*cur, pl);
    if (!cur) return std::nullopt;
  }
  return cur;
}

// The window's head profile as points (s, z) from the left springing to the
// right one: the corners where h(s) changes slope.
std::vector<Vec2> head_points(const SpireSpec& s) {
  const double w = s.window_width;
  if (s.window_head_shape == WindowHead::flat) return {{-0.5 * w, s.window_head}, {0.5 * w, s.window_head}};
  // Equilateral pointed arch: arcs of radius w centred on the opposite
  // springing point; the left arc runs from angle 180° to 120°.
  const double spring = s.window_head - w * std::sqrt(3.0) / 2.0;
  const int m = s.window_arch_segments;
  std::vector<Vec2> pts;
  for (int i = 0; i <= m; ++i) {
    const double a = kPi - (kPi / 3.0) * i / m;
    pts.emplace_back(0.5 * w + w * std::cos(a), spring + w * std::sin(a));
  }
  for (int i = m - 1; i >= 0; --i) pts.emplace_back(-pts[i].x(), pts[i].y());
  pts[m].x() = 0.0;  // apex exactly on the face's centre line
  return pts;
}

// a s + b z <= d in face k's (s, z) frame.
struct HalfPlane {
  double a, b, d;
  HalfPlane flipped() const { return {-a, -b, -d}; }
  HalfPlane mirrored() const { return {-a, b, d}; }  // s -> -s
};

Plane on_face(int k, const HalfPlane& h) { return {h.a * face_tangent(k) + Vec3(0, 0, h.b), h.d}; }

std::vector<Plane> on_face(int k, const std::vector<HalfPlane>& hs) {
  std::vector<Plane> out;
  for (const auto& h : hs) out.push_back(on_face(k, h));
  return out;
}

struct Window {
  double half_width;
  double sill;
  double head;                // z of the top of the opening
  bool pointed;
  std::vector<Vec2> profile;  // head corners (s, z), s increasing
  // The head courses [head_lo, head_hi] and the top of the head blocks.
  int head_lo = -1, head_hi = -1;
  double head_top = 0;
  double spring = 0;          // pointed: z of the springing
  double spring_slope = 0;    // pointed: dz/ds of the first chord
  double lintel_half = 0;     // flat: half the lintel's length, w/2 + b; 0 = the whole face
  std::vector<HalfPlane> left, below, right;      // the regions beside and under the opening
  std::vector<std::vector<HalfPlane>> head_blocks;  // voussoirs left to right, or the lintel
};

// Below chord a-b (inside the opening).
HalfPlane below_chord(const Vec2& a, const Vec2& b) {
  const double ds = b.x() - a.x(), dz = b.y() - a.y();
  // (-dz, ds) is the chord's upward normal in the (s, z) plane.
  return {-dz, ds, -dz * a.x() + ds * a.y()};
}

// The regions of the window's partition (see the top of the file).
void build_regions(Window& w) {
  const double hw = w.half_width;
  w.below = {{1, 0, hw}, {-1, 0, hw}, {0, 1, w.sill}};
  if (!w.pointed) {
    w.left = {{1, 0, -hw}, {0, 1, w.head}};
    std::vector<HalfPlane> lintel = {{0, -1, -w.head}};
    if (w.lintel_half > 0) lintel.push_back({1, 0, w.lintel_half}), lintel.push_back({-1, 0, w.lintel_half});
    w.head_blocks = {lintel};
  } else {
    const auto& p = w.profile;
    const int m = static_cast<int>(p.size() - 1) / 2;  // chords per arc; p[m] is the apex
    auto chord_dir = [&](int j) { return Vec2(p[j + 1] - p[j]).normalized(); };
    // Joint j of the left arc: "before" (springing side) half-plane.
    auto before_joint = [&](int j) {
      Vec2 t;
      if (j == 0)
        t = chord_dir(0);
      else if (j == m)
        t = Vec2(1, 0);  // the crown: s <= 0
      else
        t = (chord_dir(j - 1) + chord_dir(j)).normalized();
      return HalfPlane{t.x(), t.y(), t.dot(p[j])};
    };
    w.left = {{1, 0, -hw}, before_joint(0)};
    std::vector<std::vector<HalfPlane>> left_arc;
    for (int j = 0; j < m; ++j)
      left_arc.push_back({below_chord(p[j], p[j + 1]).flipped(), before_joint(j).flipped(), before_joint(j + 1)});
    w.head_blocks = left_arc;
    for (int j = m - 1; j >= 0; --j) {
      std::vector<HalfPlane> v;
      for (const auto& h : left_arc[j]) v.push_back(h.mirrored());
      w.head_blocks.push_back(v);
    }
  }
  for (const auto& h : w.left) w.right.push_back(h.mirrored());
}

// Does the opening meet the stone (with volume)?
bool meets_opening(const Polyhedron& stone, int k, const Window& w) {
  std::vector<HalfPlane> opening = {{-1, 0, w.half_width}, {1, 0, w.half_width}, {0, -1, -w.sill}};
  for (size_t j = 0; j + 1 < w.profile.size(); ++j) opening.push_back(below_chord(w.profile[j], w.profile[j + 1]));
  return clip_all(stone, on_face(k, opening)).has_value();
}

// The convex pieces of the stone beside and under the opening (none if the
// opening and the head blocks take the whole stone).
std::vector<Polyhedron> cut_by_window(const Polyhedron& stone, int k, const Window& w) {
  std::vector<Polyhedron> out;
  for (const auto* region : {&w.left, &w.below, &w.right})
    if (auto piece = clip_all(stone, on_face(k, *region))) out.push_back(std::move(*piece));
  return out;
}

void require(bool ok, const char* field, const std::string& what) {
  if (!ok) throw SpireSpecError(field, what);
}

void require_finite_positive(double v, const char* field) {
  require(std::isfinite(v) && v > 0, field, "must be > 0 and finite (got " + num(v) + ")");
}

}  // namespace

double spire_outer_inradius(const SpireSpec& s, double z) {
  return outer_apothem_at_base(s) * (1.0 - z / s.height);
}

double spire_inner_inradius(const SpireSpec& s, double z) { return spire_outer_inradius(s, z) - thickness_at(s, z); }

void validate_spire(const SpireSpec& s) {
  require_finite_positive(s.height, "height");
  require_finite_positive(s.tip_height, "tip_height");
  require(s.tip_height < s.height, "tip_height",
          "must be less than height (" + num(s.height) + "), leaving a shell of courses below the tip (got " +
              num(s.tip_height) + ")");
  require_finite_positive(s.base_inradius, "base_inradius");
  require_finite_positive(s.wall_thickness, "wall_thickness");
  require_finite_positive(s.wall_thickness_top, "wall_thickness_top");
  require(s.wall_thickness < 2.0 * s.base_inradius, "wall_thickness",
          "must be less than 2·base_inradius = " + num(2.0 * s.base_inradius) + " (got " + num(s.wall_thickness) + ")");
  const double top = shell_top(s);
  const double ai_top = spire_inner_inradius(s, top);
  require(ai_top > 1e-3 * s.base_inradius, "wall_thickness_top",
          "the wall (" + num(s.wall_thickness_top) + " m) is as thick as the spire is wide at the top of the shell (z = " +
              num(top) + " m, outer inradius " + num(spire_outer_inradius(s, top)) +
              " m): the shell must stay hollow up to the solid tip");
  require_finite_positive(s.course_height, "course_height");
  require(s.course_height <= top * (1 + 1e-12), "course_height",
          "must be at most height - tip_height = " + num(top) + " (got " + num(s.course_height) + ")");
  require(top / s.course_height <= 10000, "course_height", "gives more than 10000 courses");
  require(s.stones_per_face >= 1 && s.stones_per_face <= 64, "stones_per_face",
          "must be in [1, 64] (got " + std::to_string(s.stones_per_face) + ")");
  require(s.corner_stones == SpireCornerStones::halves || s.joint_pattern == SpireJointPattern::aligned ||
              s.stones_per_face >= 2,
          "corner_stones",
          "\"merged\" needs stones_per_face >= 2 (with one stone per face merging the corner halves would line "
          "the vertical joints up) (got stones_per_face = " + std::to_string(s.stones_per_face) + ")");
  // Each setting is sane on its own, but their product can ask for millions
  // of CGAL-built stones from a three-line deck (found by fuzzing). The
  // paper's spire has about 330 blocks.
  const double stones = std::ceil(top / s.course_height) * 8.0 * s.stones_per_face;
  require(stones <= 5000, "course_height",
          "with stones_per_face = " + std::to_string(s.stones_per_face) + " gives " + num(stones) +
              " stones (at most 5000)");
  require(std::isfinite(s.base_thickness) && s.base_thickness >= 0, "base_thickness",
          "must be >= 0 and finite (0 = no base block) (got " + num(s.base_thickness) + ")");
  require(std::isfinite(s.base_apothem) && (s.base_apothem == 0 || s.base_apothem >= outer_apothem_at_base(s)),
          "base_apothem",
          "must be 0 (the shell's outline) or at least the shell's outer apothem at z = 0, " +
              num(outer_apothem_at_base(s)) + " m (got " + num(s.base_apothem) + ")");
  require(s.base_apothem <= 1000.0 * s.height, "base_apothem",
          "must be at most 1000·height (got " + num(s.base_apothem) + ")");

  std::vector<int> seen;
  for (int f : s.window_faces) {
    require(f >= 0 && f <= 7, "window_faces", "face indices are 0..7 (got " + std::to_string(f) + ")");
    require(std::find(seen.begin(), seen.end(), f) == seen.end(), "window_faces",
            "face " + std::to_string(f) + " is listed twice (one window per face)");
    seen.push_back(f);
  }
  require(s.window_arch_segments >= 1 && s.window_arch_segments <= 64, "window_arch_segments",
          "must be in [1, 64] (got " + std::to_string(s.window_arch_segments) + ")");
  require(std::isfinite(s.window_sill) && s.window_sill >= 0, "window_sill",
          "must be >= 0 (z = 0 is the bed of course 0) (got " + num(s.window_sill) + ")");
  require_finite_positive(s.window_width, "window_width");
  require(std::isfinite(s.window_head) && s.window_head > s.window_sill, "window_head",
          "must be above window_sill = " + num(s.window_sill) + " (got " + num(s.window_head) + ")");
  require(s.window_head <= top, "window_head",
          "must be at most the top of the shell, height - tip_height = " + num(top) + " (got " + num(s.window_head) +
              ")");
  if (s.window_head_shape == WindowHead::pointed) {
    const double rise = s.window_width * std::sqrt(3.0) / 2.0;
    require(s.window_head - s.window_sill >= rise, "window_head",
            "a pointed head of width " + num(s.window_width) + " m rises " + num(rise) +
                " m (equilateral arch): window_head must be at least window_sill + " + num(rise) + " = " +
                num(s.window_sill + rise) + " (got " + num(s.window_head) + ")");
  }
  // The jambs must cross the wall inside the face: the face is narrowest at
  // the inner surface at the head.
  const double room = spire_inner_inradius(s, s.window_head) * kTan8;
  require(0.5 * s.window_width < 0.999 * room, "window_width",
          "does not fit in the face: at the window head (z = " + num(s.window_head) +
              " m) the face is " + num(2 * room) + " m wide at the inner surface (got " + num(s.window_width) + ")");
}

SpireModel build_spire(const SpireSpec& s) {
  validate_spire(s);
  SpireModel model;
  model.shell_top = shell_top(s);
  model.n_courses = std::max(1, static_cast<int>(std::lround(model.shell_top / s.course_height)));
  model.course_height = model.shell_top / model.n_courses;
  const int n = s.stones_per_face;
  const int course_digits = std::max(2, static_cast<int>(std::to_string(model.n_courses - 1).size()));

  const double A = outer_apothem_at_base(s);
  if (s.base_thickness > 0) {
    std::vector<Vec2> octagon;
    const double R = (s.base_apothem > 0 ? s.base_apothem : A) / std::cos(kPi / 8.0);
    for (int k = 0; k < 8; ++k) {
      const double phi = k * kPi / 4.0 + kPi / 8.0;
      octagon.emplace_back(R * std::cos(phi), R * std::sin(phi));
    }
    GeneratedBlock b;
    b.shape = make_prism(octagon, -s.base_thickness, 0.0);
    b.kind = BlockKind::base;
    b.name = "base";
    model.blocks.push_back(std::move(b));
  }

  auto course_z0 = [&](int c) { return c * model.course_height; };
  auto course_z1 = [&](int c) { return c + 1 == model.n_courses ? model.shell_top : (c + 1) * model.course_height; };

  Window window;
  window.half_width = 0.5 * s.window_width;
  window.sill = s.window_sill;
  window.head = s.window_head;
  window.pointed = s.window_head_shape == WindowHead::pointed;
  window.profile = head_points(s);
  // The head courses: from the one holding the springing (flat: the head)
  // to the first whose top is at least half a course above the head.
  if (window.pointed) {
    window.spring = window.profile.front().y();
    const Vec2 d = window.profile[1] - window.profile[0];
    window.spring_slope = d.y() / d.x();
  }
  const double head_bottom = window.pointed ? window.spring : window.head;
  for (int c = 0; c < model.n_courses; ++c) {
    if (window.head_lo < 0 && course_z1(c) > head_bottom + 1e-12) window.head_lo = c;
    if (window.head_lo >= 0 &&
        (course_z1(c) >= window.head + 0.5 * model.course_height - 1e-12 || c + 1 == model.n_courses)) {
      window.head_hi = c;
      break;
    }
  }
  // (No head course: a flat head at the top of the shell, under the tip.)
  if (window.head_lo >= 0) window.head_top = course_z1(window.head_hi);
  if (!window.pointed && window.head_lo >= 0) {
    // The lintel bears on each jamb over half the wall left beside the
    // opening at the inner surface at its top (the face's narrowest place).
    const double room = spire_inner_inradius(s, window.head_top) * kTan8 - window.half_width;
    window.lintel_half = room > 0.02 * s.window_width ? window.half_width + 0.5 * room : 0.0;
  }
  build_regions(window);
  if (window.head_lo < 0) window.head_blocks.clear();
  auto has_window = [&](int k) {
    return std::find(s.window_faces.begin(), s.window_faces.end(), k) != s.window_faces.end();
  };
  // The face's courses [c_lo, c_hi] as one slab between the corner planes.
  auto face_slab = [&](int k, int c_lo, int c_hi) {
    const double z0 = course_z0(c_lo), z1 = course_z1(c_hi), zm = 0.5 * (z0 + z1);
    const double am = 0.5 * (spire_outer_inradius(s, zm) + spire_inner_inradius(s, zm));
    return intersect({outer_plane(s, k), inner_plane(s, k), z_at_least(z0), z_at_most(z1), low_corner_plane(k),
                      high_corner_plane(k)},
                     am * face_normal(k) + Vec3(0, 0, zm));
  };

  std::vector<bool> jambs_continue(8, true);  // aligned_above_windows: still continuing the jambs
  for (int c = 0; c < model.n_courses; ++c) {
    const double z0 = course_z0(c);
    const double z1 = course_z1(c);
    const double zm = 0.5 * (z0 + z1);
    const double am = 0.5 * (spire_outer_inradius(s, zm) + spire_inner_inradius(s, zm));
    const double face_width = 2.0 * am * kTan8;   // mid-wall, mid-course
    const double nominal = face_width / n;         // nominal stone width
    const bool odd = c % 2 == 1;
    const bool head_course = c >= window.head_lo && c <= window.head_hi;

    for (int k = 0; k < 8; ++k) {
      const bool win = has_window(k);
      const bool window_course = win && z0 < window.head - 1e-12 && z1 > window.sill + 1e-12;
      const bool zone_course = win && head_course;
      std::vector<double> joints;
      bool on_jambs = false;
      if (s.joint_pattern == SpireJointPattern::aligned_above_windows && win && jambs_continue[k] &&
          z1 > window.sill + 1e-12) {
        const double side = spire_inner_inradius(s, z1) * kTan8 - window.half_width;
        if (side >= 0.25 * nominal)
          on_jambs = true;
        else
          jambs_continue[k] = false;
      }
      if (on_jambs) {
        joints = {-window.half_width, window.half_width};
      } else {
        const bool shift = odd && s.joint_pattern != SpireJointPattern::aligned;
        const bool merge = shift && s.corner_stones == SpireCornerStones::merged;
        for (int j = 1; j < (shift ? n + 1 : n); ++j) {
          if (merge && (j == 1 || j == n)) continue;  // the corner halves join their neighbours
          const double f = shift ? (j - 0.5) / n : static_cast<double>(j) / n;
          joints.push_back((f - 0.5) * face_width);
        }
        // Joints next to a jamb move onto it: no slivers beside the window.
        if (window_course)
          for (double& x : joints)
            for (double jamb : {-window.half_width, window.half_width})
              if (std::abs(x - jamb) < 0.25 * nominal) x = jamb;
      }
      if (zone_course) {
        // One zone stone takes what the head blocks leave of this course
        // around the opening: no joint within s_zone (or a quarter stone
        // beyond it), none at all if the stones outside would be slivers.
        double s_zone = 0;
        if (window.pointed)
          s_zone = window.half_width + std::max(0.0, z1 - window.spring) * window.spring_slope;
        else
          s_zone = window.lintel_half;
        const double inner_half = spire_inner_inradius(s, z1) * kTan8;
        const bool whole_face = s_zone <= 0 || (window.pointed && inner_half - s_zone < 0.25 * nominal);
        std::erase_if(joints, [&](double x) { return whole_face || std::abs(x) < s_zone + 0.25 * nominal; });
        if (!whole_face) joints.push_back(-s_zone), joints.push_back(s_zone);
      }
      std::sort(joints.begin(), joints.end());
      joints.erase(std::unique(joints.begin(), joints.end()), joints.end());

      const int n_stones = static_cast<int>(joints.size()) + 1;
      const double corner = am * kTan8;  // s of the corners at mid-wall
      for (int i = 0; i < n_stones; ++i) {
        std::vector<Plane> planes = {outer_plane(s, k), inner_plane(s, k), z_at_least(z0), z_at_most(z1)};
        const double lo = i == 0 ? -corner : joints[i - 1];
        const double hi = i + 1 == n_stones ? corner : joints[i];
        planes.push_back(i == 0 ? low_corner_plane(k) : s_at_least(k, lo));
        planes.push_back(i + 1 == n_stones ? high_corner_plane(k) : s_at_most(k, hi));
        const Vec3 interior = am * face_normal(k) + 0.5 * (lo + hi) * face_tangent(k) + Vec3(0, 0, zm);
        const std::string name =
            "course" + zero_padded(c, course_digits) + "_face" + std::to_string(k) + "_stone" + std::to_string(i);
        Polyhedron stone;
        try {
          stone = intersect(planes, interior);
        } catch (const GeometryError& e) {
          throw GeometryError("spire: cannot build " + name + ": " + e.what());
        }
        const bool zone_stone = zone_course && lo < 0 && hi > 0;
        bool cut = false;
        std::vector<Polyhedron> pieces;
        if (window_course || zone_stone) {
          try {
            cut = zone_stone || meets_opening(stone, k, window);
            if (cut) pieces = cut_by_window(stone, k, window);
          } catch (const GeometryError& e) {
            throw GeometryError("spire: cannot cut the window out of " + name + ": " + e.what());
          }
        }
        if (!cut) pieces.push_back(std::move(stone));
        if (cut) ++model.stones_cut_by_windows;
        for (size_t p = 0; p < pieces.size(); ++p) {
          GeneratedBlock b;
          b.shape = std::move(pieces[p]);
          b.kind = cut ? BlockKind::window_piece : BlockKind::stone;
          b.course = c;
          b.face = k;
          b.index = i;
          b.piece = cut ? static_cast<int>(p) : -1;
          b.name = cut ? name + "_piece" + std::to_string(p) : name;
          if (cut) ++model.window_pieces;
          model.blocks.push_back(std::move(b));
        }
      }

      // The head blocks, once per window, with the lowest head course.
      if (win && c == window.head_lo) {
        const std::string prefix = "course" + zero_padded(c, course_digits) + "_face" + std::to_string(k);
        Polyhedron slab;
        try {
          slab = face_slab(k, window.head_lo, window.head_hi);
        } catch (const GeometryError& e) {
          throw GeometryError("spire: cannot build the head courses of " + prefix + ": " + e.what());
        }
        for (size_t v = 0; v < window.head_blocks.size(); ++v) {
          const std::string name = prefix + (window.pointed ? "_voussoir" + std::to_string(v) : "_lintel");
          std::optional<Polyhedron> shape;
          try {
            shape = clip_all(slab, on_face(k, window.head_blocks[v]));
          } catch (const GeometryError& e) {
            throw GeometryError("spire: cannot build " + name + ": " + e.what());
          }
          if (!shape) throw GeometryError("spire: " + name + " is empty");
          GeneratedBlock b;
          b.shape = std::move(*shape);
          b.kind = BlockKind::window_piece;
          b.course = c;
          b.face = k;
          b.piece = static_cast<int>(v);
          b.name = name;
          ++model.window_pieces;
          model.blocks.push_back(std::move(b));
        }
      }
    }
  }

  std::vector<Plane> tip_planes;
  for (int k = 0; k < 8; ++k) tip_planes.push_back(outer_plane(s, k));
  tip_planes.push_back(z_at_least(model.shell_top));
  GeneratedBlock tip;
  tip.shape = intersect(tip_planes, Vec3(0, 0, model.shell_top + 0.25 * s.tip_height));
  tip.kind = BlockKind::tip;
  tip.course = model.n_courses;
  tip.name = "tip";
  model.blocks.push_back(std::move(tip));
  return model;
}

}  // namespace polydem
