// The tower generator: the stones tile the hollow shaft exactly (inside the
// outer prism and outside the inner one, outside every opening, no two
// overlapping, volumes summing to the solid's computed here to 1e-9), the
// corners interlock course by course, the vertical joints stagger, and bad
// specs name their field.
#include "structures/tower.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "convex_overlap.hpp"

namespace polydem {
namespace {

constexpr double kPi = std::numbers::pi;
using test::interiors_overlap;

Vec2 normal(int k, int N) { return {std::cos(2 * kPi * k / N), std::sin(2 * kPi * k / N)}; }

// The opening through face k as a prism (an arch's head as its chords).
Polyhedron opening_prism(const TowerSpec& s, const TowerOpening& o, int k) {
  std::vector<Vec2> outline;  // (along the face, z)
  const double top = o.sill + o.height, h = 0.5 * o.width;
  if (o.head == OpeningHead::lintel) {
    outline = {{-h, o.sill}, {h, o.sill}, {h, top}, {-h, top}};
  } else {
    const double spring = top - h;
    if (spring > o.sill + 1e-12) outline.push_back({-h, o.sill}), outline.push_back({h, o.sill});
    for (int j = o.voussoirs; j >= 0; --j) {
      const double a = kPi - kPi * j / o.voussoirs;
      outline.push_back({h * std::cos(a), spring + h * std::sin(a)});
    }
  }
  const double A = s.outer_apothem, Ai = A - s.wall_thickness;
  const Polyhedron p = make_prism(outline, Ai, A);  // (s, z, n)
  const Vec2 nk = normal(k, s.sides);
  Mat3 R;
  R.col(0) = Vec3(-nk.y(), nk.x(), 0);
  R.col(1) = Vec3(0, 0, 1);
  R.col(2) = Vec3(nk.x(), nk.y(), 0);
  return transformed(p, R, s.origin);
}

double solid(const TowerSpec& s) {
  const double tn = std::tan(kPi / s.sides), A = s.outer_apothem, Ai = A - s.wall_thickness;
  double v = s.sides * tn * (A * A - Ai * Ai) * s.height;
  for (const auto& o : s.openings) {
    const double h = 0.5 * o.width;
    const double area = o.head == OpeningHead::lintel
                            ? o.width * o.height
                            : o.width * (o.height - h) + 0.5 * o.voussoirs * h * h * std::sin(kPi / o.voussoirs);
    v -= area * s.wall_thickness * static_cast<double>(o.faces.size());
  }
  return v;
}

TowerModel expect_exact_tiling(const TowerSpec& s) {
  const TowerModel m = build_tower(s);
  const double expected = solid(s);
  EXPECT_NEAR(m.solid_volume, expected, 1e-12 * expected);
  const double A = s.outer_apothem, Ai = A - s.wall_thickness, tol = 1e-9 * A;
  std::vector<Polyhedron> holes;
  for (const auto& o : s.openings)
    for (int k : o.faces) holes.push_back(opening_prism(s, o, k));
  double sum = 0;
  std::vector<Eigen::AlignedBox3d> boxes;
  std::set<std::string> names;
  for (const auto& b : m.blocks) {
    EXPECT_NO_THROW(validate(b.shape)) << b.name;
    EXPECT_TRUE(names.insert(b.name).second) << "duplicate " << b.name;
    sum += mass_properties(b.shape).volume;
    for (const auto& x : b.shape.vertices) {
      const Vec3 r = x - s.origin;
      double outmost = -1e300;
      for (int k = 0; k < s.sides; ++k) {
        const double d = normal(k, s.sides).dot(r.head<2>());
        EXPECT_LE(d, A + tol) << b.name;
        outmost = std::max(outmost, d);
      }
      EXPECT_GE(outmost, Ai - tol) << b.name << " reaches into the shaft";
      EXPECT_GE(r.z(), -tol);
      EXPECT_LE(r.z(), s.height + tol);
    }
    for (const auto& h : holes) EXPECT_FALSE(interiors_overlap(b.shape, h, 1e-9)) << b.name << " is in an opening";
    Eigen::AlignedBox3d box;
    for (const auto& v : b.shape.vertices) box.extend(v);
    boxes.push_back(box.extend(box.min() - Vec3::Constant(1e-9)).extend(box.max() + Vec3::Constant(1e-9)));
  }
  EXPECT_NEAR(sum, expected, 1e-9 * expected);
  for (std::size_t i = 0; i < m.blocks.size(); ++i)
    for (std::size_t j = i + 1; j < m.blocks.size(); ++j)
      if (boxes[i].intersects(boxes[j])) {
        EXPECT_FALSE(interiors_overlap(m.blocks[i].shape, m.blocks[j].shape, 1e-9))
            << m.blocks[i].name << " overlaps " << m.blocks[j].name;
      }
  return m;
}

TowerSpec octagon_tower() {
  TowerSpec s;
  s.name = "t";
  s.sides = 8;
  s.origin = Vec3(0.5, -0.25, 1.0);
  s.outer_apothem = 2.0;
  s.wall_thickness = 0.5;
  s.height = 2.4;
  s.course_height = 0.3;
  s.stones_per_face = 3;
  return s;
}

// The s (along face k) of the vertical joints on the outer face, per course.
std::map<int, std::vector<double>> outer_joints(const TowerSpec& s, const TowerModel& m, int k) {
  std::map<int, std::set<double>> sets;
  const Vec2 nk = normal(k, s.sides), tk(-nk.y(), nk.x());
  const double edge = s.outer_apothem * std::tan(kPi / s.sides);
  for (const auto& b : m.blocks) {
    if (b.face != k) continue;
    for (const auto& x : b.shape.vertices) {
      const Vec2 r = (x - s.origin).head<2>();
      const double sv = tk.dot(r);
      if (std::abs(nk.dot(r) - s.outer_apothem) < 1e-9 && std::abs(std::abs(sv) - edge) > 1e-9)
        sets[b.course].insert(std::round(sv * 1e9) / 1e9);
    }
  }
  std::map<int, std::vector<double>> out;
  for (auto& [c, v] : sets) out[c] = std::vector<double>(v.begin(), v.end());
  return out;
}

TEST(Tower, OctagonalShaftTilesExactlyWithStaggeredJoints) {
  const TowerSpec s = octagon_tower();
  const TowerModel m = expect_exact_tiling(s);
  EXPECT_EQ(m.n_courses, 8);
  EXPECT_NEAR(m.top, 3.4, 1e-12);
  for (int k = 0; k < 8; ++k) {
    const auto joints = outer_joints(s, m, k);
    for (int c = 0; c + 1 < m.n_courses; ++c) {
      double best = 1e300;
      for (double a : joints.at(c))
        for (double b : joints.at(c + 1)) best = std::min(best, std::abs(a - b));
      EXPECT_GE(best, 0.25 * m.stone_length) << "face " << k << " course " << c;
    }
  }
}

TEST(Tower, SquareCornersInterlockCourseByCourse) {
  TowerSpec s = octagon_tower();
  s.sides = 4;
  s.origin = Vec3::Zero();
  const TowerModel m = expect_exact_tiling(s);
  // The outer corner (A, A) belongs to face 0's stone in even courses and
  // to face 1's in odd ones.
  const double A = s.outer_apothem;
  for (const auto& b : m.blocks) {
    bool has_corner = false;
    for (const auto& v : b.shape.vertices) has_corner = has_corner || (v.head<2>() - Vec2(A, A)).norm() < 1e-9;
    if (!has_corner) continue;
    EXPECT_EQ(b.face, b.course % 2 == 0 ? 0 : 1) << b.name;
    // A quoin: as deep as the wall is thick along the other face.
    double x0 = 1e300, y0 = 1e300;
    for (const auto& v : b.shape.vertices) x0 = std::min(x0, v.x()), y0 = std::min(y0, v.y());
    EXPECT_NEAR(b.face == 0 ? x0 : y0, A - s.wall_thickness, 1e-12) << b.name;
  }
}

TEST(Tower, BelfryOpeningsWithLintelsAndArches) {
  TowerSpec s = octagon_tower();
  s.height = 3.0;
  s.openings = {TowerOpening{.faces = {0, 4}, .sill = 0.6, .width = 0.4, .height = 0.9},
                TowerOpening{.faces = {2, 6}, .sill = 0.9, .width = 0.4, .height = 1.2, .head = OpeningHead::arch,
                             .voussoirs = 5}};
  const TowerModel m = expect_exact_tiling(s);
  int lintels = 0, voussoirs = 0;
  for (const auto& b : m.blocks) {
    lintels += b.kind == BlockKind::lintel;
    voussoirs += b.kind == BlockKind::voussoir;
  }
  EXPECT_EQ(lintels, 2);
  EXPECT_EQ(voussoirs, 10);
}

void expect_spec_error(const TowerSpec& s, const std::string& field, int opening, const std::string& fragment) {
  try {
    build_tower(s);
    ADD_FAILURE() << "accepted; expected an error on " << field;
  } catch (const TowerSpecError& e) {
    EXPECT_EQ(e.field, field) << e.what();
    EXPECT_EQ(e.opening, opening) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Tower, BadSpecsNameTheirField) {
  TowerSpec s = octagon_tower();
  s.sides = 6;
  expect_spec_error(s, "sides", -1, "4 (square) or 8");
  s = octagon_tower();
  s.wall_thickness = 1.9;
  expect_spec_error(s, "wall_thickness", -1, "hollow");
  const TowerOpening window{.faces = {0}, .sill = 0.6, .width = 0.4, .height = 0.9};
  s = octagon_tower();
  s.openings = {window};
  s.openings[0].width = 0.7;
  expect_spec_error(s, "width", 0, "between its corners");
  s.openings = {window, window};
  expect_spec_error(s, "faces", 1, "already has opening 0");
  s.openings = {window};
  s.openings[0].faces = {8};
  expect_spec_error(s, "faces", 0, "0..7");
  s.openings[0] = window;
  s.openings[0].height = 1.65;  // head 2.25: half a course above is 2.4, the top
  EXPECT_NO_THROW(build_tower(s));
  s.openings[0].height = 1.7;
  expect_spec_error(s, "height", 0, "cuts the top course");
  s.openings[0] = window;
  s.openings[0].sill = 0.65;
  expect_spec_error(s, "sill", 0, "quarter course");
}

}  // namespace
}  // namespace polydem
