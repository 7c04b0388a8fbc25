// Verification 14: an imported model runs bitwise identically to the same
// model built in the deck. The wall cut from one box (cut_wall.toml) against
// the same wall imported from OBJ (imported_wall.toml, its committed file)
// and from polydem's .vtu; the spire ([spire]) against its own blocks
// imported from OBJ and .vtu; a cut box against the same boxes listed by
// hand. Same positions, velocities, orientations, energies and histories,
// bit for bit: the import gives back the very blocks (the same corners in
// the same canonical order), so every sum of the run is the same.
#include "io/block_files.hpp"
#include "io/deck.hpp"
#include "io/vtk.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace polydem {
namespace {

namespace fs = std::filesystem;

std::string example(const std::string& name) {
  return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same_blocks(const SceneSpec& a, const SceneSpec& b, bool names = true) {
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const BlockSpec &x = a.blocks[i], &y = b.blocks[i];
    if (names) {
      EXPECT_EQ(x.name, y.name);
    }
    EXPECT_EQ(x.motion, y.motion) << x.name;
    EXPECT_EQ(x.density, y.density) << x.name;
    EXPECT_TRUE(same_bits(x.shape.vertices, y.shape.vertices)) << x.name;
    EXPECT_EQ(x.shape.faces, y.shape.faces) << x.name;
    EXPECT_TRUE(same_bits(x.shape.normals, y.shape.normals)) << x.name;
    EXPECT_TRUE(same_bits(x.shape.offsets, y.shape.offsets)) << x.name;
  }
}

// The state and the ledger (what does not name blocks).
void expect_same_state(const RunReport& a, const RunReport& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.time_step, b.time_step);
  EXPECT_EQ(a.detections, b.detections);
  EXPECT_TRUE(same_bits(a.final_position, b.final_position));
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity));
  EXPECT_EQ(std::memcmp(a.final_orientation.data(), b.final_orientation.data(),
                        a.final_orientation.size() * sizeof(Quat)),
            0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  EXPECT_TRUE(same_bits(a.energies.rows, b.energies.rows));
}

void expect_same_run(const RunReport& a, const RunReport& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.time_step, b.time_step);
  EXPECT_EQ(a.detections, b.detections);
  EXPECT_EQ(a.status, b.status);
  EXPECT_TRUE(same_bits(a.final_position, b.final_position));
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity));
  EXPECT_EQ(a.final_orientation.size(), b.final_orientation.size());
  EXPECT_EQ(std::memcmp(a.final_orientation.data(), b.final_orientation.data(),
                        a.final_orientation.size() * sizeof(Quat)),
            0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  EXPECT_EQ(a.histories.columns, b.histories.columns);
  EXPECT_TRUE(same_bits(a.histories.rows, b.histories.rows));
  EXPECT_TRUE(same_bits(a.energies.rows, b.energies.rows));
  ASSERT_EQ(a.checks.size(), b.checks.size());
  for (std::size_t i = 0; i < a.checks.size(); ++i) EXPECT_EQ(a.checks[i].measured, b.checks[i].measured);
}

class ImportVerification : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polydem_importv_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  fs::path dir_;
};

// What `polydem mesh` writes: the deck's blocks with their motion.
std::string mesh_vtu(const SceneSpec& s) {
  std::vector<Polyhedron> shapes;
  std::vector<int> motion, course;
  for (const BlockSpec& b : s.blocks) {
    shapes.push_back(b.shape);
    motion.push_back(static_cast<int>(b.motion));
    course.push_back(b.course);
  }
  VtkCellData data;
  data.add_ints("course", course).add_ints("motion", motion);
  return vtu_document(shapes, data);
}

std::string mesh_obj(const SceneSpec& s) {
  std::vector<Polyhedron> shapes;
  std::vector<std::string> names;
  for (const BlockSpec& b : s.blocks) {
    shapes.push_back(b.shape);
    names.push_back(b.name);
  }
  return obj_document(shapes, names);
}

TEST_F(ImportVerification, CutWallAndItsImportsRunBitwiseIdentically) {
  const std::vector<std::string> shorter = {"simulation.end_time=0.02"};
  const SceneSpec cut = read_deck(example("cut_wall.toml"), shorter);
  ASSERT_EQ(cut.blocks.size(), 43u);
  // The committed OBJ is what `polydem mesh` writes from cut_wall.toml.
  std::ifstream committed(example("imported_wall.obj"));
  std::stringstream text;
  text << committed.rdbuf();
  EXPECT_EQ(text.str(), mesh_obj(cut)) << "regenerate examples/verification/imported_wall.obj (see cut_wall.toml)";

  const SceneSpec from_obj = read_deck(example("imported_wall.toml"), shorter);
  // A .vtu has no block names (its parts are part1, part2, ...): the same
  // wall from polydem's .vtu, without the named histories and checks.
  write("wall.vtu", mesh_vtu(cut));
  const SceneSpec from_vtu = parse_deck(R"([simulation]
end_time = 0.02
[joint]
normal_stiffness = 98e9
friction_angle = 30.0
damping = 2.1e-5
[output]
history_interval = 0.01
[[import]]
file = "wall.vtu"
)",
                                        path("wall_vtu.toml"));
  expect_same_blocks(cut, from_obj);
  expect_same_blocks(cut, from_vtu, /*names=*/false);

  const RunReport a = run_scene(cut), b = run_scene(from_obj), c = run_scene(from_vtu);
  expect_same_run(a, b);
  expect_same_state(a, c);
  // And the run is not trivial: the stones settled onto their joints.
  double speed = 0;
  for (std::size_t i = 1; i < a.final_velocity.size(); ++i) speed = std::max(speed, a.final_velocity[i].norm());
  EXPECT_GT(speed, 1e-7);
  EXPECT_GT(a.detections, 0);
}

TEST_F(ImportVerification, DryStoneWallOfBoxesAndItsObjRunBitwiseIdentically) {
  // The 52-stone wall of [[block]] boxes (make_box's own corner order): the
  // import keeps each block as written, so this too is the same run.
  const SceneSpec listed = read_deck(example("dry_stone_wall.toml"), {"simulation.end_time=0.02"});
  ASSERT_EQ(listed.blocks.size(), 53u);
  write("wall.obj", mesh_obj(listed));
  const SceneSpec imported = parse_deck(R"([simulation]
end_time = 0.02
[joint]
normal_stiffness = 98e9
friction_angle = 30.0
damping = 2.1e-5
[[import]]
file = "wall.obj"
fixed_below = 0
density = 2600
[output]
history_interval = 0.05
histories = ["c5s52.position"]
[[check]]
kind = "no_drift"
block = "c5s52"
tolerance = 1e-4
[[check]]
kind = "no_drift"
block = "c5s43"
tolerance = 1e-4
[[check]]
kind = "energy_no_growth"
tolerance = 1e-3
)",
                                        path("imported.toml"));
  expect_same_blocks(listed, imported);
  const RunReport a = run_scene(listed), b = run_scene(imported);
  expect_same_run(a, b);
  EXPECT_GT(a.detections, 0);
}

TEST_F(ImportVerification, SpireAndItsImportsRunBitwiseIdentically) {
  // A small spire (5 courses, windows, the tip) under a pulse, with its
  // joints given explicitly so the import deck can say the same.
  const std::string common = R"([simulation]
end_time = 0.01
[joint]
normal_stiffness = 5e9
shear_stiffness = 2e9
friction_angle = 35
[ground_motion]
kind = "sine_pulse"
acceleration_g = 0.3
period = 0.05
)";
  const std::string spire = common + R"([spire]
height = 3.0
tip_height = 1.5
course_height = 0.3
window_sill = 0.3
window_head = 0.9
)";
  const SceneSpec built = parse_deck(spire, path("spire.toml"));
  ASSERT_GT(built.blocks.size(), 40u);
  write("spire.obj", mesh_obj(built));
  write("spire.vtu", mesh_vtu(built));
  const SceneSpec from_obj = parse_deck(common + "[[import]]\nfile = \"spire.obj\"\nfixed_below = 0\n", path("a.toml"));
  const SceneSpec from_vtu = parse_deck(common + "[[import]]\nfile = \"spire.vtu\"\n", path("b.toml"));
  expect_same_blocks(built, from_obj);
  expect_same_blocks(built, from_vtu, /*names=*/false);
  const RunReport a = run_scene(built), b = run_scene(from_obj), c = run_scene(from_vtu);
  expect_same_run(a, b);
  expect_same_state(a, c);
  double speed = 0;
  for (const Vec3& v : a.final_velocity) speed = std::max(speed, v.norm());
  EXPECT_GT(speed, 1e-3);  // the pulse moved it
}

TEST_F(ImportVerification, CutBoxRunsLikeTheBoxesListedByHand) {
  const std::string common = R"([simulation]
end_time = 0.02
[ground_motion]
kind = "sine_pulse"
acceleration_g = 0.4
period = 0.05
[[block]]
name = "base"
shape = "hull"
vertices = [[-1, -1, -0.5], [1, -1, -0.5], [-1, 1, -0.5], [1, 1, -0.5], [-1, -1, 0], [1, -1, 0], [-1, 1, 0], [1, 1, 0]]
motion = "fixed"
)";
  const SceneSpec cut = parse_deck(common + R"([[block]]
name = "pier"
shape = "box"
size = [0.5, 0.5, 1.5]
center = [0, 0, 0.75]
[[cut]]
dip = 0
origin = [0, 0, 0.5]
spacing = 0.5
count = 2
)",
                                   "cut.toml");
  std::string listed = common;
  for (int k = 0; k < 3; ++k) {
    const double z0 = 0.5 * k, z1 = 0.5 * (k + 1);
    std::ostringstream b;
    b << "[[block]]\nname = \"pier_cut" << k + 1 << "\"\nshape = \"hull\"\nvertices = [";
    for (double z : {z0, z1})
      for (double x : {-0.25, 0.25})
        for (double y : {-0.25, 0.25}) b << "[" << x << ", " << y << ", " << z << "], ";
    b << "]\n";
    listed += b.str();
  }
  const SceneSpec hand = parse_deck(listed, "hand.toml");
  expect_same_blocks(cut, hand);
  const RunReport a = run_scene(cut), b = run_scene(hand);
  expect_same_run(a, b);
  double speed = 0;
  for (const Vec3& v : a.final_velocity) speed = std::max(speed, v.norm());
  EXPECT_GT(speed, 1e-3);
}

}  // namespace
}  // namespace polydem
