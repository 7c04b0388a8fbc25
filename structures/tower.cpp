// The tower builder: course by course, face by face, stone by stone (see
// tower.hpp).
//
// Every stone, piece and lintel is a vertical prism: its plan is a convex
// polygon cut by half-planes from a large square (Sutherland-Hodgman): the
// face's outer and inner lines, the joints s = const, and at a corner either
// s = ±(inner half-width) (the face that does not own the corner) or the
// other face's outer line and the line through the inner corner
// perpendicular to the other face (the face that owns it). Openings and
// their heads are worked out in the face's (s, z) plane by
// structures/coursed_openings; the rectangles left of a stone beside or under
// an opening only narrow its s range and its z range, so they stay prisms.
// Voussoirs are half-space intersections through the wall
// (halfspace_intersection, CGAL).
#include "structures/generator_text.hpp"
#include "structures/tower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "structures/coursed_openings.hpp"

namespace polydem {

namespace {

using generator_text::num;
using generator_text::zero_padded;

constexpr double kPi = std::numbers::pi;
using masonry::kSliver;
using masonry::Segment;

void require(bool ok, const char* field, int opening, const std::string& what) {
  if (!ok) throw TowerSpecError(field, opening, what);
}

using masonry::Line;
using masonry::clip;
using masonry::cleaned;

int n_courses(const TowerSpec& s) { return std::max(1, static_cast<int>(std::lround(s.height / s.course_height))); }

double stone_length(const TowerSpec& s) {
  const double am = s.outer_apothem - 0.5 * s.wall_thickness;
  return 2.0 * am * std::tan(kPi / s.sides) / s.stones_per_face;
}

double extent_of(const TowerSpec& s, const TowerOpening& o) {
  const double e = o.head == OpeningHead::lintel ? o.bearing : o.ring;
  return e > 0 ? e : 0.5 * stone_length(s);
}

masonry::Opening opening_of(const TowerSpec& s, const TowerOpening& o, int courses, double ch) {
  return masonry::make_opening(-0.5 * o.width, o.sill, o.width, o.height, o.head == OpeningHead::arch,
                               extent_of(s, o), o.voussoirs, courses, ch);
}

}  // namespace

void validate_tower(const TowerSpec& s) {
  auto finite_positive = [&](double v, const char* field) {
    require(std::isfinite(v) && v > 0, field, -1, "must be > 0 and finite (got " + num(v) + ")");
  };
  require(!s.name.empty(), "name", -1, "must not be empty");
  require(s.sides == 4 || s.sides == 8, "sides", -1, "must be 4 (square) or 8 (octagonal) (got " +
                                                         std::to_string(s.sides) + ")");
  require(s.origin.allFinite(), "origin", -1, "must be finite");
  finite_positive(s.outer_apothem, "outer_apothem");
  finite_positive(s.wall_thickness, "wall_thickness");
  finite_positive(s.height, "height");
  finite_positive(s.course_height, "course_height");
  require(s.wall_thickness < 0.9 * s.outer_apothem, "wall_thickness", -1,
          "must be less than 0.9 × outer_apothem = " + num(0.9 * s.outer_apothem) +
              ": the tower is hollow (got " + num(s.wall_thickness) + ")");
  require(s.course_height <= s.height * (1 + 1e-12), "course_height", -1,
          "must be at most height = " + num(s.height) + " (got " + num(s.course_height) + ")");
  require(s.stones_per_face >= 1 && s.stones_per_face <= 32, "stones_per_face", -1,
          "must be in [1, 32] (got " + std::to_string(s.stones_per_face) + ")");
  const double blocks = std::ceil(s.height / s.course_height) * s.sides * (s.stones_per_face + 1);
  require(blocks <= 20000, "course_height", -1,
          "with stones_per_face = " + std::to_string(s.stones_per_face) + " gives about " + num(blocks) +
              " stones (at most 20000)");
  const int courses = n_courses(s);
  const double ch = s.height / courses;
  const double tn = std::tan(kPi / s.sides);
  const double inner_half = (s.outer_apothem - s.wall_thickness) * tn;
  const double ell = stone_length(s);
  std::vector<int> face_used(static_cast<std::size_t>(s.sides), -1);
  for (std::size_t i = 0; i < s.openings.size(); ++i) {
    const TowerOpening& o = s.openings[i];
    const int k = static_cast<int>(i);
    require(!o.faces.empty(), "faces", k, "must list at least one face");
    for (int f : o.faces) {
      require(f >= 0 && f < s.sides, "faces", k,
              "face indices are 0.." + std::to_string(s.sides - 1) + " (got " + std::to_string(f) + ")");
      require(face_used[static_cast<std::size_t>(f)] < 0, "faces", k,
              "face " + std::to_string(f) + " already has opening " +
                  std::to_string(face_used[static_cast<std::size_t>(f)]) + " (one opening per face)");
      face_used[static_cast<std::size_t>(f)] = k;
    }
    require(std::isfinite(o.width) && o.width > 0, "width", k, "must be > 0 (got " + num(o.width) + ")");
    require(std::isfinite(o.height) && o.height > 0, "height", k, "must be > 0 (got " + num(o.height) + ")");
    require(std::isfinite(o.sill) && o.sill >= 0, "sill", k, "must be >= 0 (got " + num(o.sill) + ")");
    const double e = extent_of(s, o);
    const char* e_key = o.head == OpeningHead::lintel ? "bearing" : "ring";
    require(e >= kSliver * ell * (1 - 1e-9), e_key, k,
            "must be at least a quarter stone (" + num(kSliver * ell) + " m) (got " + num(e) + ")");
    if (o.head == OpeningHead::arch) {
      require(o.voussoirs >= 3 && o.voussoirs <= 64, "voussoirs", k,
              "must be in [3, 64] (got " + std::to_string(o.voussoirs) + ")");
      require(o.height >= 0.5 * o.width * (1 - 1e-12), "height", k,
              "a semicircular arch of width " + num(o.width) + " m rises " + num(0.5 * o.width) +
                  " m: height must be at least that (got " + num(o.height) + ")");
    }
    const double room = inner_half - kSliver * ell;
    require(0.5 * o.width + e <= room * (1 + 1e-12), "width", k,
            "the opening and its head's " + std::string(e_key) + " (" + num(e) + " m each side) span " +
                num(o.width + 2 * e) + " m, more than the face leaves between its corners (" + num(2 * room) +
                " m: the inner face width less a quarter stone at each end)");
    const masonry::Opening g = opening_of(s, o, courses, ch);
    for (const auto& problem : masonry::level_problems(g, o.height, ch, s.height))
      throw TowerSpecError(problem.key, k, problem.what);
  }
}

TowerModel build_tower(const TowerSpec& s) {
  validate_tower(s);
  TowerModel m;
  m.n_courses = n_courses(s);
  m.course_height = s.height / m.n_courses;
  m.stone_length = stone_length(s);
  m.top = s.origin.z() + s.height;
  const int N = s.sides, n = s.stones_per_face;
  const double A = s.outer_apothem, T = s.wall_thickness, Ai = A - T, Am = A - 0.5 * T;
  const double tn = std::tan(kPi / N);
  const double ch = m.course_height, ell = m.stone_length;
  const double tol = 1e-12 * A;
  const double min_len = kSliver * ell * (1 - 1e-9);
  const int course_digits = std::max(2, static_cast<int>(std::to_string(m.n_courses - 1).size()));

  auto normal = [&](int k) {
    const int kk = ((k % N) + N) % N;
    const double th = 2.0 * kPi * kk / N;
    return Vec2(std::cos(th), std::sin(th));
  };
  auto tangent = [&](int k) {
    const Vec2 nk = normal(k);
    return Vec2(-nk.y(), nk.x());
  };

  // Openings by face.
  std::vector<std::vector<masonry::Opening>> face_openings(static_cast<std::size_t>(N));
  std::vector<std::vector<int>> face_opening_index(static_cast<std::size_t>(N));
  m.solid_volume = N * tn * (A * A - Ai * Ai) * s.height;
  for (std::size_t i = 0; i < s.openings.size(); ++i)
    for (int f : s.openings[i].faces) {
      face_openings[static_cast<std::size_t>(f)].push_back(opening_of(s, s.openings[i], m.n_courses, ch));
      face_opening_index[static_cast<std::size_t>(f)].push_back(static_cast<int>(i));
      m.solid_volume -= masonry::opening_area(face_openings[static_cast<std::size_t>(f)].back()) * T;
    }

  const double big = 10.0 * A;
  const std::vector<Vec2> square = {{-big, -big}, {big, -big}, {big, big}, {-big, big}};
  auto prism = [&](const std::vector<Line>& lines, double z0, double z1, const std::string& name) {
    std::vector<Vec2> poly = square;
    for (const Line& l : lines) poly = clip(poly, l);
    poly = cleaned(poly, 1e-12 * A);
    for (auto& v : poly) v += s.origin.head<2>();
    try {
      return make_prism(poly, s.origin.z() + z0, s.origin.z() + z1);
    } catch (const GeometryError& e) {
      throw GeometryError("tower: cannot build " + name + ": " + e.what());
    }
  };

  for (int c = 0; c < m.n_courses; ++c) {
    const double z0 = c * ch, z1 = c + 1 == m.n_courses ? s.height : (c + 1) * ch;
    for (int k = 0; k < N; ++k) {
      const bool owns = (k + c) % 2 == 0;
      const Vec2 nk = normal(k), tk = tangent(k);
      const double s_end = owns ? A * tn : Ai * tn;
      // The face's joints.
      std::vector<double> joints;
      if (owns)
        for (int j = 1; j < n; ++j) joints.push_back((j - 0.5 * n) * ell);
      else
        for (int j = 1; j <= n; ++j) joints.push_back((j - 0.5 * n - 0.5) * ell);
      std::erase_if(joints, [&](double x) { return std::abs(x) > Ai * tn - min_len; });
      std::vector<Segment> segs;
      double prev = -s_end;
      for (double x : joints) segs.push_back({prev, x, true, static_cast<int>(BlockKind::stone)}), prev = x;
      segs.push_back({prev, s_end, true, static_cast<int>(BlockKind::stone)});
      const auto& openings = face_openings[static_cast<std::size_t>(k)];
      for (const auto& g : openings)
        masonry::fit_course(segs, g, c, z0, z1, ch, min_len, tol, static_cast<int>(BlockKind::jamb));

      const std::string base_name = s.name + "_course" + zero_padded(c, course_digits) + "_face" + std::to_string(k);
      for (std::size_t i = 0; i < segs.size(); ++i) {
        const Segment& seg = segs[i];
        bool cut = false;
        const auto rects = masonry::cut_by_openings({seg.u0, seg.u1, z0, z1}, openings, ch, tol, cut);
        for (std::size_t p = 0; p < rects.size(); ++p) {
          const masonry::Rect& r = rects[p];
          std::vector<Line> lines = {{nk, A}, {-nk, -Ai}};
          const bool low_end = i == 0 && r.u0 <= seg.u0 + tol;
          const bool high_end = i + 1 == segs.size() && r.u1 >= seg.u1 - tol;
          if (!low_end) lines.push_back({-tk, -r.u0});
          if (!high_end) lines.push_back({tk, r.u1});
          if (low_end) {
            if (owns) {
              lines.push_back({normal(k - 1), A});
              lines.push_back({-tangent(k - 1), -Ai * tn});
            } else {
              lines.push_back({-tk, Ai * tn});
            }
          }
          if (high_end) {
            if (owns) {
              lines.push_back({normal(k + 1), A});
              lines.push_back({tangent(k + 1), -Ai * tn});
            } else {
              lines.push_back({tk, Ai * tn});
            }
          }
          GeneratedBlock b;
          b.name = base_name + "_stone" + std::to_string(i) + (cut ? "_piece" + std::to_string(p) : std::string());
          b.shape = prism(lines, r.z0, r.z1, b.name);
          b.kind = static_cast<BlockKind>(seg.kind);
          b.course = c;
          b.face = k;
          m.blocks.push_back(std::move(b));
        }
      }
      // Head blocks starting in this course.
      for (std::size_t q = 0; q < openings.size(); ++q) {
        const masonry::Opening& g = openings[q];
        if (g.head_lo != c) continue;
        const std::string prefix =
            s.name + "_face" + std::to_string(k) + "_opening" + std::to_string(face_opening_index[static_cast<std::size_t>(k)][q]);
        if (!g.arch) {
          GeneratedBlock b;
          b.name = prefix + "_lintel";
          b.shape = prism({{nk, A}, {-nk, -Ai}, {-tk, -g.zone_a}, {tk, g.zone_b}}, g.head, g.head_top, b.name);
          b.kind = BlockKind::lintel;
          b.course = c;
          b.face = k;
          b.opening = face_opening_index[static_cast<std::size_t>(k)][q];
          m.blocks.push_back(std::move(b));
          continue;
        }
        const Vec3 n3(nk.x(), nk.y(), 0), t3(tk.x(), tk.y(), 0), ez(0, 0, 1);
        for (int j = 0; j < g.voussoirs; ++j) {
          Vec2 inside;
          std::vector<Vec3> normals;
          std::vector<double> offsets;
          for (const masonry::HalfPlane& h : masonry::voussoir(g, j, inside)) {
            normals.push_back(h.a * t3 + h.b * ez);
            offsets.push_back(h.d + normals.back().dot(s.origin));
          }
          normals.push_back(n3), offsets.push_back(A + n3.dot(s.origin));
          normals.push_back(-n3), offsets.push_back(-Ai - n3.dot(s.origin));
          const Vec3 interior = s.origin + Am * n3 + inside.x() * t3 + inside.y() * ez;
          GeneratedBlock b;
          b.name = prefix + "_voussoir" + std::to_string(j);
          try {
            b.shape = halfspace_intersection(normals, offsets, interior);
          } catch (const GeometryError& e) {
            throw GeometryError("tower: cannot build " + b.name + ": " + e.what());
          }
          b.kind = BlockKind::voussoir;
          b.course = c;
          b.face = k;
          b.opening = face_opening_index[static_cast<std::size_t>(k)][q];
          m.blocks.push_back(std::move(b));
        }
      }
    }
  }
  return m;
}

}  // namespace polydem
