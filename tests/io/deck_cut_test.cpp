// [[cut]] in a deck: the coursed wall of docs/deck.md, a cut box against the
// same boxes listed by hand (bit for bit), what pieces inherit, and every
// bad [[cut]] refused with file, line and key.
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cut.hpp"

namespace polydem {
namespace {

const std::string kFile = "decks/cut.toml";

void expect_error(const std::string& text, int line, const std::string& key, const std::string& fragment) {
  try {
    parse_deck(text, kFile);
    ADD_FAILURE() << "accepted a bad deck; expected an error at line " << line << " key " << key;
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    const std::string where = kFile + ":" + std::to_string(line) + ": key '" + key + "': ";
    EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected: " << where;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "message: " << msg << "\nexpected fragment: " << fragment;
  }
}

const std::string kWall = R"([[block]]
name = "wall"
shape = "box"
size = [2.0, 0.25, 1.0]
center = [1.0, 0.125, 0.5]
group = "masonry"

[[cut]]
dip = 0
origin = [0, 0, 0.25]
spacing = 0.25
count = 3

[[cut]]
dip = 90
dip_direction = 90
origin = [0.5, 0, 0]
spacing = 0.5
count = 3
blocks = ["wall_cut1", "wall_cut3"]

[[cut]]
dip = 90
dip_direction = 90
origin = [0.25, 0, 0]
spacing = 0.5
count = 4
blocks = ["wall_cut2", "wall_cut4"]
)";

TEST(DeckCut, CoursedWallWithStaggeredHeadJoints) {
  const SceneSpec s = parse_deck(kWall, kFile);
  ASSERT_EQ(s.blocks.size(), 18u);  // courses of 4, 5, 4, 5 units
  EXPECT_EQ(s.blocks[0].name, "wall_cut1_cut1");
  EXPECT_EQ(s.blocks[4].name, "wall_cut2_cut1");
  EXPECT_EQ(s.blocks[17].name, "wall_cut4_cut5");
  double v = 0;
  for (const BlockSpec& b : s.blocks) {
    v += mass_properties(b.shape).volume;
    EXPECT_EQ(b.group, "masonry");
    EXPECT_EQ(b.motion, BlockMotion::free);
  }
  EXPECT_NEAR(v, 0.5, 1e-12 * 0.5);
  // Course 2's first unit is a half unit from x = 0 to 0.25, z 0.25 to 0.5.
  const Polyhedron& half = s.blocks[4].shape;
  EXPECT_EQ(mass_properties(half).volume, 0.25 * 0.25 * 0.25);
  double xmax = -1;
  for (const Vec3& p : half.vertices) xmax = std::max(xmax, p.x());
  EXPECT_EQ(xmax, 0.25);
}

TEST(DeckCut, CutBoxEqualsTheSameBoxesListedByHandBitForBit) {
  const SceneSpec cut = parse_deck(R"([[block]]
name = "b"
shape = "box"
size = [1, 0.5, 0.75]
center = [0.5, 0.25, 0.375]
[[cut]]
dip = 90
dip_direction = 90
origin = [0.25, 0, 0]
spacing = 0.5
count = 2
)",
                                   kFile);
  const SceneSpec listed = parse_deck(R"([[block]]
name = "b_cut1"
shape = "hull"
vertices = [[0, 0, 0], [0.25, 0, 0], [0, 0.5, 0], [0.25, 0.5, 0], [0, 0, 0.75], [0.25, 0, 0.75], [0, 0.5, 0.75], [0.25, 0.5, 0.75]]
[[block]]
name = "b_cut2"
shape = "hull"
vertices = [[0.25, 0, 0], [0.75, 0, 0], [0.25, 0.5, 0], [0.75, 0.5, 0], [0.25, 0, 0.75], [0.75, 0, 0.75], [0.25, 0.5, 0.75], [0.75, 0.5, 0.75]]
[[block]]
name = "b_cut3"
shape = "hull"
vertices = [[0.75, 0, 0], [1, 0, 0], [0.75, 0.5, 0], [1, 0.5, 0], [0.75, 0, 0.75], [1, 0, 0.75], [0.75, 0.5, 0.75], [1, 0.5, 0.75]]
)",
                                      kFile);
  ASSERT_EQ(cut.blocks.size(), 3u);
  ASSERT_EQ(listed.blocks.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(cut.blocks[i].name, listed.blocks[i].name);
    EXPECT_EQ(cut.blocks[i].shape.vertices, listed.blocks[i].shape.vertices);
    EXPECT_EQ(cut.blocks[i].shape.faces, listed.blocks[i].shape.faces);
    EXPECT_EQ(cut.blocks[i].shape.normals, listed.blocks[i].shape.normals);
    EXPECT_EQ(cut.blocks[i].shape.offsets, listed.blocks[i].shape.offsets);
  }
}

TEST(DeckCut, SelectionGroupsAndInheritedMotion) {
  const SceneSpec s = parse_deck(R"([[block]]
name = "base"
shape = "box"
size = [2, 2, 1]
center = [0, 0, -0.5]
motion = "fixed"
[[block]]
name = "rock"
shape = "box"
size = [1, 1, 1]
center = [0, 0, 0.5]
density = 2000
velocity = [1, 0, 0]
angular_velocity = [0, 0, 2]
group = "mass"
[[cut]]
dip = 45
dip_direction = 90
origin = [0, 0, 0.5]
group = "pieces"
)",
                                 kFile);
  ASSERT_EQ(s.blocks.size(), 3u);  // the fixed base is not cut by default
  EXPECT_EQ(s.blocks[0].name, "base");
  EXPECT_EQ(s.blocks[1].name, "rock_cut1");
  EXPECT_EQ(s.blocks[2].name, "rock_cut2");
  const Vec3 n = joint_set_normal(45, 90);
  for (int i : {1, 2}) {
    const BlockSpec& b = s.blocks[i];
    EXPECT_EQ(b.group, "pieces");
    EXPECT_EQ(b.density, 2000);
    const Vec3 c = mass_properties(b.shape).centroid;
    // Below the plane first; each piece's centroid moves with the rock.
    EXPECT_EQ(n.dot(c - Vec3(0, 0, 0.5)) < 0, i == 1);
    const Vec3 v = Vec3(1, 0, 0) + Vec3(0, 0, 2).cross(c - Vec3(0, 0, 0.5));
    EXPECT_NEAR((b.velocity - v).norm(), 0, 1e-15);
    EXPECT_EQ(b.angular_velocity, Vec3(0, 0, 2));
  }
  EXPECT_NEAR(mass_properties(s.blocks[1].shape).volume + mass_properties(s.blocks[2].shape).volume, 1.0, 1e-12);
  // By group, the fixed base too.
  const SceneSpec g = parse_deck(R"([[block]]
name = "base"
shape = "box"
size = [2, 2, 1]
center = [0, 0, -0.5]
motion = "fixed"
group = "ground"
[[cut]]
dip = 90
groups = ["ground"]
)",
                                 kFile);
  ASSERT_EQ(g.blocks.size(), 2u);
  EXPECT_EQ(g.blocks[0].motion, BlockMotion::fixed);
  EXPECT_EQ(g.blocks[1].group, "ground");
}

TEST(DeckCut, RockSlopeExampleFillsTheSlope) {
  const SceneSpec s = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/rock_slope_cut.toml");
  ASSERT_EQ(s.blocks.size(), 76u);
  double v = 0;
  for (std::size_t i = 1; i < s.blocks.size(); ++i) {
    EXPECT_EQ(s.blocks[i].group, "rock");
    EXPECT_EQ(s.blocks[i].name.rfind("rock_cut", 0), 0u);
    v += mass_properties(s.blocks[i].shape).volume;
  }
  // The slope: a trapezoid (6 m at the toe, 3.5 m at the crest, 4 m high) 3 m wide.
  EXPECT_NEAR(v, 57.0, 1e-12 * 57.0);
}

TEST(DeckCut, BadCutsNameFileLineAndKey) {
  const std::string box = "[[block]]\nname = \"b\"\nshape = \"box\"\nsize = [1, 1, 1]\n";  // lines 1-4
  expect_error(box + "[[cut]]\ndip = 95\n", 6, "cut[1].dip", "must be in [0, 90]");
  expect_error(box + "[[cut]]\ndip = -1\n", 6, "cut[1].dip", "must be in [0, 90]");
  expect_error(box + "[[cut]]\norigin = [0, 0, 0]\n", 5, "cut[1].dip", "missing");
  expect_error(box + "[[cut]]\ndip = 0\ndip_direction = 400\n", 7, "cut[1].dip_direction", "[0, 360]");
  expect_error(box + "[[cut]]\ndip = 0\nspacing = 0\n", 7, "cut[1].spacing", "must be > 0");
  expect_error(box + "[[cut]]\ndip = 0\nspacing = -0.1\ncount = 2\n", 7, "cut[1].spacing", "must be > 0");
  expect_error(box + "[[cut]]\ndip = 0\ncount = 3\n", 5, "cut[1].spacing", "need their spacing");
  expect_error(box + "[[cut]]\ndip = 0\norigin = [0, 0, -0.5]\nspacing = 1e-6\ncount = 100000\n", 8, "cut[1].spacing",
               "more than 100000");
  expect_error(box + "[[cut]]\ndip = 0\ncount = 0\n", 7, "cut[1].count", "[1, 100000]");
  expect_error(box + "[[cut]]\ndip = 0\nblocks = [\"c\"]\n", 7, "cut[1].blocks[1]", "unknown block \"c\"");
  expect_error(box + "[[cut]]\ndip = 0\ngroups = [\"arch\"]\n", 7, "cut[1].groups[1]", "unknown group \"arch\"");
  expect_error(box + "[[cut]]\ndip = 0\nblocks = []\n", 7, "cut[1].blocks", "no block selected");
  expect_error(box + "motion = \"fixed\"\n[[cut]]\ndip = 0\n", 6, "cut[1].blocks", "no block selected");
  expect_error(box + "[[cut]]\ndip = 0\norigin = [0, 0, 3]\n", 7, "cut[1].origin", "no plane of the joint set");
  expect_error(box + "[[cut]]\ndip = 0\nmin_thickness = 0.6\n", 5, "cut[1].origin", "no plane of the joint set");
  expect_error(box + "[[cut]]\ndip = 0\ngroup = \"\"\n", 7, "cut[1].group", "must not be empty");
  expect_error(box + "[[cut]]\ndip = 0\ndipp = 3\n", 7, "cut[1].dipp", "unknown key");
  // A plane grazing a corner of a tilted block without going through it.
  expect_error(box + "rotation = [0, 0, 45]\n[[cut]]\ndip = 90\ndip_direction = 90\norigin = [0.7071067811, 0, 0]\n"
                     "min_thickness = 0\n",
               9, "cut[1].origin", "needle-thin");
  // A piece's name taken by another block.
  expect_error(box + "[[block]]\nname = \"b_cut1\"\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [5, 0, 0]\n"
                     "[[cut]]\ndip = 0\nblocks = [\"b\"]\n",
               12, "cut[1].blocks", "would be named \"b_cut1\"");
}

}  // namespace
}  // namespace polydem
