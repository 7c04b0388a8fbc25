// The spire generator: volumes against closed forms computed here (not by
// the generator), block counts, convexity, no overlaps between neighbours,
// windows where asked and nowhere else.
#include "structures/spire.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace polydem {
namespace {

constexpr double kPi = std::numbers::pi;

// ------------------------------------------------- independent closed forms

// Horizontal apothems of the outer and inner surfaces, from the spec's
// definitions (outer: r_b + t0/2 at z = 0, reaching the apex; inner: outer
// minus the linearly varying thickness).
double outer_a(const SpireSpec& s, double z) { return (s.base_inradius + 0.5 * s.wall_thickness) * (1 - z / s.height); }
double thickness(const SpireSpec& s, double z) {
  return s.wall_thickness + (s.wall_thickness_top - s.wall_thickness) * z / (s.height - s.tip_height);
}
double inner_a(const SpireSpec& s, double z) { return outer_a(s, z) - thickness(s, z); }
// Area of a regular octagon of apothem a: 8 a² tan(π/8).
double octagon_area(double a) { return 8 * a * a * std::tan(kPi / 8); }

// The hollow shell from z = 0 to the tip: the integrand is quadratic in z,
// so Simpson's rule is exact.
double shell_volume(const SpireSpec& s) {
  const double top = s.height - s.tip_height;
  auto area = [&](double z) { return octagon_area(outer_a(s, z)) - octagon_area(inner_a(s, z)); };
  return top / 6 * (area(0) + 4 * area(top / 2) + area(top));
}

double tip_volume(const SpireSpec& s) {
  return octagon_area(outer_a(s, s.height - s.tip_height)) * s.tip_height / 3;
}

// The opening's profile in the face plane (s, z), counter-clockwise.
std::vector<Vec2> window_profile(const SpireSpec& s) {
  const double w = s.window_width;
  std::vector<Vec2> p = {{-w / 2, s.window_sill}, {w / 2, s.window_sill}};
  if (s.window_head_shape == WindowHead::flat) {
    p.push_back({w / 2, s.window_head});
    p.push_back({-w / 2, s.window_head});
    return p;
  }
  const double rise = w * std::sqrt(3.0) / 2;
  const double spring = s.window_head - rise;
  const int m = s.window_arch_segments;
  // Right arc (centre at the left springing point) from 0° to 60°, then the
  // left arc (centre at the right springing point) from 120° to 180°.
  for (int i = 0; i <= m; ++i) {
    const double a = (kPi / 3) * i / m;
    p.push_back({-w / 2 + w * std::cos(a), spring + w * std::sin(a)});
  }
  for (int i = 1; i <= m; ++i) {
    const double a = 2 * kPi / 3 + (kPi / 3) * i / m;
    p.push_back({w / 2 + w * std::cos(a), spring + w * std::sin(a)});
  }
  return p;
}

// Volume a window takes out of the wall: ∫∫ over the profile of the wall's
// horizontal thickness, which is linear in z, so = thickness(z̄) · area.
double window_volume(const SpireSpec& s) {
  const auto p = window_profile(s);
  double a2 = 0, zc = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    const double cr = u.x() * v.y() - v.x() * u.y();
    a2 += cr;
    zc += (u.y() + v.y()) * cr;
  }
  const double area = a2 / 2;
  const double zbar = zc / (3 * a2);
  return thickness(s, zbar) * area;
}

double base_volume(const SpireSpec& s) { return octagon_area(outer_a(s, 0)) * s.base_thickness; }

// ------------------------------------------------------------ helpers

SpireSpec coarse_spec() {
  SpireSpec s;
  s.stones_per_face = 1;
  s.course_height = 0.6;
  s.joint_pattern = SpireJointPattern::aligned;
  s.window_faces.clear();
  return s;
}

double volume(const Polyhedron& p) { return mass_properties(p).volume; }

bool inside(const Polyhedron& p, const Vec3& x, double margin = 1e-9) {
  for (size_t f = 0; f < p.faces.size(); ++f)
    if (p.normals[f].dot(x) - p.offsets[f] > -margin) return false;
  return true;
}

// Separating axis test for two convex polyhedra: true if their interiors
// overlap by more than tol along every candidate axis (face normals of both
// and cross products of edge directions).
bool interiors_overlap(const Polyhedron& a, const Polyhedron& b, double tol) {
  auto separated_along = [&](Vec3 axis) {
    const double len = axis.norm();
    if (len < 1e-9) return false;
    axis /= len;
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (const auto& v : a.vertices) amin = std::min(amin, axis.dot(v)), amax = std::max(amax, axis.dot(v));
    for (const auto& v : b.vertices) bmin = std::min(bmin, axis.dot(v)), bmax = std::max(bmax, axis.dot(v));
    return amax <= bmin + tol || bmax <= amin + tol;
  };
  for (const auto& n : a.normals)
    if (separated_along(n)) return false;
  for (const auto& n : b.normals)
    if (separated_along(n)) return false;
  for (const auto& ea : a.edges)
    for (const auto& eb : b.edges)
      if (separated_along((a.vertices[ea[1]] - a.vertices[ea[0]]).cross(b.vertices[eb[1]] - b.vertices[eb[0]])))
        return false;
  return true;
}

Eigen::AlignedBox3d box_of(const Polyhedron& p) {
  Eigen::AlignedBox3d b;
  for (const auto& v : p.vertices) b.extend(v);
  return b;
}

// Checks every pair of blocks whose boxes touch; returns the number of such
// neighbour pairs.
int expect_no_overlaps(const SpireModel& m) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const auto& b : m.blocks) boxes.push_back(box_of(b.shape));
  int pairs = 0;
  for (size_t i = 0; i < m.blocks.size(); ++i)
    for (size_t j = i + 1; j < m.blocks.size(); ++j) {
      Eigen::AlignedBox3d bi = boxes[i];
      bi.extend(bi.min() - Vec3::Constant(1e-9)).extend(bi.max() + Vec3::Constant(1e-9));
      if (!bi.intersects(boxes[j])) continue;
      ++pairs;
      EXPECT_FALSE(interiors_overlap(m.blocks[i].shape, m.blocks[j].shape, 1e-9))
          << m.blocks[i].name << " overlaps " << m.blocks[j].name;
    }
  return pairs;
}

double sum_volume(const SpireModel& m, std::initializer_list<BlockKind> kinds) {
  double v = 0;
  for (const auto& b : m.blocks)
    if (std::find(kinds.begin(), kinds.end(), b.kind) != kinds.end()) v += volume(b.shape);
  return v;
}

int count(const SpireModel& m, BlockKind kind) {
  return static_cast<int>(std::count_if(m.blocks.begin(), m.blocks.end(), [&](const auto& b) { return b.kind == kind; }));
}

// A point of face k at horizontal offset s along the face, height z, in the
// middle of the wall.
Vec3 wall_point(const SpireSpec& s, int k, double along, double z) {
  const double a = 0.5 * (outer_a(s, z) + inner_a(s, z));
  const double th = k * kPi / 4;
  return a * Vec3(std::cos(th), std::sin(th), 0) + along * Vec3(-std::sin(th), std::cos(th), 0) + Vec3(0, 0, z);
}

bool in_some_block(const SpireModel& m, const Vec3& x) {
  return std::any_of(m.blocks.begin(), m.blocks.end(), [&](const auto& b) { return inside(b.shape, x); });
}

// --------------------------------------------------------------- tests

TEST(Spire, DefaultVolumesAddUpToShellMinusWindows) {
  const SpireSpec s;
  const SpireModel m = build_spire(s);
  const double expected = shell_volume(s) - s.window_faces.size() * window_volume(s);
  const double got = sum_volume(m, {BlockKind::stone, BlockKind::window_piece});
  EXPECT_NEAR(got, expected, 1e-9 * expected);
  EXPECT_NEAR(sum_volume(m, {BlockKind::tip}), tip_volume(s), 1e-9 * tip_volume(s));
  EXPECT_NEAR(sum_volume(m, {BlockKind::base}), base_volume(s), 1e-9 * base_volume(s));
  EXPECT_EQ(m.n_courses, 20);
  EXPECT_NEAR(m.course_height, 0.3, 1e-12);
  EXPECT_NEAR(m.shell_top, 6.0, 1e-12);
}

TEST(Spire, FlatHeadsAndStaggeredJointsKeepTheVolume) {
  SpireSpec s;
  s.window_head_shape = WindowHead::flat;
  s.window_head = 1.35;  // between bed joints: the head cuts stones
  s.window_sill = 0.45;
  s.joint_pattern = SpireJointPattern::staggered;
  s.window_faces = {1, 6};
  const SpireModel m = build_spire(s);
  const double expected = shell_volume(s) - 2 * window_volume(s);
  EXPECT_NEAR(sum_volume(m, {BlockKind::stone, BlockKind::window_piece}), expected, 1e-9 * expected);
  EXPECT_GT(m.stones_cut_by_windows, 0);
  expect_no_overlaps(m);
}

TEST(Spire, EveryBlockIsAValidConvexPolyhedron) {
  const SpireModel m = build_spire(SpireSpec{});
  for (const auto& b : m.blocks) {
    EXPECT_NO_THROW(validate(b.shape)) << b.name;
    EXPECT_GT(volume(b.shape), 0) << b.name;
  }
}

TEST(Spire, NeighboursDoNotOverlap) {
  const SpireModel m = build_spire(SpireSpec{});
  const int pairs = expect_no_overlaps(m);
  EXPECT_GT(pairs, static_cast<int>(2 * m.blocks.size()));  // the check did see the neighbours
}

TEST(Spire, BlocksStayInsideTheShell) {
  const SpireSpec s;
  const SpireModel m = build_spire(s);
  for (const auto& b : m.blocks) {
    if (b.kind == BlockKind::base) continue;
    for (const auto& v : b.shape.vertices) {
      const double tol = 1e-9;
      EXPECT_GE(v.z(), -tol) << b.name;
      EXPECT_LE(v.z(), s.height + tol) << b.name;
      for (int k = 0; k < 8; ++k) {
        const Vec3 n(std::cos(k * kPi / 4), std::sin(k * kPi / 4), 0);
        EXPECT_LE(n.dot(v), outer_a(s, v.z()) + tol) << b.name << " outside face " << k;
      }
      if (b.face >= 0) {
        const Vec3 n(std::cos(b.face * kPi / 4), std::sin(b.face * kPi / 4), 0);
        EXPECT_GE(n.dot(v), inner_a(s, v.z()) - tol) << b.name << " inside the hollow";
      }
    }
  }
}

TEST(Spire, CoarseSpireCountsAndNoWindowSplitting) {
  const SpireSpec s = coarse_spec();
  const SpireModel m = build_spire(s);
  EXPECT_EQ(m.n_courses, 10);
  EXPECT_EQ(m.blocks.size(), 1u + 10 * 8 + 1);  // base, 8 stones per course, tip
  EXPECT_EQ(m.stones_cut_by_windows, 0);
  EXPECT_EQ(m.window_pieces, 0);
  EXPECT_EQ(count(m, BlockKind::window_piece), 0);
  EXPECT_EQ(count(m, BlockKind::base), 1);
  EXPECT_EQ(count(m, BlockKind::tip), 1);
  EXPECT_NEAR(sum_volume(m, {BlockKind::stone}), shell_volume(s), 1e-9 * shell_volume(s));
  expect_no_overlaps(m);
}

TEST(Spire, StaggeredCountAndNames) {
  SpireSpec s;
  s.window_faces.clear();
  s.joint_pattern = SpireJointPattern::staggered;
  const SpireModel m = build_spire(s);
  // Even courses 2 stones per face, odd courses 3 (half stones at the corners).
  EXPECT_EQ(m.blocks.size(), 1u + 8 * (10 * 2 + 10 * 3) + 1);
  EXPECT_EQ(m.stones_cut_by_windows, 0);
  std::map<std::string, int> names;
  for (const auto& b : m.blocks) ++names[b.name];
  EXPECT_EQ(names.size(), m.blocks.size()) << "names are unique";
  EXPECT_EQ(names.count("course03_face5_stone1"), 1u);
  EXPECT_EQ(names.count("course03_face5_stone2"), 1u);
  EXPECT_EQ(names.count("course04_face5_stone2"), 0u);
  // Joints of consecutive courses do not line up: the vertical joint of
  // course 0 at the middle of face 0 falls inside a stone of course 1.
  EXPECT_TRUE(in_some_block(m, wall_point(s, 0, 0.0, 0.45)));
  EXPECT_FALSE(in_some_block(m, wall_point(s, 0, 0.0, 0.15)));
}

// corner_stones = "merged": the shifted courses' corner halves join their
// neighbours, one stone per face from mitre to mitre with two stones per
// face. The volume is kept, the stagger too (course 0's middle joint falls
// inside a stone of course 1), and the lightest block of the default spire
// (windows, jambs continued) is a 14.5 kg window piece, no longer a 9.2 kg
// corner half of the top course.
TEST(Spire, MergedCornerStonesKeepTheStaggerWithoutSmallPieces) {
  SpireSpec s;
  s.window_faces.clear();
  s.joint_pattern = SpireJointPattern::staggered;
  s.corner_stones = SpireCornerStones::merged;
  const SpireModel m = build_spire(s);
  EXPECT_EQ(m.blocks.size(), 1u + 8 * (10 * 2 + 10 * 1) + 1);
  EXPECT_NEAR(sum_volume(m, {BlockKind::stone}), shell_volume(s), 1e-9 * shell_volume(s));
  EXPECT_TRUE(in_some_block(m, wall_point(s, 0, 0.0, 0.45)));
  EXPECT_FALSE(in_some_block(m, wall_point(s, 0, 0.0, 0.15)));
  expect_no_overlaps(m);

  auto lightest = [](const SpireModel& model) {
    double v = 1e300;
    for (const auto& b : model.blocks)
      if (b.kind == BlockKind::stone || b.kind == BlockKind::window_piece) v = std::min(v, volume(b.shape));
    return 2600.0 * v;  // kg
  };
  SpireSpec d;  // the paper's spire
  const double halves = lightest(build_spire(d));
  d.corner_stones = SpireCornerStones::merged;
  const SpireModel merged = build_spire(d);
  const double least = lightest(merged);
  EXPECT_NEAR(halves, 9.2, 0.1);
  EXPECT_GT(least, 1.5 * halves);
  const double expected = shell_volume(d) - 4 * window_volume(d);
  EXPECT_NEAR(sum_volume(merged, {BlockKind::stone, BlockKind::window_piece}), expected, 1e-9 * expected);
  expect_no_overlaps(merged);

  SpireSpec one;
  one.stones_per_face = 1;
  one.corner_stones = SpireCornerStones::merged;
  EXPECT_THROW(validate_spire(one), SpireSpecError);
}

TEST(Spire, WindowsWhereAsked) {
  const SpireSpec s;  // windows on faces 0, 2, 4, 6
  const SpireModel m = build_spire(s);
  EXPECT_GT(m.stones_cut_by_windows, 0);
  EXPECT_EQ(m.window_pieces, count(m, BlockKind::window_piece));
  const double zmid = 0.5 * (s.window_sill + s.window_head) - 0.2;
  for (int k = 0; k < 8; ++k) {
    const bool win = k % 2 == 0;
    // The middle of the opening is empty on window faces, masonry elsewhere
    // (0.01 m off the centre line, where even courses have a joint).
    EXPECT_EQ(in_some_block(m, wall_point(s, k, 0.01, zmid)), !win) << "face " << k;
    EXPECT_EQ(in_some_block(m, wall_point(s, k, 0.01, s.window_head - 0.03)), !win) << "face " << k;
    // Beside the jambs, under the sill and above the apex: masonry.
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.6 * s.window_width, zmid))) << "face " << k;
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.01, s.window_sill - 0.05))) << "face " << k;
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.01, s.window_head + 0.02))) << "face " << k;
    // A pointed head: just inside the jamb near the apex height is masonry.
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.45 * s.window_width, s.window_head - 0.05))) << "face " << k;
  }
  for (const auto& b : m.blocks) {
    if (b.kind == BlockKind::window_piece) {
      EXPECT_EQ(b.face % 2, 0) << b.name;
    }
  }
}

TEST(Spire, JointsContinueTheJambsAboveTheWindows) {
  const SpireSpec s;  // aligned_above_windows
  const SpireModel m = build_spire(s);
  // Course 6 (z 1.8..2.1, above the heads at 1.5): window faces have three
  // stones with joints on the jamb planes, the others two.
  const double w2 = 0.5 * s.window_width;
  for (int k = 0; k < 8; ++k) {
    int stones = 0;
    bool on_jamb = false;
    const double th = k * kPi / 4;
    const Vec3 t(-std::sin(th), std::cos(th), 0);
    for (const auto& b : m.blocks) {
      if (b.course != 6 || b.face != k) continue;
      ++stones;
      for (size_t f = 0; f < b.shape.faces.size(); ++f)
        on_jamb = on_jamb || (std::abs(std::abs(b.shape.normals[f].dot(t)) - 1) < 1e-12 &&
                              std::abs(std::abs(b.shape.offsets[f]) - w2) < 1e-9);
    }
    EXPECT_EQ(stones, k % 2 == 0 ? 3 : 2) << "face " << k;
    EXPECT_EQ(on_jamb, k % 2 == 0) << "face " << k;
  }
  // The joint above the window is straight through course 6 and 7 (no
  // stagger): a point on the jamb plane is in no block's interior.
  for (int c : {6, 7}) EXPECT_FALSE(in_some_block(m, wall_point(s, 0, w2, (c + 0.5) * 0.3)));
}

TEST(Spire, CourseHeightAdjustsToAWholeNumberOfCourses) {
  SpireSpec s = coarse_spec();
  s.course_height = 0.7;  // 6.0 / 0.7 = 8.57 -> 9 courses of 0.6667 m
  const SpireModel m = build_spire(s);
  EXPECT_EQ(m.n_courses, 9);
  EXPECT_NEAR(m.course_height, 6.0 / 9, 1e-12);
  s.base_thickness = 0;
  EXPECT_EQ(count(build_spire(s), BlockKind::base), 0);
}

// Faces fa of a and fb of b lie in one plane with opposite normals and
// overlap with positive area (separating axis test in the plane).
bool share_a_joint(const Polyhedron& a, size_t fa, const Polyhedron& b, size_t fb) {
  const Vec3& n = a.normals[fa];
  if ((n + b.normals[fb]).norm() > 1e-9 || std::abs(a.offsets[fa] + b.offsets[fb]) > 1e-9) return false;
  auto overlap_along = [&](const Vec3& axis) {
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (int v : a.faces[fa]) {
      amin = std::min(amin, axis.dot(a.vertices[v]));
      amax = std::max(amax, axis.dot(a.vertices[v]));
    }
    for (int v : b.faces[fb]) {
      bmin = std::min(bmin, axis.dot(b.vertices[v]));
      bmax = std::max(bmax, axis.dot(b.vertices[v]));
    }
    return std::min(amax, bmax) - std::max(amin, bmin) > 1e-6;
  };
  for (const auto* side : {&a.faces[fa], &b.faces[fb]}) {
    const Polyhedron& p = side == &a.faces[fa] ? a : b;
    for (size_t i = 0; i < side->size(); ++i) {
      const Vec3 e = p.vertices[(*side)[(i + 1) % side->size()]] - p.vertices[(*side)[i]];
      if (!overlap_along(e.cross(n).normalized())) return false;
    }
  }
  return true;
}

// The names of the blocks (not the base) that bear on nothing: no joint of
// theirs with another block faces downwards. Such a block can only hang on
// vertical joints, which carry no weight without normal force (no cohesion,
// no tension): it falls under gravity.
std::vector<std::string> blocks_without_bearing(const SpireModel& m) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const auto& b : m.blocks) boxes.push_back(box_of(b.shape));
  std::vector<std::string> out;
  for (size_t i = 0; i < m.blocks.size(); ++i) {
    if (m.blocks[i].kind == BlockKind::base) continue;
    const Polyhedron& a = m.blocks[i].shape;
    bool bears = false;
    for (size_t fa = 0; fa < a.faces.size() && !bears; ++fa) {
      if (a.normals[fa].z() > -1e-6) continue;  // vertical or facing up
      for (size_t j = 0; j < m.blocks.size() && !bears; ++j) {
        if (j == i) continue;
        Eigen::AlignedBox3d bi = boxes[i];
        bi.extend(bi.min() - Vec3::Constant(1e-9)).extend(bi.max() + Vec3::Constant(1e-9));
        if (!bi.intersects(boxes[j])) continue;
        for (size_t fb = 0; fb < m.blocks[j].shape.faces.size() && !bears; ++fb)
          bears = share_a_joint(a, fa, m.blocks[j].shape, fb);
      }
    }
    if (!bears) out.push_back(m.blocks[i].name);
  }
  return out;
}

TEST(Spire, EveryBlockBearsOnTheMasonryBelow) {
  // The default (pointed heads, joints continuing the jambs above the
  // windows), flat heads on a bed joint and between bed joints, rounder
  // arches, staggered joints and a coarse spire.
  std::vector<SpireSpec> specs(7);
  specs[1].window_head_shape = WindowHead::flat;
  specs[2].window_head_shape = WindowHead::flat;
  specs[2].window_head = 1.35;
  specs[2].window_sill = 0.45;
  specs[3].window_arch_segments = 3;
  specs[4].joint_pattern = SpireJointPattern::staggered;
  specs[4].window_head = 1.4;
  specs[5].joint_pattern = SpireJointPattern::aligned;
  specs[5].stones_per_face = 3;
  specs[6].stones_per_face = 1;
  specs[6].course_height = 0.6;
  for (size_t i = 0; i < specs.size(); ++i) {
    const SpireModel m = build_spire(specs[i]);
    const auto hanging = blocks_without_bearing(m);
    EXPECT_TRUE(hanging.empty()) << "spec " << i << ": " << hanging.size() << " blocks, e.g. " << hanging.front();
    if (i > 0) expect_no_overlaps(m);
  }
  // The check sees a hanging block: without its springer, the voussoir
  // touches only the crown and the mitre joints, which are vertical.
  SpireModel m = build_spire(SpireSpec{});
  std::erase_if(m.blocks, [](const auto& b) { return b.name == "course04_face0_stone0_piece0"; });
  EXPECT_EQ(blocks_without_bearing(m), std::vector<std::string>{"course04_face0_voussoir0"});
}

TEST(Spire, PointedHeadsAreTwoVoussoirsOnInclinedSpringers) {
  const SpireSpec s;
  const SpireModel m = build_spire(s);
  // 402 blocks: base, 400 stones and pieces, tip. Before the heads were
  // voussoirs, each window face had 7 blocks in courses 4 and 5 (a stone
  // each side of the head, the two wedges over the arch, three stones over
  // them); now it has 4: two springers and two voussoirs spanning both
  // courses (414 - 4 * 3 = 402).
  EXPECT_EQ(m.blocks.size(), 402u);
  EXPECT_EQ(m.window_pieces, 16);  // per window face: 2 springers, 2 voussoirs
  const double spring = s.window_head - s.window_width * std::sqrt(3.0) / 2;
  for (int k : s.window_faces) {
    const std::string f = "course04_face" + std::to_string(k);
    for (const auto& b : m.blocks) {
      if (b.name != f + "_voussoir0" && b.name != f + "_voussoir1") continue;
      double zmin = 1e9, zmax = -1e9;
      for (const auto& v : b.shape.vertices) zmin = std::min(zmin, v.z()), zmax = std::max(zmax, v.z());
      EXPECT_NEAR(zmin, spring, 1e-9) << b.name;  // from the springing
      EXPECT_NEAR(zmax, 1.8, 1e-9) << b.name;     // to the top of course 5: a crown joint 0.3 m tall
      // The springing joint: normal to the chord, 30° from horizontal.
      bool inclined = false;
      for (const auto& n : b.shape.normals) inclined = inclined || std::abs(n.z() + std::cos(kPi / 6)) < 1e-9;
      EXPECT_TRUE(inclined) << b.name;
    }
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.3, 1.25)));  // the springer beside the head
  }
  // The jambs' joints continue from course 6 (JointsContinueTheJambsAboveTheWindows).
  EXPECT_FALSE(in_some_block(m, wall_point(s, 0, 0.5 * s.window_width, 1.95)));
}

TEST(Spire, FlatHeadsHaveALintelBearingOnBothJambs) {
  SpireSpec s;
  s.window_head_shape = WindowHead::flat;
  const SpireModel m = build_spire(s);
  // Per window face in courses 4 and 5: a stone each side of the opening in
  // course 4 (the stone between the jambs is all opening), the lintel
  // (|s| <= w/2 + b) and a stone each side in course 5: 5 blocks where
  // pointed heads have 4 (two springers, two voussoirs), so 402 + 4 = 406.
  EXPECT_EQ(m.blocks.size(), 406u);
  EXPECT_EQ(m.window_pieces, 4);
  for (int k : s.window_faces) {
    // No vertical joint above the jambs in the lintel's course: the jamb
    // plane at mid-course 5 is inside the lintel.
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, 0.5 * s.window_width, 1.65))) << "face " << k;
    EXPECT_TRUE(in_some_block(m, wall_point(s, k, -0.5 * s.window_width, 1.65))) << "face " << k;
  }
  EXPECT_FALSE(in_some_block(m, wall_point(s, 0, 0.5 * s.window_width, 1.95)));  // course 6: the jambs again
}

void expect_spec_error(const SpireSpec& s, const std::string& field, const std::string& fragment) {
  try {
    validate_spire(s);
    ADD_FAILURE() << "accepted a bad spec; expected an error on " << field;
  } catch (const SpireSpecError& e) {
    EXPECT_EQ(e.field, field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Spire, InvalidSpecsNameTheField) {
  SpireSpec s;
  s.tip_height = 9.4;
  expect_spec_error(s, "tip_height", "less than height");
  s = SpireSpec{};
  s.wall_thickness_top = 0.6;
  expect_spec_error(s, "wall_thickness_top", "hollow");
  s = SpireSpec{};
  s.window_faces = {0, 8};
  expect_spec_error(s, "window_faces", "0..7");
  s = SpireSpec{};
  s.window_faces = {3, 3};
  expect_spec_error(s, "window_faces", "twice");
  s = SpireSpec{};
  s.window_width = 1.2;
  expect_spec_error(s, "window_width", "does not fit");
  s = SpireSpec{};
  s.window_head = 0.5;
  expect_spec_error(s, "window_head", "pointed head");
  s = SpireSpec{};
  s.window_head = 7;
  expect_spec_error(s, "window_head", "top of the shell");
  s = SpireSpec{};
  s.stones_per_face = 0;
  expect_spec_error(s, "stones_per_face", "[1, 64]");
  s = SpireSpec{};
  s.course_height = -0.3;
  expect_spec_error(s, "course_height", "> 0");
}

}  // namespace
}  // namespace polydem
