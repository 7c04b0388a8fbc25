// The [[tower]] deck section and [spire] origin: the generator's blocks,
// named and grouped, a spire standing on the tower's top course, and every
// bad key reported with file, line and key.
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "structures/spire.hpp"
#include "structures/tower.hpp"

namespace polydem {
namespace {

const std::string kFile = "decks/tower.toml";

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

const std::string kTower = R"([[tower]]
name = "belfry"
shape = "octagonal"
origin = [0, 0, 0]
outer_apothem = 2.0
wall_thickness = 0.5
height = 3.0
course_height = 0.3
stones_per_face = 3
group_by = "face"
group = "belfry_"

[[tower.opening]]
faces = [0, 2, 4, 6]
sill = 1.5
width = 0.4
height = 1.0
head = "arch"
voussoirs = 5
)";

TEST(DeckTower, BlocksNamedAndGroupedByFace) {
  const SceneSpec s = parse_deck(kTower, kFile);
  TowerSpec t;
  t.name = "belfry";
  t.outer_apothem = 2.0;
  t.wall_thickness = 0.5;
  t.height = 3.0;
  t.stones_per_face = 3;
  t.openings = {TowerOpening{.faces = {0, 2, 4, 6}, .sill = 1.5, .width = 0.4, .height = 1.0,
                             .head = OpeningHead::arch, .voussoirs = 5}};
  const TowerModel m = build_tower(t);
  ASSERT_EQ(s.blocks.size(), m.blocks.size());
  for (std::size_t i = 0; i < m.blocks.size(); ++i) {
    EXPECT_EQ(s.blocks[i].name, m.blocks[i].name);
    EXPECT_EQ(s.blocks[i].group, "belfry_face" + std::to_string(m.blocks[i].face));
    EXPECT_EQ(s.blocks[i].deck_line, 1);
    EXPECT_EQ(s.blocks[i].course, m.blocks[i].course);
  }
  EXPECT_EQ(std::count_if(s.blocks.begin(), s.blocks.end(),
                          [](const BlockSpec& b) { return b.name.find("_voussoir") != std::string::npos; }),
            20);
}

TEST(DeckTower, SpireOriginPutsItsFirstBedOnTheTowersTop) {
  const std::string deck = kTower + R"(
[spire]
origin = [0, 0, 3.0]
height = 4.0
tip_height = 1.5
course_height = 0.5
window_faces = []
base_thickness = 0
)";
  const SceneSpec s = parse_deck(deck, kFile);
  SpireSpec sp;
  sp.height = 4.0;
  sp.tip_height = 1.5;
  sp.course_height = 0.5;
  sp.window_faces = {};
  sp.base_thickness = 0;
  const SpireModel model = build_spire(sp);
  // The spire's blocks come first (the generators' table order), moved up by 3 m.
  ASSERT_GT(s.blocks.size(), model.blocks.size());
  double lowest = 1e300;
  for (std::size_t i = 0; i < model.blocks.size(); ++i) {
    ASSERT_EQ(s.blocks[i].name, model.blocks[i].name);
    for (std::size_t v = 0; v < model.blocks[i].shape.vertices.size(); ++v) {
      EXPECT_EQ(s.blocks[i].shape.vertices[v], model.blocks[i].shape.vertices[v] + Vec3(0, 0, 3.0));
      lowest = std::min(lowest, s.blocks[i].shape.vertices[v].z());
    }
  }
  EXPECT_EQ(lowest, 3.0);
}

TEST(DeckTower, BadKeysNameFileLineAndKey) {
  expect_error("[[tower]]\nshape = \"hexagonal\"\n", 2, "tower[1].shape", "must be one of");
  expect_error("[[tower]]\nwall_thickness = 1.4\n", 2, "tower[1].wall_thickness", "hollow");
  expect_error("[[tower]]\nstones_per_face = 0\n", 2, "tower[1].stones_per_face", "[1, 32]");
  expect_error("[[tower]]\nspire = true\n", 2, "tower[1].spire", "unknown key");
  expect_error("[[tower]]\nname = \"a\"\n[[tower]]\nname = \"a\"\n", 4, "tower[2].name", "also the name");
  // Lines: the opening's table at 13, faces 14, sill 15, width 16, height 17, head 18, voussoirs 19.
  std::string wide = kTower;
  wide.replace(wide.find("width = 0.4"), 11, "width = 0.9");
  expect_error(wide, 16, "tower[1].opening[1].width", "between its corners");
  std::string nine = kTower;
  nine.replace(nine.find("[0, 2, 4, 6]"), 12, "[0, 9]");
  expect_error(nine, 14, "tower[1].opening[1].faces[2]", "0..7");
  std::string low = kTower;
  low.replace(low.find("sill = 1.5"), 10, "sill = 1.55");
  expect_error(low, 15, "tower[1].opening[1].sill", "quarter course");
  std::string tall = kTower;
  tall.replace(tall.find("height = 1.0"), 12, "height = 1.4");
  expect_error(tall, 17, "tower[1].opening[1].height", "cuts the top course");
  std::string two = kTower + "\n[[tower.opening]]\nfaces = [2]\nwidth = 0.3\nheight = 0.6\n";
  expect_error(two, 22, "tower[1].opening[2].faces", "already has opening 0");
  expect_error("[[tower]]\n[[tower.opening]]\nfaces = [0]\nwidth = 0.3\n", 2, "tower[1].opening[1].height", "missing");
  expect_error("[spire]\norigin = [0, 0]\n", 2, "spire.origin", "3 numbers");
}

}  // namespace
}  // namespace polydem
