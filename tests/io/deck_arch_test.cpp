// The [[arch]] and [[column]] deck sections: keys reach the generators, the
// section's name prefixes its blocks', groups say what each block is, several
// tables in one deck give distinct names, and every bad key is reported with
// file, line and key.
#include "io/deck.hpp"

#include "structures/arch.hpp"
#include "structures/column.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace polydem {
namespace {

const std::string kFile = "decks/arch.toml";

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

const BlockSpec* find(const SceneSpec& s, const std::string& name) {
  for (const auto& b : s.blocks)
    if (b.name == name) return &b;
  return nullptr;
}

int count_group(const SceneSpec& s, const std::string& group) {
  return static_cast<int>(
      std::count_if(s.blocks.begin(), s.blocks.end(), [&](const BlockSpec& b) { return b.group == group; }));
}

TEST(DeckArch, KeysReachTheArch) {
  const SceneSpec s = parse_deck(R"([[arch]]
name = "nave"
shape = "segmental"
span = 5.0
rise = 1.5
voussoirs = 11
thickness = 0.4
depth = 3.0
rings = 3
spans = 2
supports = "piers"
pier_width = 1.2
pier_height = 2.5
pier_courses = 2
base_thickness = 0.5
support_motion = "kinematic"
origin = [1, 2, 3]
direction = [0, 1, 0]
density = 2000
)",
                                 kFile);
  ArchSpec a;
  a.shape = ArchShape::segmental;
  a.span = 5.0;
  a.rise = 1.5;
  a.voussoirs = 11;
  a.thickness = 0.4;
  a.depth = 3.0;
  a.rings = 3;
  a.spans = 2;
  a.supports = ArchSupports::piers;
  a.pier_width = 1.2;
  a.pier_height = 2.5;
  a.pier_courses = 2;
  a.base_thickness = 0.5;
  a.origin = Vec3(1, 2, 3);
  a.direction = Vec3(0, 1, 0);
  const ArchModel m = build_arch(a);
  ASSERT_EQ(s.blocks.size(), m.blocks.size());
  for (std::size_t i = 0; i < m.blocks.size(); ++i) {
    EXPECT_EQ(s.blocks[i].name, "nave_" + m.blocks[i].name);
    EXPECT_EQ(s.blocks[i].shape.vertices, m.blocks[i].shape.vertices) << m.blocks[i].name;
    EXPECT_EQ(s.blocks[i].deck_line, 1);
    EXPECT_DOUBLE_EQ(s.blocks[i].density, 2000.0);
  }
  // Voussoirs by ring in `course`; 2 spans × (11 + 12 + 11); 3 piers of 2 courses.
  EXPECT_EQ(count_group(s, "voussoir"), 2 * (11 + 12 + 11));
  EXPECT_EQ(count_group(s, "pier"), 6);
  EXPECT_EQ(count_group(s, "base"), 1);
  const BlockSpec* v = find(s, "nave_span1_ring1_voussoir11");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->course, 1);
  EXPECT_EQ(v->motion, BlockMotion::free);
  ASSERT_NE(find(s, "nave_pier2_course1"), nullptr);
  EXPECT_EQ(find(s, "nave_pier2_course1")->course, 1);
  EXPECT_EQ(find(s, "nave_base")->motion, BlockMotion::kinematic);
}

TEST(DeckArch, DefaultsAndSeveralArchesInOneDeck) {
  const SceneSpec one = parse_deck("[[arch]]\n", kFile);
  // A 2 m semicircle of 9 voussoirs on two fixed abutments.
  EXPECT_EQ(one.blocks.size(), 11u);
  EXPECT_EQ(one.blocks.front().name, "arch_voussoir00");
  EXPECT_EQ(find(one, "arch_abutment0")->motion, BlockMotion::fixed);
  EXPECT_EQ(find(one, "arch_abutment1")->group, "abutment");
  // Two unnamed arches are arch1 and arch2; named ones keep their names.
  const SceneSpec two = parse_deck("[[arch]]\n[[arch]]\norigin = [0, 5, 0]\n", kFile);
  EXPECT_NE(find(two, "arch1_voussoir00"), nullptr);
  EXPECT_NE(find(two, "arch2_voussoir00"), nullptr);
  std::set<std::string> names;
  for (const auto& b : two.blocks) names.insert(b.name);
  EXPECT_EQ(names.size(), two.blocks.size());
  expect_error("[[arch]]\nname = \"a\"\n\n[[arch]]\nname = \"a\"\norigin = [0, 5, 0]\n", 4, "arch[2]",
               "has the name of a block of [arch[1]] at line 1");
  expect_error("[[block]]\nname = \"arch_base\"\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [0, 9, 0]\n\n"
               "[[arch]]\nsupports = \"base\"\n",
               7, "arch[1]", "has the name of the [[block]] at line 1");
  // Arches and columns mix, and with listed blocks.
  const SceneSpec mix = parse_deck("[[arch]]\n[[column]]\norigin = [0, 4, 0]\n", kFile);
  EXPECT_EQ(mix.blocks.size(), 11u + 1 + 4);
  EXPECT_EQ(count_group(mix, "drum"), 4);
}

TEST(DeckArch, OverridesApply) {
  const SceneSpec s = parse_deck("[[arch]]\n", kFile, {"arch[1].voussoirs=5"});
  EXPECT_EQ(count_group(s, "voussoir"), 5);
}

TEST(DeckArch, BadKeysNameFileLineAndKey) {
  expect_error("[[arch]]\nspan = 4\nheight = 1\n", 3, "arch[1].height", "unknown key");
  expect_error("[[arch]]\nvoussoirs = 2\n", 2, "arch[1].voussoirs", "[3, 1000]");
  expect_error("[[arch]]\nradius = 1\n\nthickness = 1.2\n", 4, "arch[1].thickness", "less than the intrados radius");
  expect_error("[[arch]]\nembrace = 360\n", 2, "arch[1].embrace", "(0, 360)");
  expect_error("[[arch]]\nembrace = 0\n", 2, "arch[1].embrace", "must be > 0");
  expect_error("[[arch]]\nshape = \"pointed\"\npointedness = 3\n", 3, "arch[1].pointedness", "(0, 2]");
  expect_error("[[arch]]\nshape = \"gothic\"\n", 2, "arch[1].shape", "\"pointed\"");
  expect_error("[[arch]]\nspan = 4\nradius = 2\n", 3, "arch[1].radius", "not both");
  expect_error("[[arch]]\nrise = 1\n", 2, "arch[1].rise", "not used by shape = \"circular\"");
  expect_error("[[arch]]\nshape = \"segmental\"\nspan = 4\n", 1, "arch[1].rise", "missing");
  expect_error("[[arch]]\nshape = \"segmental\"\nspan = 4\nrise = 2\n", 4, "arch[1].rise", "span/2");
  expect_error("[[arch]]\nshape = \"segmental\"\nrise = 0.5\nsupports = \"base\"\n", 4, "arch[1].supports",
               "horizontal springing");
  expect_error("[[arch]]\npier_courses = 3\n", 2, "arch[1].pier_courses", "only piers");
  expect_error("[[arch]]\nbase_thickness = 3\n", 2, "arch[1].base_thickness", "no base slab");
  expect_error("[[arch]]\nsupports = \"base\"\npier_height = 3\n", 3, "arch[1].pier_height", "no piers");
  expect_error("[[arch]]\npier_width = 0.1\n", 2, "arch[1].pier_width", "at least");
  expect_error("[[arch]]\nspans = 3\npier_width = 0.4\n", 3, "arch[1].pier_width", "interior pier");
  expect_error("[[arch]]\ndirection = [0, 0, 1]\n", 2, "arch[1].direction", "horizontal");
  expect_error("[[arch]]\nname = \"\"\n", 2, "arch[1].name", "must not be empty");
  expect_error("[[arch]]\nsupport_motion = \"free\"\n", 2, "arch[1].support_motion", "\"fixed\"");
  expect_error("[[arch]]\n[[arch]]\nrings = 0\n", 3, "arch[2].rings", "[1, 200]");
  expect_error("[arch]\nspan = 2\n", 1, "arch", "write [[arch]]");
  expect_error("[[arch]]\nspan = 1e9\n", 2, "arch[1].span", "from 1 mm to 100 km");
  std::string many;
  for (int i = 0; i < 5; ++i) many += "[[arch]]\nrings = 200\nvoussoirs = 20\n";
  expect_error(many, 13, "arch[5]", "at most 20000 in a deck");
}

TEST(DeckColumn, KeysReachTheColumn) {
  const SceneSpec s = parse_deck(R"([[column]]
name = "c1"
drums = 3
radius = 0.35
sides = 24
drum_heights = [0.5, 0.6, 0.7]
plinth_width = 1.0
plinth_height = 0.2
capital = "frustum"
capital_width = 1.0
capital_height = 0.3
base_width = 3.0
base_thickness = 0.4
base_motion = "kinematic"
origin = [2, 0, 0]
density = 2500
)",
                                 kFile);
  ColumnSpec c;
  c.drums = 3;
  c.radius = 0.35;
  c.sides = 24;
  c.drum_heights = {0.5, 0.6, 0.7};
  c.plinth_width = 1.0;
  c.plinth_height = 0.2;
  c.capital = ColumnCapital::frustum;
  c.capital_width = 1.0;
  c.capital_height = 0.3;
  c.base_width = 3.0;
  c.base_thickness = 0.4;
  c.origin = Vec3(2, 0, 0);
  const ColumnModel m = build_column(c);
  ASSERT_EQ(s.blocks.size(), m.blocks.size());
  for (std::size_t i = 0; i < m.blocks.size(); ++i) {
    EXPECT_EQ(s.blocks[i].name, "c1_" + m.blocks[i].name);
    EXPECT_EQ(s.blocks[i].shape.vertices, m.blocks[i].shape.vertices);
    EXPECT_DOUBLE_EQ(s.blocks[i].density, 2500.0);
  }
  EXPECT_EQ(find(s, "c1_base")->motion, BlockMotion::kinematic);
  EXPECT_EQ(find(s, "c1_base")->group, "base");
  EXPECT_EQ(find(s, "c1_plinth")->group, "plinth");
  EXPECT_EQ(find(s, "c1_capital")->group, "capital");
  EXPECT_EQ(find(s, "c1_drum02")->group, "drum");
  EXPECT_EQ(find(s, "c1_drum02")->course, 2);
  // drum_heights alone sets the number of drums.
  const SceneSpec d = parse_deck("[[column]]\ndrum_heights = [1, 1]\n", kFile);
  EXPECT_EQ(count_group(d, "drum"), 2);
}

TEST(DeckColumn, BadKeysNameFileLineAndKey) {
  expect_error("[[column]]\ndrums = 0\n", 2, "column[1].drums", "[1, 1000]");
  expect_error("[[column]]\nsides = 3\n", 2, "column[1].sides", "[4, 128]");
  expect_error("[[column]]\nheight = 2\ndrum_heights = [1, 1]\n", 3, "column[1].drum_heights", "not both");
  expect_error("[[column]]\ndrums = 3\ndrum_heights = [1, 1]\n", 3, "column[1].drum_heights", "one height per drum");
  expect_error("[[column]]\ndrum_heights = [1, -1]\n", 2, "column[1].drum_heights[2]", "must be > 0");
  expect_error("[[column]]\ndrum_heights = []\n", 2, "column[1].drum_heights", "at least one");
  expect_error("[[column]]\ncapital = \"ionic\"\n", 2, "column[1].capital", "\"abacus\"");
  expect_error("[[column]]\ncapital_height = 0.3\n", 2, "column[1].capital_height", "no capital");
  expect_error("[[column]]\nplinth_height = 0.2\nplinth_width = 0.3\n", 3, "column[1].plinth_width",
               "at least the drums' diameter");
  expect_error("[[column]]\nbase_width = 0.2\n", 2, "column[1].base_width", "at least as wide");
  expect_error("[[column]]\nradius = 0\n", 2, "column[1].radius", "must be > 0");
  expect_error("[[column]]\nfoo = 0\n", 2, "column[1].foo", "unknown key");
  expect_error("[[column]]\nheight = 1000\n", 2, "column[1].height", "at most 1000 radii");
  std::string many;
  for (int i = 0; i < 25; ++i) many += "[[column]]\ndrums = 1000\nheight = 100\n";
  expect_error(many, 58, "column[20]", "at most 20000 in a deck");
}

// CGAL builds the frustum capital: the same deck read twice gives the same
// blocks, vertex for vertex and face for face.
TEST(DeckColumn, TheSameDeckReadTwiceGivesTheSameBlocks) {
  const std::string text = "[[column]]\ncapital = \"frustum\"\n[[arch]]\nrings = 3\norigin = [0, 4, 0]\n";
  const SceneSpec a = parse_deck(text, kFile), b = parse_deck(text, kFile);
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].shape.vertices, b.blocks[i].shape.vertices) << a.blocks[i].name;
    EXPECT_EQ(a.blocks[i].shape.faces, b.blocks[i].shape.faces) << a.blocks[i].name;
  }
}

// The gallery's decks (docs/structures.md) read, with the blocks they show.
TEST(DeckArch, ExampleDecksRead) {
  const std::pair<const char*, std::size_t> decks[] = {
      {"arch_semicircular.toml", 11 + 2}, {"arch_pointed.toml", 12 + 2 * 4 + 1}, {"arch_segmental.toml", 9 + 2 * 3 + 1}, {"arch_horseshoe.toml", 14 + 2},
      {"barrel_vault.toml", 3 * 9 + 3 * 10 + 2 * 2 + 1}, {"column.toml", 1 + 1 + 6 + 1}, {"arcade.toml", 22 + 9 + 1}};
  for (const auto& [name, blocks] : decks) {
    const SceneSpec s = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/structures/" + name);
    EXPECT_EQ(s.blocks.size(), blocks) << name;
  }
}

}  // namespace
}  // namespace polydem
