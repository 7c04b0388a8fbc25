// The [spire] deck section: generated blocks land in SceneSpec.blocks, the
// joint stiffness comes from the materials unless [joint] gives it, and every
// bad key is reported with file, line and key.
#include "io/deck.hpp"
#include "structures/generator_specs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace polydem {
namespace {

const std::string kFile = "decks/spire.toml";

void expect_error(const std::string& text, int line, const std::string& key, const std::string& fragment,
                  const std::vector<std::string>& overrides = {}) {
  try {
    parse_deck(text, kFile, overrides);
    ADD_FAILURE() << "accepted a bad deck; expected an error at line " << line << " key " << key;
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    const std::string where = line > 0 ? kFile + ":" + std::to_string(line) + ": key '" + key + "': "
                                       : kFile + ": --set key '" + key + "': ";
    EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected: " << where;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "message: " << msg << "\nexpected fragment: " << fragment;
  }
}

int count_if_name(const SceneSpec& s, const std::string& fragment) {
  return static_cast<int>(std::count_if(s.blocks.begin(), s.blocks.end(), [&](const BlockSpec& b) {
    return b.name.find(fragment) != std::string::npos;
  }));
}

TEST(DeckSpire, EmptySectionIsThePapersSpire) {
  const SceneSpec s = parse_deck("[simulation]\nend_time = 1\n\n[spire]\n", kFile);
  ASSERT_TRUE(spire_of(s.generators));
  const SpireModel m = build_spire(SpireSpec{});
  ASSERT_EQ(s.blocks.size(), m.blocks.size());
  for (std::size_t i = 0; i < s.blocks.size(); ++i) {
    const BlockSpec& b = s.blocks[i];
    EXPECT_EQ(b.name, m.blocks[i].name);
    EXPECT_EQ(b.course, m.blocks[i].course);
    EXPECT_EQ(b.deck_line, 4) << b.name;  // the [spire] header
    EXPECT_DOUBLE_EQ(b.density, 2600.0);
    EXPECT_EQ(b.motion, b.name == "base" ? BlockMotion::fixed : BlockMotion::free) << b.name;
  }
  EXPECT_EQ(s.blocks.front().name, "base");
  EXPECT_EQ(s.blocks.back().name, "tip");
  EXPECT_EQ(s.blocks.back().course, 20);
  EXPECT_EQ(count_if_name(s, "course04_face5_stone"), 2);  // even course, face without a window
  EXPECT_EQ(count_if_name(s, "course03_face5_stone"), 3);  // odd course: staggered
  EXPECT_GT(count_if_name(s, "_piece"), 0);
  // 1/kn = (0.3 - 0.01)/30e9 + 0.01/10e9 -> 93.75 GPa/m; ks = 0.4 kn.
  EXPECT_NEAR(s.joint.normal_stiffness, 93.75e9, 1e3);
  EXPECT_NEAR(s.joint.shear_stiffness, 0.4 * 93.75e9, 1e3);
  EXPECT_DOUBLE_EQ(s.joint.friction_angle, 30.0);
  EXPECT_DOUBLE_EQ(s.joint.damping, 2.1e-5);
}

TEST(DeckSpire, KeysReachTheSpec) {
  const SceneSpec s = parse_deck(R"([spire]
height = 9.0
base_inradius = 1.0
wall_thickness = 0.3
wall_thickness_top = 0.2
course_height = 0.6
tip_height = 3.0
stones_per_face = 1
joint_pattern = "aligned"
window_faces = []
window_sill = 0.6
window_width = 0.25
window_head = 1.8
window_head_shape = "flat"
window_arch_segments = 3
base_thickness = 0.5
base_motion = "kinematic"
density = 2400
stone_youngs_modulus = 20e9
mortar_youngs_modulus = 5e9
mortar_thickness = 0.02
shear_stiffness_ratio = 0.5
)",
                                 kFile);
  ASSERT_TRUE(spire_of(s.generators));
  const SpireSpec& p = *spire_of(s.generators);
  EXPECT_DOUBLE_EQ(p.height, 9.0);
  EXPECT_DOUBLE_EQ(p.base_inradius, 1.0);
  EXPECT_DOUBLE_EQ(p.wall_thickness, 0.3);
  EXPECT_DOUBLE_EQ(p.wall_thickness_top, 0.2);
  EXPECT_DOUBLE_EQ(p.course_height, 0.6);
  EXPECT_DOUBLE_EQ(p.tip_height, 3.0);
  EXPECT_EQ(p.stones_per_face, 1);
  EXPECT_EQ(p.joint_pattern, SpireJointPattern::aligned);
  EXPECT_TRUE(p.window_faces.empty());
  EXPECT_DOUBLE_EQ(p.window_sill, 0.6);
  EXPECT_DOUBLE_EQ(p.window_width, 0.25);
  EXPECT_DOUBLE_EQ(p.window_head, 1.8);
  EXPECT_EQ(p.window_head_shape, WindowHead::flat);
  EXPECT_EQ(p.window_arch_segments, 3);
  EXPECT_DOUBLE_EQ(p.base_thickness, 0.5);
  // Coarse spire: base, 10 courses of 8 stones, tip; no window pieces.
  EXPECT_EQ(s.blocks.size(), 1u + 10 * 8 + 1);
  EXPECT_EQ(count_if_name(s, "_piece"), 0);
  EXPECT_EQ(s.blocks.front().motion, BlockMotion::kinematic);
  EXPECT_DOUBLE_EQ(s.blocks[5].density, 2400.0);
  const double kn = 1.0 / (0.58 / 20e9 + 0.02 / 5e9);
  EXPECT_NEAR(s.joint.normal_stiffness, kn, 1e-6 * kn);
  EXPECT_NEAR(s.joint.shear_stiffness, 0.5 * kn, 1e-6 * kn);
}

TEST(DeckSpire, JointKeysWinOverTheMaterials) {
  SceneSpec s = parse_deck("[spire]\n[joint]\nnormal_stiffness = 98e9\n", kFile);
  EXPECT_DOUBLE_EQ(s.joint.normal_stiffness, 98e9);
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, 0.4 * 98e9);
  s = parse_deck("[spire]\nshear_stiffness_ratio = 0.25\n[joint]\nnormal_stiffness = 98e9\n", kFile);
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, 0.25 * 98e9);
  s = parse_deck("[spire]\n[joint]\nshear_stiffness = 1e9\n", kFile);
  EXPECT_NEAR(s.joint.normal_stiffness, 93.75e9, 1e3);
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, 1e9);
  // Without [spire] nothing changes: Table 1's 98 GPa/m.
  s = parse_deck("[[block]]\nshape = \"box\"\nsize = [1, 1, 1]\n", kFile);
  EXPECT_DOUBLE_EQ(s.joint.normal_stiffness, 98e9);
  EXPECT_FALSE(spire_of(s.generators));
}

TEST(DeckSpire, ListedBlocksComeFirstAndNamesStayUnique) {
  const SceneSpec s = parse_deck(R"([[block]]
name = "ground"
shape = "box"
size = [5, 5, 0.2]
center = [0, 0, -0.4]
motion = "fixed"

[spire]
window_faces = []
)",
                                 kFile);
  EXPECT_EQ(s.blocks.front().name, "ground");
  EXPECT_EQ(s.blocks[1].name, "base");
  std::set<std::string> names;
  for (const auto& b : s.blocks) names.insert(b.name);
  EXPECT_EQ(names.size(), s.blocks.size());
  // Groups: the base, the stones by course, the tip; a listed block has none.
  EXPECT_EQ(s.blocks[0].group, "");
  EXPECT_EQ(s.blocks[1].group, "base");
  EXPECT_EQ(s.blocks.back().group, "tip");
  for (const auto& b : s.blocks)
    if (b.course >= 0 && b.name != "tip") {
      EXPECT_EQ(b.group, (b.course < 10 ? "course0" : "course") + std::to_string(b.course)) << b.name;
    }
  expect_error("[[block]]\nname = \"tip\"\nshape = \"box\"\nsize = [1, 1, 1]\n\n[spire]\n", 6, "spire",
               "has the name of the [[block]] at line 1");
}

TEST(DeckSpire, OverridesApply) {
  const SceneSpec s = parse_deck("[spire]\n", kFile, {"spire.window_faces=[]", "spire.stones_per_face=1",
                                                       "spire.joint_pattern=aligned"});
  EXPECT_EQ(count_if_name(s, "_piece"), 0);
  EXPECT_EQ(s.blocks.size(), 1u + 20 * 8 + 1);
  expect_error("[spire]\n", 0, "spire.stones_per_face", "[1, 64]", {"spire.stones_per_face=0"});
}

// A wide base is a platform for fallen stones: the base block grows to the
// given apothem, the spire's blocks stay the same.
TEST(DeckSpire, BaseApothemWidensOnlyTheBase) {
  const SceneSpec narrow = parse_deck("[spire]\n", kFile);
  const SceneSpec wide = parse_deck("[spire]\nbase_apothem = 12\n", kFile);
  ASSERT_EQ(narrow.blocks.size(), wide.blocks.size());
  auto extent_x = [](const BlockSpec& b) {
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : b.shape.vertices) {
      lo = std::min(lo, v.x());
      hi = std::max(hi, v.x());
    }
    return hi - lo;
  };
  for (std::size_t i = 0; i < wide.blocks.size(); ++i) {
    if (wide.blocks[i].name == "base") {
      EXPECT_NEAR(extent_x(wide.blocks[i]), 24.0, 1e-9);  // face to face
      EXPECT_NEAR(extent_x(narrow.blocks[i]), 2 * (1.064 + 0.125), 1e-9);
    } else {
      EXPECT_EQ(wide.blocks[i].shape.vertices, narrow.blocks[i].shape.vertices) << wide.blocks[i].name;
    }
  }
}

// The same deck read twice in one process gives the same blocks, vertex for
// vertex and face for face (CGAL's hull order depends on heap addresses; a
// study or a Python script builds scenes again and again).
TEST(DeckSpire, TheSameDeckReadTwiceGivesTheSameBlocks) {
  const SceneSpec a = parse_deck("[spire]\n", kFile);
  const SceneSpec b = parse_deck("[spire]\n", kFile);
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].shape.vertices, b.blocks[i].shape.vertices) << a.blocks[i].name;
    EXPECT_EQ(a.blocks[i].shape.faces, b.blocks[i].shape.faces) << a.blocks[i].name;
  }
}

TEST(DeckSpire, BadKeysNameFileLineAndKey) {
  expect_error("[spire]\nheight = 9.4\nradius = 1\n", 3, "spire.radius", "unknown key");
  expect_error("[spire]\nheight = -1\n", 2, "spire.height", "must be > 0");
  expect_error("[spire]\nheight = \"tall\"\n", 2, "spire.height", "must be a number");
  expect_error("[spire]\ntip_height = 9.4\n", 2, "spire.tip_height", "less than height");
  expect_error("[spire]\nwall_thickness_top = 0.6\n", 2, "spire.wall_thickness_top", "hollow");
  expect_error("[spire]\nstones_per_face = 2.5\n", 2, "spire.stones_per_face", "must be an integer");
  expect_error("[spire]\njoint_pattern = \"random\"\n", 2, "spire.joint_pattern", "\"staggered\"");
  expect_error("[spire]\ncorner_stones = \"whole\"\n", 2, "spire.corner_stones", "\"merged\"");
  expect_error("[spire]\nstones_per_face = 1\ncorner_stones = \"merged\"\n", 3, "spire.corner_stones",
               "stones_per_face >= 2");
  expect_error("[spire]\nwindow_faces = [0, 9]\n", 2, "spire.window_faces[2]", "0..7");
  expect_error("[spire]\nwindow_faces = [1, 1]\n", 2, "spire.window_faces[2]", "twice");
  expect_error("[spire]\nwindow_faces = 3\n", 2, "spire.window_faces", "must be an array");
  expect_error("[spire]\n\nwindow_width = 1.0\n", 3, "spire.window_width", "does not fit in the face");
  expect_error("[spire]\nwindow_head = 0.4\n", 2, "spire.window_head", "pointed head");
  expect_error("[spire]\nwindow_head = 8\n", 2, "spire.window_head", "top of the shell");
  expect_error("[spire]\nwindow_head_shape = \"round\"\n", 2, "spire.window_head_shape", "\"pointed\"");
  expect_error("[spire]\nwindow_arch_segments = 0\n", 2, "spire.window_arch_segments", "[1, 64]");
  expect_error("[spire]\nbase_motion = \"free\"\n", 2, "spire.base_motion", "\"fixed\"");
  expect_error("[spire]\nbase_thickness = 0\nbase_motion = \"fixed\"\n", 3, "spire.base_motion", "no base block");
  expect_error("[spire]\nbase_apothem = 1.0\n", 2, "spire.base_apothem", "at least the shell's outer apothem");
  expect_error("[spire]\nbase_thickness = 0\nbase_apothem = 12\n", 3, "spire.base_apothem", "no base block");
  expect_error("[spire]\nmortar_thickness = 0.3\n", 2, "spire.mortar_thickness", "less than the course pitch");
  expect_error("[spire]\ndensity = 0\n", 2, "spire.density", "must be > 0");
  expect_error("[spire]\nshear_stiffness_ratio = -1\n", 2, "spire.shear_stiffness_ratio", "must be > 0");
  expect_error("spire = 3\n", 1, "spire", "must be a table");
  expect_error("[simulation]\nend_time = 1\n", 1, "block", "(or a generator: [spire], [[wall]], [[tower]])");
}

TEST(DeckSpire, ExampleDeckReads) {
  const SceneSpec s = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/spire_geometry.toml");
  ASSERT_TRUE(spire_of(s.generators));
  EXPECT_EQ(s.blocks.size(), build_spire(SpireSpec{}).blocks.size());
  EXPECT_NEAR(s.joint.normal_stiffness, 93.75e9, 1e3);
}

}  // namespace
}  // namespace polydem
