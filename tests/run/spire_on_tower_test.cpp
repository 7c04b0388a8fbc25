// A [spire] standing on a [[tower]] ([spire] origin at the tower's top,
// base_thickness = 0): at t = 0 no spire stone overlaps a tower stone and
// the spire's lowest stones touch the tower's top course; in a short run
// under gravity they stay there. Unsupported, they would fall
// g·t²/2 = 1.96 mm in 0.02 s; resting on stone joints of about 94 GPa/m
// under a few metres of masonry they settle by microns.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>

#include "structures/tower.hpp"

namespace polydem {
namespace {

const std::string kDeck = R"([simulation]
end_time = 0.02

[[block]]
name = "ground"
shape = "box"
size = [4, 4, 0.4]
center = [0, 0, -0.2]
motion = "fixed"

[[tower]]
name = "tower"
shape = "octagonal"
outer_apothem = 1.3
wall_thickness = 0.45
height = 0.6
course_height = 0.3
stones_per_face = 2

[spire]
origin = [0, 0, 0.6]
height = 4.0
tip_height = 1.5
course_height = 0.5
window_faces = []
base_thickness = 0
)";

bool separated_or_touching(const Polyhedron& a, const Polyhedron& b, double tol) {
  // Separating axis along a face normal of either (enough for a horizontal
  // bed between prisms: the test's pairs meet on planes).
  auto apart = [&](const Vec3& axis) {
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (const auto& v : a.vertices) a0 = std::min(a0, axis.dot(v)), a1 = std::max(a1, axis.dot(v));
    for (const auto& v : b.vertices) b0 = std::min(b0, axis.dot(v)), b1 = std::max(b1, axis.dot(v));
    return a1 <= b0 + tol || b1 <= a0 + tol;
  };
  for (const auto& n : a.normals)
    if (apart(n)) return true;
  for (const auto& n : b.normals)
    if (apart(n)) return true;
  return false;
}

TEST(SpireOnTower, FirstCourseRestsOnTheTowersTopCourse) {
  const SceneSpec s = parse_deck(kDeck, "spire_on_tower.toml");
  std::vector<std::size_t> spire, tower_top;
  for (std::size_t i = 0; i < s.blocks.size(); ++i) {
    if (s.blocks[i].name.rfind("course00_", 0) == 0) spire.push_back(i);
    if (s.blocks[i].name.rfind("tower_course01_", 0) == 0) tower_top.push_back(i);
  }
  ASSERT_EQ(spire.size(), 16u);  // 8 faces x 2 stones
  ASSERT_FALSE(tower_top.empty());
  // t = 0: every first-course stone's bed is at the tower's top and lies on
  // the top course (its bed's corners inside the tower's wall ring), and no
  // spire stone overlaps a tower stone.
  for (std::size_t i : spire) {
    double z0 = 1e300;
    for (const auto& v : s.blocks[i].shape.vertices) z0 = std::min(z0, v.z());
    EXPECT_NEAR(z0, 0.6, 1e-12) << s.blocks[i].name;  // the spire's own z = 0 is CGAL's, to round-off
    for (const auto& v : s.blocks[i].shape.vertices) {
      if (v.z() > 0.6 + 1e-9) continue;
      double outmost = -1e300;
      for (int k = 0; k < 8; ++k) {
        const double th = k * std::numbers::pi / 4;
        const double d = std::cos(th) * v.x() + std::sin(th) * v.y();
        EXPECT_LE(d, 1.3 + 1e-12) << s.blocks[i].name;
        outmost = std::max(outmost, d);
      }
      EXPECT_GE(outmost, 1.3 - 0.45 - 1e-12) << s.blocks[i].name;
    }
    for (std::size_t j : tower_top)
      EXPECT_TRUE(separated_or_touching(s.blocks[i].shape, s.blocks[j].shape, 1e-12))
          << s.blocks[i].name << " overlaps " << s.blocks[j].name;
  }
  // A short run: the spire stays on the tower.
  const RunReport r = run_scene(s);
  ASSERT_FALSE(r.unstable) << r.instability;
  double worst = 0;
  for (std::size_t i = 0; i < s.blocks.size(); ++i) {
    const Vec3 c0 = mass_properties(s.blocks[i].shape).centroid;
    worst = std::max(worst, (r.final_position[i] - c0).norm());
  }
  std::printf("largest displacement after %.3f s: %.3g m\n", r.end_time, worst);
  EXPECT_LT(worst, 1e-4) << "a stone moved " << worst << " m (free fall: 1.96e-3 m)";
  EXPECT_GT(r.detections, 0);
}

}  // namespace
}  // namespace polydem
