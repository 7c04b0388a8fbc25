// The [[wall]] deck section: several walls in one deck, their blocks named
// after each wall and grouped by what they are, and every bad key reported
// with file, line and key.
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "structures/wall.hpp"

namespace polydem {
namespace {

const std::string kFile = "decks/wall.toml";

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

const std::string kTwoWalls = R"([simulation]
end_time = 0.1

[[block]]
name = "ground"
shape = "box"
size = [6, 6, 0.2]
center = [0, 0, -0.1]
motion = "fixed"

[[wall]]
name = "front"
length = 2.0
height = 1.6
unit_size = [0.4, 0.2, 0.2]
bond = "running"
density = 2000

[[wall.opening]]
position = 0.7
sill = 0.4
width = 0.6
height = 0.6

[[wall]]
name = "side"
start = [1.0, 0.2, 0]
end = [1.0, 2.2, 0]
courses = 4
unit_size = [0.4, 0.2, 0.2]
bond = "english"
group_by = "kind"
group = "side_"
)";

TEST(DeckWall, TwoWallsWithOpeningsAndGroups) {
  const SceneSpec s = parse_deck(kTwoWalls, kFile);
  ASSERT_FALSE(s.blocks.empty());
  EXPECT_EQ(s.blocks.front().name, "ground");
  // The generator's own blocks, in order.
  WallSpec front;
  front.name = "front";
  front.length = 2.0;
  front.height = 1.6;
  front.openings = {WallOpening{.position = 0.7, .sill = 0.4, .width = 0.6, .height = 0.6}};
  const WallModel fm = build_wall(front);
  WallSpec side;
  side.name = "side";
  side.origin = Vec3(1.0, 0.2, 0);
  side.direction = 90;
  side.length = 2.0;
  side.height = 0.8;
  side.bond = WallBond::english;
  const WallModel sm = build_wall(side);
  ASSERT_EQ(s.blocks.size(), 1 + fm.blocks.size() + sm.blocks.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < fm.blocks.size(); ++i) {
    const BlockSpec& b = s.blocks[1 + i];
    EXPECT_EQ(b.name, fm.blocks[i].name);
    EXPECT_EQ(b.name.rfind("front_", 0), 0u);
    EXPECT_EQ(b.deck_line, 11);
    EXPECT_DOUBLE_EQ(b.density, 2000);
    EXPECT_EQ(b.motion, BlockMotion::free);
    EXPECT_EQ(b.course, fm.blocks[i].course);
    const std::string course = (b.course < 10 ? "course0" : "course") + std::to_string(b.course);
    EXPECT_EQ(b.group, course) << b.name;
  }
  for (std::size_t i = 0; i < sm.blocks.size(); ++i) {
    const BlockSpec& b = s.blocks[1 + fm.blocks.size() + i];
    EXPECT_EQ(b.name, sm.blocks[i].name);
    EXPECT_EQ(b.deck_line, 25);
    EXPECT_EQ(b.group, std::string("side_") + to_string(sm.blocks[i].kind));
    for (std::size_t v = 0; v < b.shape.vertices.size(); ++v)
      EXPECT_LT((b.shape.vertices[v] - sm.blocks[i].shape.vertices[v]).norm(), 1e-12);
  }
  for (const auto& b : s.blocks) EXPECT_TRUE(names.insert(b.name).second) << b.name;
  EXPECT_EQ(std::count_if(s.blocks.begin(), s.blocks.end(), [](const BlockSpec& b) { return b.group == "side_header"; }),
            std::count_if(sm.blocks.begin(), sm.blocks.end(), [](const GeneratedBlock& b) { return b.kind == BlockKind::header; }));
  EXPECT_EQ(std::count_if(s.blocks.begin(), s.blocks.end(), [](const BlockSpec& b) { return b.name == "front_opening0_lintel"; }), 1);
}

// Two stretcher bond walls meeting at a right angle (corner_with): no two
// blocks overlap, the volumes sum to the L-shaped plan's times the height,
// and the corner square belongs to the first wall's units in even courses
// and to the second's in odd ones.
TEST(DeckWall, CornerInterlocksCourseByCourse) {
  const std::string deck = R"([[wall]]
name = "a"
origin = [0, 0, 0]
direction = 0
length = 2.0
height = 1.0
leaves = 2

[[wall]]
name = "b"
corner_with = "a"
corner_at = "end"
turn = "left"
length = 1.6
height = 1.0
)";
  const SceneSpec s = parse_deck(deck, kFile);
  double volume = 0;
  for (const auto& b : s.blocks) volume += mass_properties(b.shape).volume;
  // a: 2.0 x 0.4 in plan; b: 1.6 x 0.2 from a's outer face (y = -0.2), its
  // corner square 0.2 x 0.4 shared: 0.8 + 0.32 - 0.08 = 1.04 m², 1 m high.
  EXPECT_NEAR(volume, 1.04, 1e-12);
  // The corner square: x in [1.8, 2.0], y in [-0.2, 0.2].
  const Vec3 probe(1.9, 0.0, 0.0);
  for (int c = 0; c < 5; ++c) {
    int owners = 0;
    for (const auto& b : s.blocks) {
      const Vec3 p = probe + Vec3(0, 0.1 * (b.name.find("leaf1") != std::string::npos ? 1 : -1), 0.2 * c + 0.1);
      bool inside = true;
      for (std::size_t f = 0; f < b.shape.faces.size(); ++f)
        inside = inside && b.shape.normals[f].dot(p) < b.shape.offsets[f] - 1e-9;
      if (!inside) continue;
      ++owners;
      EXPECT_EQ(b.name.substr(0, 2), c % 2 == 0 ? "a_" : "b_") << "course " << c << ": " << b.name;
    }
    EXPECT_GE(owners, 1) << "course " << c;
  }
  // No overlaps: every pair whose boxes meet is separated along a face normal
  // of one of them (boxes in the walls' frames).
  for (std::size_t i = 0; i < s.blocks.size(); ++i)
    for (std::size_t j = i + 1; j < s.blocks.size(); ++j) {
      bool apart = false;
      for (const auto* p : {&s.blocks[i].shape, &s.blocks[j].shape})
        for (const auto& n : p->normals) {
          double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
          for (const auto& v : s.blocks[i].shape.vertices) a0 = std::min(a0, n.dot(v)), a1 = std::max(a1, n.dot(v));
          for (const auto& v : s.blocks[j].shape.vertices) b0 = std::min(b0, n.dot(v)), b1 = std::max(b1, n.dot(v));
          apart = apart || a1 <= b0 + 1e-9 || b1 <= a0 + 1e-9;
        }
      EXPECT_TRUE(apart) << s.blocks[i].name << " overlaps " << s.blocks[j].name;
    }
}

TEST(DeckWall, CornersThatCannotCloseAreRefused) {
  const std::string a = "[[wall]]\nname = \"a\"\nlength = 2.0\nheight = 1.0\n";
  expect_error(a + "[[wall]]\ncorner_with = \"z\"\n", 6, "wall[2].corner_with", "no [[wall]] above");
  expect_error(a + "bond = \"english\"\n[[wall]]\ncorner_with = \"a\"\n", 7, "wall[2].corner_with",
               "cannot close a corner");
  expect_error(a + "[[wall]]\ncorner_with = \"a\"\nheight = 1.0\nunit_size = [0.4, 0.25, 0.2]\n", 6,
               "wall[2].corner_with", "cannot interlock");
  expect_error(a + "[[wall]]\ncorner_with = \"a\"\norigin = [0, 0, 0]\n", 7, "wall[2].origin", "placed by");
  expect_error(a + "[[wall]]\nname = \"b\"\ncorner_with = \"a\"\nheight = 1.0\n[[wall]]\ncorner_with = \"a\"\nheight = 1.0\n", 9,
               "wall[3].corner_at", "already has a corner");
  expect_error(a + "[[wall]]\nturn = \"left\"\n", 6, "wall[2].turn", "with corner_with only");
  // Closers need the same units on both walls, two headers to a unit length.
  const std::string e = a + "bond = \"english\"\n[[wall]]\ncorner_with = \"a\"\nheight = 1.0\nbond = \"flemish\"\n";
  expect_error(e + "unit_size = [0.5, 0.2, 0.25]\n", 10, "wall[2].unit_size", "same length and width");
  expect_error(a + "bond = \"header\"\nunit_size = [0.4, 0.2, 0.15]\n[[wall]]\ncorner_with = \"a\"\nheight = 1.0\n"
                   "bond = \"header\"\nunit_size = [0.4, 0.2, 0.15]\n",
               11, "wall[2].unit_size", "two headers side by side");
  expect_error(a + "bond = \"english\"\n[[wall]]\ncorner_with = \"a\"\nheight = 1.0\nbond = \"english\"\nlength = 1.0\n", 10,
               "wall[2].length", "two unit lengths");
  // An opening too close to the corner.
  expect_error(a + "[[wall.opening]]\nposition = 0.6\nwidth = 1.0\nheight = 0.4\n[[wall]]\ncorner_with = \"a\"\nheight = 1.0\n",
               7, "wall[1].opening[1].width", "for a corner");
}

// English and Flemish bond walls at a corner (corner_with): the second
// wall's bond is turned by a course so that the two own the corner square
// in alternate courses, each with a quoin header and a queen closer (group
// "closer" with group_by = "kind"): one closer per course, exactly a quarter
// unit (0.1 m) by a unit length (0.4 m) by a course; the volume is the
// L-shaped plan's times the height.
TEST(DeckWall, EnglishAndFlemishCornersCloseWithQueenClosers) {
  for (const char* bond : {"english", "flemish"}) {
    SCOPED_TRACE(bond);
    const std::string b = std::string("bond = \"") + bond + "\"\ngroup_by = \"kind\"\n";
    const std::string deck = "[[wall]]\nname = \"a\"\nlength = 2.0\nheight = 1.2\n" + b +
                             "[[wall]]\nname = \"b\"\ncorner_with = \"a\"\nturn = \"right\"\nlength = 1.6\nheight = 1.2\n" + b;
    const SceneSpec s = parse_deck(deck, kFile);
    double volume = 0;
    int closers = 0;
    for (const auto& blk : s.blocks) {
      const double v = mass_properties(blk.shape).volume;
      volume += v;
      if (blk.group != "closer") continue;
      ++closers;
      EXPECT_NEAR(v, 0.1 * 0.4 * 0.2, 1e-15) << blk.name;
    }
    // a: 2.0 x 0.4; b: 1.6 x 0.4 from a's outer face, sharing 0.4 x 0.4: 1.28 m², 1.2 m high.
    EXPECT_NEAR(volume, 1.28 * 1.2, 1e-12);
    EXPECT_EQ(closers, 6);
  }
}

TEST(DeckWall, GroupByLeafAndWall) {
  const std::string base = "[[wall]]\nname = \"w\"\nlength = 2.0\nheight = 0.4\nleaves = 2\nthrough_every = 2\n";
  const SceneSpec by_leaf = parse_deck(base + "group_by = \"leaf\"\n", kFile);
  std::set<std::string> groups;
  for (const auto& b : by_leaf.blocks) groups.insert(b.group);
  EXPECT_EQ(groups, (std::set<std::string>{"leaf0", "leaf1", "through"}));
  const SceneSpec by_wall = parse_deck(base + "group_by = \"wall\"\n", kFile);
  for (const auto& b : by_wall.blocks) EXPECT_EQ(b.group, "w");
}

// Lines of the bad decks below: [[wall]] at 1, [[wall.opening]] at 7.
std::string wall_with(const std::string& wall_keys, const std::string& opening_keys = "") {
  std::string t = "[[wall]]\nname = \"w\"\nlength = 2.0\nheight = 1.6\nunit_size = [0.4, 0.2, 0.2]\n" + wall_keys;
  if (!opening_keys.empty()) {
    while (std::count(t.begin(), t.end(), '\n') < 6) t += "\n";
    t += "[[wall.opening]]\n" + opening_keys;
  }
  return t;
}

TEST(DeckWall, BadWallKeysNameFileLineAndKey) {
  expect_error(wall_with("bond = \"herringbone\"\n"), 6, "wall[1].bond", "must be one of");
  expect_error("[[wall]]\nlength = 2.0\nbond = \"english\"\nunit_size = [0.4, 0.2, 0.15]\n", 4, "wall[1].unit_size",
               "cannot close");
  expect_error("[[wall]]\nlength = 2.0\nunit_size = [2.5, 0.2, 0.2]\n", 3, "wall[1].unit_size",
               "longer than the wall");
  expect_error(wall_with("leaves = 2\nbond = \"flemish\"\n"), 6, "wall[1].leaves", "only a stretcher bond");
  expect_error(wall_with("through_every = 3\n"), 6, "wall[1].through_every", "at least 2 leaves");
  expect_error(wall_with("courses = 4\n"), 6, "wall[1].courses", "not both");
  expect_error(wall_with("start = [0, 0, 0]\nend = [2, 0, 0]\n"), 3, "wall[1].length", "either start and end");
  expect_error("[[wall]]\nstart = [0, 0, 0]\nend = [2, 0, 0.1]\n", 3, "wall[1].end", "level bed");
  expect_error("[[wall]]\nstart = [0, 0, 0]\n", 1, "wall[1].end", "missing");
  expect_error(wall_with("mortar = 0.01\n"), 6, "wall[1].mortar", "unknown key");
  expect_error(wall_with("group_by = \"colour\"\n"), 6, "wall[1].group_by", "must be one of");
  expect_error("[[wall]]\nname = \"a\"\n[[wall]]\nname = \"a\"\n", 4, "wall[2].name", "also the name of wall[1]");
  expect_error("[[wall]]\nname = \"front wall\"\n", 2, "wall[1].name", "without spaces");
  expect_error("[[block]]\nname = \"w_course00_leaf0_unit0\"\nshape = \"box\"\nsize = [1, 1, 1]\n" +
                   std::string("[[wall]]\nname = \"w\"\n"),
               5, "wall[1]", "has the name of the [[block]]");
}

TEST(DeckWall, BadOpeningsNameFileLineAndKey) {
  const std::string ok = "position = 0.7\nsill = 0.4\nwidth = 0.6\nheight = 0.6\n";
  EXPECT_NO_THROW(parse_deck(wall_with("", ok), kFile));
  expect_error(wall_with("", "position = 0.7\nsill = 0.4\nwidth = 1.2\nheight = 0.6\n"), 10,
               "wall[1].opening[1].width", "quarter unit");
  expect_error(wall_with("", "position = 0.2\nsill = 0.4\nwidth = 0.6\nheight = 0.6\n"), 8,
               "wall[1].opening[1].position", "at least 0.3");
  expect_error(wall_with("", ok + "[[wall.opening]]\nposition = 1.1\nwidth = 0.6\nheight = 0.6\n"), 13,
               "wall[1].opening[2].position", "overlaps opening 0");
  expect_error(wall_with("", "position = 0.7\nsill = 0.4\nwidth = 0.6\nheight = 1.2\n"), 11,
               "wall[1].opening[1].height", "cuts the top course");
  expect_error(wall_with("", "position = 0.7\nsill = 0.42\nwidth = 0.6\nheight = 0.6\n"), 9,
               "wall[1].opening[1].sill", "quarter course");
  expect_error(wall_with("", ok + "head = \"arch\"\nvoussoirs = 2\n"), 13, "wall[1].opening[1].voussoirs", "[3, 64]");
  expect_error(wall_with("", ok + "voussoirs = 5\n"), 12, "wall[1].opening[1].voussoirs", "arch");
  expect_error(wall_with("", ok + "head = \"gothic\"\n"), 12, "wall[1].opening[1].head", "must be one of");
  expect_error(wall_with("", "sill = 0.4\nwidth = 0.6\nheight = 0.6\n"), 7, "wall[1].opening[1].position", "missing");
  expect_error(wall_with("", ok + "depth = 1\n"), 12, "wall[1].opening[1].depth", "unknown key");
  expect_error(wall_with("", ok + "bearing = 0.05\n"), 12, "wall[1].opening[1].bearing", "quarter unit");
}

}  // namespace
}  // namespace polydem
