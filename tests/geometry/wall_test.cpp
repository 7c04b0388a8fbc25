// The wall generator: the blocks tile the wall exactly. Three checks that
// together say so: every block lies inside the wall's box and outside every
// opening, no two blocks overlap (separating axes), and their volumes sum to
// the solid's (the box minus the openings, computed here) to 1e-9 relative.
// Then the bonds' joint patterns, the sliver rule, the heads over openings,
// and each validation rule.
#include "geometry/wall.hpp"

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

double volume(const Polyhedron& p) { return mass_properties(p).volume; }

using test::interiors_overlap;

// Vertices in the wall's frame (u, v, z).
std::vector<Vec3> local(const WallSpec& s, const WallModel& m, const Polyhedron& p) {
  std::vector<Vec3> out;
  for (const auto& x : p.vertices) out.push_back(m.rotation.transpose() * (x - s.origin));
  return out;
}

// The opening as a prism in the world (an arch's head as its chords).
Polyhedron opening_prism(const WallSpec& s, const WallModel& m, const WallOpening& o) {
  std::vector<Vec2> outline;  // (u, z)
  const double top = o.sill + o.height;
  if (o.head == OpeningHead::lintel) {
    outline = {{o.position, o.sill}, {o.position + o.width, o.sill}, {o.position + o.width, top}, {o.position, top}};
  } else {
    const double R = 0.5 * o.width, c = o.position + R, spring = top - R;
    if (spring > o.sill + 1e-12) outline.push_back({o.position, o.sill}), outline.push_back({o.position + o.width, o.sill});
    for (int j = o.voussoirs; j >= 0; --j) {
      const double a = kPi - kPi * j / o.voussoirs;
      outline.push_back({c + R * std::cos(a), spring + R * std::sin(a)});
    }
  }
  // make_prism extrudes along z: build in (u, z, v) and turn into (u, v, z).
  const Polyhedron p = make_prism(outline, -0.5 * m.thickness, 0.5 * m.thickness);
  Mat3 swap;
  swap << 1, 0, 0, 0, 0, 1, 0, 1, 0;  // (u, z, v) -> (u, v, z)
  return transformed(p, m.rotation * swap, s.origin);
}

double box_minus_openings(const WallSpec& s, double thickness) {
  double area = s.length * s.height + 0.5 * s.length * s.gable_height;
  for (const auto& o : s.openings) {
    if (o.head == OpeningHead::lintel) {
      area -= o.width * o.height;
    } else {
      const double R = 0.5 * o.width;
      area -= o.width * (o.height - R) + 0.5 * o.voussoirs * R * R * std::sin(kPi / o.voussoirs);
    }
  }
  return area * thickness;
}

// The three checks of the file's opening; returns the model.
WallModel expect_exact_tiling(const WallSpec& s) {
  const WallModel m = build_wall(s);
  const double T = wall_thickness(s);
  EXPECT_DOUBLE_EQ(m.thickness, T);
  const double expected = box_minus_openings(s, T);
  EXPECT_NEAR(m.solid_volume, expected, 1e-12 * expected);
  double sum = 0;
  const double tol = 1e-9 * (s.length + s.height);
  std::vector<Polyhedron> holes;
  for (const auto& o : s.openings) holes.push_back(opening_prism(s, m, o));
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const auto& b : m.blocks) {
    EXPECT_NO_THROW(validate(b.shape)) << b.name;
    sum += volume(b.shape);
    for (const auto& x : local(s, m, b.shape)) {
      EXPECT_GE(x.x(), -tol) << b.name;
      EXPECT_LE(x.x(), s.length + tol) << b.name;
      EXPECT_GE(x.y(), -0.5 * T - tol) << b.name;
      EXPECT_LE(x.y(), 0.5 * T + tol) << b.name;
      EXPECT_GE(x.z(), -tol) << b.name;
      EXPECT_LE(x.z(), s.height + s.gable_height * (1 - std::abs(2 * x.x() / s.length - 1)) + tol) << b.name;
    }
    for (std::size_t k = 0; k < holes.size(); ++k)
      EXPECT_FALSE(interiors_overlap(b.shape, holes[k], 1e-9)) << b.name << " is in opening " << k;
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
  std::set<std::string> names;
  for (const auto& b : m.blocks) EXPECT_TRUE(names.insert(b.name).second) << "duplicate name " << b.name;
  return m;
}

// The vertical joints of each course on the wall's face v = -T/2 (the u of
// block ends, without the wall's ends).
std::map<int, std::vector<double>> face_joints(const WallSpec& s, const WallModel& m) {
  std::map<int, std::set<double>> sets;
  const double T = m.thickness;
  for (const auto& b : m.blocks) {
    const auto xs = local(s, m, b.shape);
    double u0 = 1e300, u1 = -1e300, v0 = 1e300;
    for (const auto& x : xs) u0 = std::min(u0, x.x()), u1 = std::max(u1, x.x()), v0 = std::min(v0, x.y());
    if (std::abs(v0 + 0.5 * T) > 1e-9) continue;
    for (double u : {u0, u1})
      if (u > 1e-9 && u < s.length - 1e-9) sets[b.course].insert(std::round(u * 1e9) / 1e9);
  }
  std::map<int, std::vector<double>> out;
  for (auto& [c, set] : sets) out[c] = std::vector<double>(set.begin(), set.end());
  return out;
}

// The smallest distance between a vertical joint of one course and one of
// the next.
double smallest_joint_offset(const WallSpec& s, const WallModel& m) {
  const auto joints = face_joints(s, m);
  double best = 1e300;
  for (int c = 0; c + 1 < m.n_courses; ++c) {
    if (!joints.count(c) || !joints.count(c + 1)) continue;
    for (double a : joints.at(c))
      for (double b : joints.at(c + 1)) best = std::min(best, std::abs(a - b));
  }
  return best;
}

double shortest_piece(const WallSpec& s, const WallModel& m) {
  double best = 1e300;
  for (const auto& b : m.blocks) {
    double u0 = 1e300, u1 = -1e300;
    for (const auto& x : local(s, m, b.shape)) u0 = std::min(u0, x.x()), u1 = std::max(u1, x.x());
    best = std::min(best, u1 - u0);
  }
  return best;
}

WallSpec small_wall() {
  WallSpec s;
  s.name = "w";
  s.length = 2.0;
  s.height = 1.6;
  s.unit_length = 0.4;
  s.unit_height = 0.2;
  s.unit_width = 0.2;
  return s;
}

TEST(Wall, RunningBondHasHalfUnitsAtTheEndsOfOddCourses) {
  const WallSpec s = small_wall();
  const WallModel m = expect_exact_tiling(s);
  EXPECT_EQ(m.n_courses, 8);
  EXPECT_DOUBLE_EQ(m.course_height, 0.2);
  // Even courses: 5 whole units; odd: a half, 4 whole, a half.
  EXPECT_EQ(m.blocks.size(), 4u * 5 + 4u * 6);
  const auto joints = face_joints(s, m);
  EXPECT_EQ(joints.at(0), (std::vector<double>{0.4, 0.8, 1.2, 1.6}));
  EXPECT_EQ(joints.at(1), (std::vector<double>{0.2, 0.6, 1.0, 1.4, 1.8}));
  EXPECT_NEAR(smallest_joint_offset(s, m), 0.2, 1e-12);  // half a unit
  EXPECT_EQ(m.blocks.front().name, "w_course00_leaf0_unit0");
}

TEST(Wall, EveryBondTilesTheWallWithItsOverlap) {
  struct Case {
    WallBond bond;
    double thickness, overlap;  // quarter or half unit between the joints of consecutive courses
  };
  for (const Case& k : {Case{WallBond::stretcher, 0.2, 0.2}, Case{WallBond::header, 0.4, 0.1},
                        Case{WallBond::english, 0.4, 0.1}, Case{WallBond::flemish, 0.4, 0.1}}) {
    WallSpec s = small_wall();
    s.length = 2.4;
    s.bond = k.bond;
    SCOPED_TRACE(static_cast<int>(k.bond));
    const WallModel m = expect_exact_tiling(s);
    EXPECT_NEAR(m.thickness, k.thickness, 1e-15);
    EXPECT_NEAR(smallest_joint_offset(s, m), k.overlap, 1e-9);
    EXPECT_GE(shortest_piece(s, m), 0.25 * s.unit_length - 1e-12);
  }
}

TEST(Wall, EnglishBondAlternatesStretcherAndHeaderCourses) {
  WallSpec s = small_wall();
  s.bond = WallBond::english;
  const WallModel m = build_wall(s);
  std::map<int, std::set<WallBlockKind>> kinds;
  for (const auto& b : m.blocks) kinds[b.course].insert(b.kind);
  for (int c = 0; c < m.n_courses; ++c)
    EXPECT_EQ(kinds[c], (std::set<WallBlockKind>{c % 2 ? WallBlockKind::header : WallBlockKind::unit})) << c;
  // A header course: a closer (half a header) at each end, whole headers between.
  const auto joints = face_joints(s, m);
  EXPECT_DOUBLE_EQ(joints.at(1).front(), 0.1);
  EXPECT_NEAR(joints.at(1)[1], 0.3, 1e-12);
}

TEST(Wall, FlemishBondCentresEachHeaderOnAStretcher) {
  WallSpec s = small_wall();
  s.length = 2.4;
  s.bond = WallBond::flemish;
  const WallModel m = build_wall(s);
  std::vector<double> header_centres[2], stretcher_centres[2];
  for (const auto& b : m.blocks) {
    if (b.course > 1 || b.leaf == 1) continue;
    const double u = (m.rotation.transpose() * (mass_properties(b.shape).centroid - s.origin)).x();
    (b.kind == WallBlockKind::header ? header_centres : stretcher_centres)[b.course].push_back(u);
  }
  // Course 1's headers that are whole sit over the middle of course 0's stretchers.
  int centred = 0;
  for (double h : header_centres[1])
    for (double st : stretcher_centres[0]) centred += std::abs(h - st) < 1e-12;
  EXPECT_GE(centred, 2);
}

TEST(Wall, LeavesWithThroughStonesCrossTheWholeWall) {
  WallSpec s = small_wall();
  s.leaves = 3;
  s.through_every = 3;
  const WallModel m = expect_exact_tiling(s);
  EXPECT_NEAR(m.thickness, 0.6, 1e-15);
  int through = 0;
  std::set<int> courses_with;
  for (const auto& b : m.blocks) {
    if (b.kind != WallBlockKind::through_stone) continue;
    ++through;
    courses_with.insert(b.course);
    EXPECT_EQ(b.leaf, -1);
    double v0 = 1e300, v1 = -1e300;
    for (const auto& x : local(s, m, b.shape)) v0 = std::min(v0, x.y()), v1 = std::max(v1, x.y());
    EXPECT_NEAR(v1 - v0, 0.6, 1e-12) << b.name;
  }
  // Even courses (5 units): units 0 and 3; odd (6 units, shifted by 1): units 2 and 5.
  EXPECT_EQ(through, 4 * 2 + 4 * 2);
  EXPECT_EQ(courses_with.size(), 8u);
}

TEST(Wall, LeftoverShorterThanAQuarterUnitJoinsItsNeighbour) {
  WallSpec s = small_wall();
  s.length = 2.05;  // even courses: 5 units and 0.05 left over; odd: 0.2 + 4 + 0.05
  const WallModel m = expect_exact_tiling(s);
  EXPECT_NEAR(shortest_piece(s, m), 0.2, 1e-12);  // the odd courses' first half unit
  const auto joints = face_joints(s, m);
  EXPECT_EQ(joints.at(0).size(), 4u);  // 0.4 .. 1.6, then one unit of 0.45
  EXPECT_EQ(joints.at(1).size(), 5u);  // 0.2 .. 1.8, then 0.25
}

TEST(Wall, TurnedAndMovedByOriginAndDirection) {
  WallSpec s = small_wall();
  s.origin = Vec3(1, 2, 0.5);
  s.direction = 90;
  const WallModel m = expect_exact_tiling(s);
  Eigen::AlignedBox3d box;
  for (const auto& b : m.blocks)
    for (const auto& v : b.shape.vertices) box.extend(v);
  EXPECT_NEAR(box.min().x(), 0.9, 1e-12);
  EXPECT_NEAR(box.max().x(), 1.1, 1e-12);
  EXPECT_NEAR(box.min().y(), 2.0, 1e-12);
  EXPECT_NEAR(box.max().y(), 4.0, 1e-12);
  EXPECT_NEAR(box.min().z(), 0.5, 1e-12);
  EXPECT_NEAR(box.max().z(), 2.1, 1e-12);
}

TEST(Wall, WindowWithALintel) {
  WallSpec s = small_wall();
  s.length = 2.4;
  s.leaves = 2;
  s.openings = {WallOpening{.position = 0.9, .sill = 0.4, .width = 0.6, .height = 0.7}};
  const WallModel m = expect_exact_tiling(s);
  const auto lintel = std::find_if(m.blocks.begin(), m.blocks.end(),
                                   [](const WallBlock& b) { return b.kind == WallBlockKind::lintel; });
  ASSERT_NE(lintel, m.blocks.end());
  EXPECT_EQ(lintel->name, "w_opening0_lintel");
  Eigen::AlignedBox3d box;
  for (const auto& x : local(s, m, lintel->shape)) box.extend(x);
  // Bearing half a unit onto each jamb; from the head (1.1) to the first bed
  // joint at least half a course above it (1.2).
  EXPECT_NEAR(box.min().x(), 0.7, 1e-12);
  EXPECT_NEAR(box.max().x(), 1.7, 1e-12);
  EXPECT_NEAR(box.min().z(), 1.1, 1e-12);
  EXPECT_NEAR(box.max().z(), 1.2, 1e-12);
  EXPECT_NEAR(box.max().y() - box.min().y(), 0.4, 1e-12);  // through both leaves
  EXPECT_EQ(lintel->course, 5);
  EXPECT_GE(shortest_piece(s, m), 0.25 * s.unit_length - 1e-12);
}

TEST(Wall, DoorAndWindowWithArchesOfVoussoirs) {
  WallSpec s = small_wall();
  s.length = 3.2;
  s.height = 2.4;
  s.openings = {WallOpening{.position = 0.4, .sill = 0.0, .width = 0.8, .height = 1.6, .head = OpeningHead::arch,
                            .voussoirs = 9},
                WallOpening{.position = 2.0, .sill = 0.6, .width = 0.6, .height = 0.9, .head = OpeningHead::arch,
                            .voussoirs = 5, .ring = 0.3}};
  const WallModel m = expect_exact_tiling(s);
  for (int k = 0; k < 2; ++k) {
    const WallOpening& o = s.openings[static_cast<std::size_t>(k)];
    const Vec3 centre = s.origin + m.rotation * Vec3(o.position + 0.5 * o.width, 0, o.sill + o.height - 0.5 * o.width);
    int n = 0;
    for (const auto& b : m.blocks) {
      if (b.kind != WallBlockKind::voussoir || b.opening != k) continue;
      ++n;
      // Radial joints: two faces whose planes hold the arch's centre line.
      int radial = 0;
      for (std::size_t f = 0; f < b.shape.faces.size(); ++f)
        radial += std::abs(b.shape.normals[f].dot(centre) - b.shape.offsets[f]) < 1e-9 &&
                  std::abs(b.shape.normals[f].dot(m.rotation.col(1))) < 1e-12;
      EXPECT_EQ(radial, 2) << b.name;
    }
    EXPECT_EQ(n, o.voussoirs);
  }
}

TEST(Wall, HeadAndSillBetweenBedJoints) {
  WallSpec s = small_wall();
  s.length = 2.4;
  // The sill half a course above the joint at 0.2; the head at
  // 0.3 + 0.75 = 1.05, a quarter course above the joint at 1.0.
  s.openings = {WallOpening{.position = 0.9, .sill = 0.3, .width = 0.6, .height = 0.75}};
  expect_exact_tiling(s);
}

TEST(Wall, GableCoursesCutByTheSlopesUnderAnApexStone) {
  for (WallBond bond : {WallBond::stretcher, WallBond::flemish}) {
    WallSpec s = small_wall();
    s.length = 3.0;
    s.height = 1.2;
    s.gable_height = 1.1;  // not a whole number of courses: the apex stone takes the rest
    s.bond = bond;
    s.openings = {WallOpening{.position = 1.2, .sill = 0.4, .width = 0.6, .height = 0.6}};
    const WallModel m = expect_exact_tiling(s);
    EXPECT_EQ(m.n_courses, 6);
    // Gable courses while the gable is 1.5 units (0.6 m) wide at their bed:
    // width 3 (1 - (z - 1.2)/1.1) >= 0.6 up to z = 2.08, so beds 1.2 .. 2.0.
    EXPECT_EQ(m.gable_courses, 5);
    const auto apex = std::find_if(m.blocks.begin(), m.blocks.end(), [](const WallBlock& b) { return b.kind == WallBlockKind::apex; });
    ASSERT_NE(apex, m.blocks.end());
    EXPECT_EQ(apex->name, "w_apex");
    EXPECT_EQ(apex->shape.vertices.size(), 6u);  // a triangle through the wall
    EXPECT_GE(shortest_piece(s, m), 0.25 * s.unit_length - 1e-12);
  }
}

void expect_spec_error(const WallSpec& s, const std::string& field, int opening, const std::string& fragment) {
  try {
    build_wall(s);
    ADD_FAILURE() << "accepted; expected an error on " << field;
  } catch (const WallSpecError& e) {
    EXPECT_EQ(e.field, field) << e.what();
    EXPECT_EQ(e.opening, opening) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Wall, BadSpecsNameTheirField) {
  WallSpec s = small_wall();
  s.unit_length = 2.5;
  expect_spec_error(s, "unit_length", -1, "longer than the wall");
  s = small_wall();
  s.bond = WallBond::english;
  s.unit_width = 0.15;
  expect_spec_error(s, "unit_width", -1, "cannot close");
  s = small_wall();
  s.bond = WallBond::flemish;
  s.leaves = 2;
  expect_spec_error(s, "leaves", -1, "only a stretcher bond");
  s = small_wall();
  s.through_every = 2;
  expect_spec_error(s, "through_every", -1, "at least 2 leaves");
  const WallOpening window{.position = 0.7, .sill = 0.4, .width = 0.6, .height = 0.6};
  s = small_wall();
  s.openings = {window};
  s.openings[0].width = 1.2;  // 0.7 + 1.2 + 0.2 > 2.0 - 0.1
  expect_spec_error(s, "width", 0, "quarter unit");
  s.openings[0] = window;
  s.openings[0].position = 0.2;
  expect_spec_error(s, "position", 0, "at least 0.3");
  s.openings = {window, window};
  s.openings[1].position = 1.1;
  expect_spec_error(s, "position", 1, "overlaps opening 0");
  s.openings = {window};
  s.openings[0].height = 1.2;  // head 1.6: the top of the wall
  expect_spec_error(s, "height", 0, "cuts the top course");
  s.openings[0] = window;
  s.openings[0].sill = 0.42;
  expect_spec_error(s, "sill", 0, "thinner than a quarter course");
  s.openings[0] = window;
  s.openings[0].height = 0.62;
  expect_spec_error(s, "height", 0, "thinner than a quarter course");
  s.openings[0] = window;
  s.openings[0].head = OpeningHead::arch;
  s.openings[0].voussoirs = 2;
  expect_spec_error(s, "voussoirs", 0, "[3, 64]");
  s.openings[0].voussoirs = 5;
  s.openings[0].height = 0.2;
  expect_spec_error(s, "height", 0, "semicircular arch");
  s.openings[0] = window;
  s.openings[0].bearing = 0.05;
  expect_spec_error(s, "bearing", 0, "quarter unit");
}

}  // namespace
}  // namespace polydem
