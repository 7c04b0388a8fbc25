// The wall generator: the blocks tile the wall exactly. Three checks that
// together say so: every block lies inside the wall's box and outside every
// opening, no two blocks overlap (separating axes), and their volumes sum to
// the solid's (the box minus the openings, computed here) to 1e-9 relative.
// Then the bonds' joint patterns, the sliver rule, the heads over openings,
// and each validation rule.
#include "structures/wall.hpp"

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
  std::map<int, std::set<BlockKind>> kinds;
  for (const auto& b : m.blocks) kinds[b.course].insert(b.kind);
  for (int c = 0; c < m.n_courses; ++c)
    EXPECT_EQ(kinds[c], (std::set<BlockKind>{c % 2 ? BlockKind::header : BlockKind::unit})) << c;
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
    (b.kind == BlockKind::header ? header_centres : stretcher_centres)[b.course].push_back(u);
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
    if (b.kind != BlockKind::through_stone) continue;
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
                                   [](const GeneratedBlock& b) { return b.kind == BlockKind::lintel; });
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
      if (b.kind != BlockKind::voussoir || b.opening != k) continue;
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
    const auto apex = std::find_if(m.blocks.begin(), m.blocks.end(), [](const GeneratedBlock& b) { return b.kind == BlockKind::apex; });
    ASSERT_NE(apex, m.blocks.end());
    EXPECT_EQ(apex->name, "w_apex");
    EXPECT_EQ(apex->shape.vertices.size(), 6u);  // a triangle through the wall
    EXPECT_GE(shortest_piece(s, m), 0.25 * s.unit_length - 1e-12);
  }
}

// Two walls at a corner, placed and interlocked as the deck reader does
// (io/wall_section.cpp, place_at_corner): b starts at a's end (or start),
// turning left or right, on a's outer face.
struct CornerPair {
  WallSpec a, b;
};

CornerPair corner_pair(WallBond bond_a, WallBond bond_b, bool at_end, bool left, int courses) {
  CornerPair p;
  p.a = small_wall();
  p.a.name = "a";
  p.a.bond = bond_a;
  p.a.length = 2.4;
  p.a.height = 0.2 * courses;
  p.a.origin = Vec3(0.3, -0.2, 0.0);
  p.a.direction = 30;
  p.b = p.a;
  p.b.name = "b";
  p.b.bond = bond_b;
  p.b.length = 2.0;
  const double T = wall_thickness(p.a);
  const double th = p.a.direction * kPi / 180.0;
  const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0);
  p.b.origin = p.a.origin + (at_end ? p.a.length - 0.5 * T : 0.5 * T) * eu + (left ? -0.5 : 0.5) * T * ev;
  p.b.direction = p.a.direction + (left ? 90.0 : -90.0);
  p.b.course_shift = quoin_parity(p.b) == quoin_parity(p.a) ? 1 : 0;
  p.a.corners.push_back({at_end, T, 1 - quoin_parity(p.a), courses});
  p.b.corners.push_back({false, T, 1 - quoin_parity(p.b), courses});
  return p;
}

// Both walls of a corner tile the L-shaped solid exactly: every block
// valid, no two overlapping (separating axes, 1e-9), volumes summing to
// (a's plan + b's plan less the shared corner square) x height, less the
// openings, to 1e-9 relative.
std::vector<GeneratedBlock> expect_exact_walls(const std::vector<WallSpec>& walls, int corners) {
  std::vector<WallModel> models;
  for (const auto& s : walls) models.push_back(build_wall(s));
  const double T = models.front().thickness;
  double expected = -corners * T * T * walls.front().height, solid = 0;
  std::vector<GeneratedBlock> all;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    EXPECT_DOUBLE_EQ(models[i].thickness, T);
    expected += box_minus_openings(walls[i], T);
    solid += models[i].solid_volume;
    all.insert(all.end(), models[i].blocks.begin(), models[i].blocks.end());
  }
  EXPECT_NEAR(solid, expected, 1e-12 * expected);
  double sum = 0;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const auto& b : all) {
    EXPECT_NO_THROW(validate(b.shape)) << b.name;
    sum += volume(b.shape);
    Eigen::AlignedBox3d box;
    for (const auto& v : b.shape.vertices) box.extend(v);
    boxes.push_back(box.extend(box.min() - Vec3::Constant(1e-9)).extend(box.max() + Vec3::Constant(1e-9)));
  }
  EXPECT_NEAR(sum, expected, 1e-9 * expected);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (boxes[i].intersects(boxes[j])) {
        EXPECT_FALSE(interiors_overlap(all[i].shape, all[j].shape, 1e-9)) << all[i].name << " overlaps " << all[j].name;
      }
  for (std::size_t i = 0; i < walls.size(); ++i) {
    for (const auto& o : walls[i].openings) {
      const Polyhedron hole = opening_prism(walls[i], models[i], o);
      for (const auto& b : all) EXPECT_FALSE(interiors_overlap(b.shape, hole, 1e-9)) << b.name << " in an opening";
    }
  }
  return all;
}

std::vector<GeneratedBlock> expect_exact_corner(const CornerPair& p) { return expect_exact_walls({p.a, p.b}, 1); }

// The vertical joints, course by course, on one face of wall s (side -1:
// v = -T/2, +1: v = +T/2) from the blocks of both walls, as distances from
// the corner along the face: from the corner's outer end on the outer face,
// from the inner corner on the inner face (where the visible face starts).
// Joints at the face's ends are left out.
std::map<int, std::vector<double>> corner_face_joints(const WallSpec& s, const WallSpec& other,
                                                      const std::vector<GeneratedBlock>& all, int side, double ch,
                                                      int corner = 0) {
  const double T = wall_thickness(s);
  const double th = s.direction * kPi / 180.0;
  const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0);
  const Vec3 n = side * ev;
  const double d = n.dot(s.origin) + 0.5 * T;
  const WallCorner& k = s.corners.at(static_cast<std::size_t>(corner));
  // Is this face the inner one (the other wall on its side)?
  const Vec3 other_mid = other.origin + 0.5 * other.length * Vec3(std::cos(other.direction * kPi / 180.0),
                                                                   std::sin(other.direction * kPi / 180.0), 0);
  const bool inner = n.dot(other_mid) > d;
  const double u_corner = k.at_end ? (inner ? s.length - T : s.length) : (inner ? T : 0.0);
  const double u_free = k.at_end ? 0.0 : s.length;
  const double lo = std::min(u_corner, u_free), hi = std::max(u_corner, u_free);
  std::map<int, std::set<double>> sets;
  for (const auto& b : all)
    for (std::size_t f = 0; f < b.shape.faces.size(); ++f) {
      if (b.shape.normals[f].dot(n) < 1 - 1e-12 || std::abs(b.shape.offsets[f] - d) > 1e-9) continue;
      double u0 = 1e300, u1 = -1e300, z0 = 1e300;
      for (int vi : b.shape.faces[f]) {
        const Vec3& x = b.shape.vertices[static_cast<std::size_t>(vi)];
        const double u = eu.dot(x - s.origin);
        u0 = std::min(u0, u), u1 = std::max(u1, u), z0 = std::min(z0, x.z() - s.origin.z());
      }
      const int c = static_cast<int>(std::lround(z0 / ch));
      for (double u : {u0, u1})
        if (u > lo + 1e-9 && u < hi - 1e-9) sets[c].insert(std::round(std::abs(u - u_corner) * 1e9) / 1e9);
    }
  std::map<int, std::vector<double>> out;
  for (auto& [c, set] : sets) out[c] = std::vector<double>(set.begin(), set.end());
  return out;
}

// The smallest distance between a joint of one course within `near` of the
// corner and a joint of the course below.
double smallest_lap_near_corner(const std::map<int, std::vector<double>>& joints, int courses, double near) {
  double best = 1e300;
  for (int c = 1; c < courses; ++c) {
    if (!joints.count(c) || !joints.count(c - 1)) continue;
    for (double a : joints.at(c))
      for (double b : joints.at(c - 1))
        if (a <= near || b <= near) best = std::min(best, std::abs(a - b));
  }
  return best;
}

TEST(Wall, EnglishFlemishAndHeaderBondCornersTileAndKeepTheQuarterLapAtTheQuoin) {
  struct Case {
    WallBond a, b;
  };
  for (const Case& k : {Case{WallBond::english, WallBond::english}, Case{WallBond::flemish, WallBond::flemish},
                        Case{WallBond::english, WallBond::flemish}, Case{WallBond::flemish, WallBond::english},
                        Case{WallBond::header, WallBond::header}})
    for (bool at_end : {true, false})
      for (bool left : {true, false}) {
        SCOPED_TRACE(std::string(to_string(BlockKind::unit)) + " bonds " + std::to_string(static_cast<int>(k.a)) +
                     "/" + std::to_string(static_cast<int>(k.b)) + (at_end ? " at end" : " at start") +
                     (left ? " left" : " right"));
        const CornerPair p = corner_pair(k.a, k.b, at_end, left, 6);
        const std::vector<GeneratedBlock> all = expect_exact_corner(p);
        // Every piece at least a quarter unit along its wall; the closers
        // exactly a quarter unit.
        int closers = 0;
        for (const WallSpec* s : {&p.a, &p.b}) {
          const WallModel m = build_wall(*s);
          EXPECT_GE(shortest_piece(*s, m), 0.25 * s->unit_length - 1e-12);
          for (const auto& b : m.blocks) {
            if (b.kind != BlockKind::closer) continue;
            ++closers;
            double u0 = 1e300, u1 = -1e300;
            for (const auto& x : local(*s, m, b.shape)) u0 = std::min(u0, x.x()), u1 = std::max(u1, x.x());
            EXPECT_NEAR(u1 - u0, 0.1, 1e-12) << b.name;
          }
        }
        // One closer per course at the quoin: the wall owning the corner square lays it.
        EXPECT_EQ(closers, 6);
        // The lap on all four faces near the corner: no joint within a
        // quarter unit (0.1 m) of a joint of the course below.
        for (const WallSpec* s : {&p.a, &p.b})
          for (int side : {-1, 1}) {
            const auto joints = corner_face_joints(*s, s == &p.a ? p.b : p.a, all, side, 0.2);
            EXPECT_EQ(joints.size(), 6u);
            EXPECT_NEAR(smallest_lap_near_corner(joints, 6, 1.2), 0.1, 1e-9) << s->name << " side " << side;
          }
      }
}

// What the closers are for: the same English corner with each queen closer
// left out (the quoin header followed at once by headers: every joint of the
// owning course beyond the quoin header a quarter unit nearer the corner)
// has straight joints over the course below at the quoin.
TEST(Wall, WithoutTheQueenClosersAnEnglishCornerHasStraightJoints) {
  const CornerPair p = corner_pair(WallBond::english, WallBond::english, true, true, 6);
  const std::vector<GeneratedBlock> all = expect_exact_corner(p);
  const auto joints = corner_face_joints(p.a, p.b, all, -1, 0.2);  // a's outer face
  EXPECT_NEAR(smallest_lap_near_corner(joints, 6, 1.2), 0.1, 1e-9);
  auto without = joints;
  for (auto& [c, js] : without) {
    if (c % 2 != quoin_parity(p.a)) continue;
    // Distances from the corner: the quoin header's joint at 0.2 stays, every
    // joint beyond it comes a quarter unit (0.1) nearer (the closer's own
    // joint at 0.3 falls onto 0.2).
    std::set<double> shifted;
    for (double j : js) shifted.insert(j > 0.2 + 1e-9 ? std::round((j - 0.1) * 1e9) / 1e9 : j);
    js.assign(shifted.begin(), shifted.end());
  }
  EXPECT_LT(smallest_lap_near_corner(without, 6, 1.2), 1e-9);
}

TEST(Wall, EnglishCornerWithAnOpeningAndCornersAtBothEnds) {
  CornerPair p = corner_pair(WallBond::english, WallBond::english, true, true, 8);
  p.b.openings = {WallOpening{.position = 0.9, .sill = 0.4, .width = 0.4, .height = 0.8}};
  expect_exact_corner(p);
  // A third wall at b's end: b has corners at both ends, laid from each and
  // meeting in the middle (b's length 2.05 m: not a whole number of units).
  for (double length : {2.0, 2.05, 2.15}) {
    CornerPair q = corner_pair(WallBond::flemish, WallBond::flemish, true, true, 6);
    q.b.length = length;
    CornerPair r;
    r.a = q.b;
    r.b = q.b;
    r.b.name = "c";
    r.b.corners.clear();
    r.b.length = 1.6;
    const double T = wall_thickness(r.a);
    const double th = r.a.direction * kPi / 180.0;
    const Vec3 eu(std::cos(th), std::sin(th), 0), ev(-std::sin(th), std::cos(th), 0);
    r.b.origin = r.a.origin + (r.a.length - 0.5 * T) * eu - 0.5 * T * ev;
    r.b.direction = r.a.direction + 90;
    r.b.course_shift = 0;
    r.b.course_shift = quoin_parity(r.b) == quoin_parity(r.a) ? 1 : 0;
    r.a.corners.push_back({true, T, 1 - quoin_parity(r.a), 6});
    r.b.corners.push_back({false, T, 1 - quoin_parity(r.b), 6});
    q.b = r.a;
    SCOPED_TRACE(length);
    const std::vector<GeneratedBlock> all = expect_exact_walls({q.a, r.a, r.b}, 2);
    for (const CornerPair* pair : {&q, &r})
      for (const WallSpec* s : {&pair->a, &pair->b}) {
        const WallSpec& other = s == &pair->a ? pair->b : pair->a;
        // b's corners: [0] at its start (with a), [1] at its end (with c).
        const int corner = s->corners.size() == 1 ? 0 : (pair == &q ? 0 : 1);
        for (int side : {-1, 1})
          EXPECT_NEAR(smallest_lap_near_corner(corner_face_joints(*s, other, all, side, 0.2, corner), 6, 0.5), 0.1,
                      1e-9)
              << s->name << " side " << side << " corner " << corner;
      }
    const WallModel mb = build_wall(r.a);
    EXPECT_GE(shortest_piece(r.a, mb), 0.25 * r.a.unit_length - 1e-12);
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
  // Corners with closers: header bond needs two headers to a unit length;
  // the other wall as thick; room beyond the corner.
  CornerPair p = corner_pair(WallBond::header, WallBond::header, true, true, 4);
  p.a.unit_width = 0.15;
  expect_spec_error(p.a, "unit_width", -1, "cannot close a corner");
  p = corner_pair(WallBond::english, WallBond::english, true, true, 4);
  p.a.corners.front().depth = 0.2;
  expect_spec_error(p.a, "unit_length", -1, "one unit length");
  p = corner_pair(WallBond::english, WallBond::english, true, true, 4);
  p.b.length = 1.1;
  expect_spec_error(p.b, "length", -1, "two unit lengths");
}

}  // namespace
}  // namespace polydem
