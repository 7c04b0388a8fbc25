// [[import]] in a deck: a file relative to the deck, placed, fixed below a
// level, named; every refusal names the deck's file, line and key and the
// file's part and why.
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "io/block_files.hpp"
#include "io/vtk.hpp"

namespace polydem {
namespace {

namespace fs = std::filesystem;

class DeckImport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polydem_import_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "meshes");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  std::string deck_path() const { return (dir_ / "deck.toml").string(); }
  SceneSpec parse(const std::string& deck) const { return parse_deck(deck, deck_path()); }

  void expect_error(const std::string& deck, int line, const std::string& key,
                    const std::vector<std::string>& fragments) const {
    try {
      parse(deck);
      ADD_FAILURE() << "accepted a bad deck; expected an error at line " << line << " key " << key;
    } catch (const DeckError& e) {
      const std::string msg = e.what();
      const std::string where = deck_path() + ":" + std::to_string(line) + ": key '" + key + "': ";
      EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected: " << where;
      for (const auto& f : fragments)
        EXPECT_NE(msg.find(f), std::string::npos) << "message: " << msg << "\nexpected fragment: " << f;
    }
  }

  fs::path dir_;
};

// A base slab and two stones on it, as OBJ.
std::vector<Polyhedron> little_wall() {
  return {make_box(Vec3(2, 1, 0.5), Vec3(0, 0, -0.25)), make_box(Vec3(0.5, 0.5, 0.4), Vec3(-0.25, 0, 0.2)),
          make_box(Vec3(0.5, 0.5, 0.4), Vec3(0.25, 0, 0.2))};
}

TEST_F(DeckImport, ObjRelativeToTheDeckFixedBelowAndNamed) {
  write("meshes/wall.obj", obj_document(little_wall(), {"base", "left", "right"}));
  const SceneSpec s = parse(R"([[import]]
file = "meshes/wall.obj"
fixed_below = 0
density = 2000
group = "wall"
)");
  ASSERT_EQ(s.blocks.size(), 3u);
  EXPECT_EQ(s.blocks[0].name, "base");
  EXPECT_EQ(s.blocks[0].motion, BlockMotion::fixed);
  EXPECT_EQ(s.blocks[1].name, "left");
  EXPECT_EQ(s.blocks[1].motion, BlockMotion::free);
  EXPECT_EQ(s.blocks[2].density, 2000);
  EXPECT_EQ(s.blocks[2].group, "wall");
  EXPECT_EQ(s.blocks[1].deck_line, 1);
  EXPECT_NEAR(mass_properties(s.blocks[1].shape).volume, 0.1, 1e-16);
}

TEST_F(DeckImport, PlacedNamedAndFixedByList) {
  write("wall.obj", obj_document(little_wall(), {"base", "left", "right"}));
  const SceneSpec s = parse(R"([[block]]
name = "ground"
shape = "box"
size = [10, 10, 1]
center = [0, 0, -10]
motion = "fixed"
[[import]]
file = "wall.obj"
scale = 2
rotation = [0, 0, 90]
offset = [5, 0, 1]
name_prefix = "w_"
fixed = ["base", 3]
)");
  ASSERT_EQ(s.blocks.size(), 4u);
  EXPECT_EQ(s.blocks[1].name, "w_base");
  EXPECT_EQ(s.blocks[1].motion, BlockMotion::fixed);
  EXPECT_EQ(s.blocks[2].motion, BlockMotion::free);
  EXPECT_EQ(s.blocks[3].motion, BlockMotion::fixed);
  // "left" (centre (-0.25, 0, 0.2)) scaled by 2, turned 90° about z, moved.
  const Vec3 c = mass_properties(s.blocks[2].shape).centroid;
  EXPECT_NEAR((c - Vec3(5, -0.5, 1.4)).norm(), 0, 1e-14);
  EXPECT_NEAR(mass_properties(s.blocks[2].shape).volume, 8 * 0.1, 1e-14);
}

TEST_F(DeckImport, ImportedBlocksCanBeCut) {
  write("wall.obj", obj_document(little_wall(), {"base", "left", "right"}));
  const SceneSpec s = parse("[[import]]\nfile = \"wall.obj\"\nfixed_below = 0\n[[cut]]\ndip = 0\norigin = [0, 0, 0.2]\n");
  ASSERT_EQ(s.blocks.size(), 5u);
  EXPECT_EQ(s.blocks[1].name, "left_cut1");
  EXPECT_EQ(s.blocks[4].name, "right_cut2");
}

TEST_F(DeckImport, BadImportsNameTheDeckAndThePart) {
  write("wall.obj", obj_document(little_wall(), {"base", "left", "right"}));
  expect_error("[[import]]\nfile = \"nothere.obj\"\n", 2, "import[1].file", {"file not found", "nothere.obj"});
  expect_error("[[import]]\nscale = 2\n", 1, "import[1].file", {"missing"});
  expect_error("[[import]]\nfile = \"wall.obj\"\nscale = 0\n", 3, "import[1].scale", {"must be > 0"});
  expect_error("[[import]]\nfile = \"wall.obj\"\nmotion = \"flying\"\n", 3, "import[1].motion", {"must be one of"});
  expect_error("[[import]]\nfile = \"wall.obj\"\nfixed = [\"roof\"]\n", 3, "import[1].fixed[1]", {"no part named \"roof\""});
  expect_error("[[import]]\nfile = \"wall.obj\"\nfixed = [4]\n", 3, "import[1].fixed[1]", {"part 4 does not exist"});
  expect_error("[[import]]\nfile = \"wall.obj\"\nfixed_below = -5\n", 3, "import[1].fixed_below", {"no part lies wholly below"});
  expect_error("[[import]]\nfile = \"wall.obj\"\n[[import]]\nfile = \"wall.obj\"\n", 4, "import[2].file",
               {"part 1 \"base\" would be block \"base\"", "give a name_prefix"});
  expect_error("[[block]]\nname = \"left\"\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [9, 9, 9]\n[[import]]\nfile = \"wall.obj\"\n",
               6, "import[1]", {"has the name of the [[block]] at line 1"});
  write("x.stl", "solid\n");
  expect_error("[[import]]\nfile = \"x.stl\"\n", 2, "import[1].file", {"unknown block file format '.stl'"});
  // Overlapping parts: the right stone moved 0.1 m into the left one.
  auto blocks = little_wall();
  blocks[2] = make_box(Vec3(0.5, 0.5, 0.4), Vec3(0.15, 0, 0.2));
  write("overlap.obj", obj_document(blocks, {"base", "left", "right"}));
  expect_error("[[import]]\nfile = \"overlap.obj\"\n", 2, "import[1].file",
               {"overlap.obj: part 3 \"right\" overlaps part 2 \"left\" by 0.1 m (penetration depth; shared volume 0.02",
                "overlap_tolerance"});
  // A malformed file: its own line.
  write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  expect_error("[[import]]\nfile = \"bad.obj\"\n", 2, "import[1].file", {"bad.obj:4: face refers to vertex 4"});
  // An open part.
  write("open.obj", "o lidless\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "f 4 3 2 1\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  expect_error("[[import]]\nfile = \"open.obj\"\n", 2, "import[1].file",
               {"open.obj: part 1 \"lidless\": open: edge (5,6) belongs to one face (at line 11)"});
}

TEST_F(DeckImport, VtuCarriesMotionAndCourse) {
  VtkCellData data;
  data.add_ints("course", {-1, 0, 0}).add_ints("motion", {1, 0, 0});
  write("wall.vtu", vtu_document(little_wall(), data));
  const SceneSpec s = parse("[[import]]\nfile = \"wall.vtu\"\n");
  ASSERT_EQ(s.blocks.size(), 3u);
  EXPECT_EQ(s.blocks[0].name, "part1");
  EXPECT_EQ(s.blocks[0].motion, BlockMotion::fixed);
  EXPECT_EQ(s.blocks[1].motion, BlockMotion::free);
  EXPECT_EQ(s.blocks[2].course, 0);
  // The deck's motion wins over the file's.
  const SceneSpec k = parse("[[import]]\nfile = \"wall.vtu\"\nmotion = \"kinematic\"\n");
  EXPECT_EQ(k.blocks[0].motion, BlockMotion::kinematic);
}

}  // namespace
}  // namespace polydem
