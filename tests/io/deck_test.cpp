// Deck reader: good decks land in the structs, overrides apply before
// validation, and every bad deck is rejected with file, line and key.
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

namespace polydem {
namespace {

// Raw-string decks start with a newline after R"( for readability; drop it
// so that the first line shown is line 1.
std::string deck(const char* text) {
  std::string s(text);
  if (!s.empty() && s.front() == '\n') s.erase(0, 1);
  return s;
}

const std::string kFile = "decks/bad.toml";

// Parses `text` and expects a DeckError naming file, line, key and `fragment`.
void expect_error(const std::string& text, int line, const std::string& key, const std::string& fragment,
                  const std::vector<std::string>& overrides = {}) {
  try {
    parse_deck(text, kFile, overrides);
    ADD_FAILURE() << "accepted a bad deck; expected an error at line " << line << " key " << key;
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    const std::string where = kFile + ":" + std::to_string(line) + ": key '" + key + "': ";
    EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected: " << where;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "message: " << msg << "\nexpected fragment: " << fragment;
  }
}

// Same for an error caused by an override: "--set key 'KEY'" instead of a line.
void expect_override_error(const std::string& text, const std::vector<std::string>& overrides,
                           const std::string& key, const std::string& fragment) {
  try {
    parse_deck(text, kFile, overrides);
    ADD_FAILURE() << "accepted a bad override; expected an error for " << key;
  } catch (const DeckError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(kFile + ": --set ", 0), 0u) << "message: " << msg;
    EXPECT_NE(msg.find(key), std::string::npos) << "message: " << msg << "\nexpected key: " << key;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "message: " << msg << "\nexpected fragment: " << fragment;
  }
}

double volume(const Polyhedron& p) { return mass_properties(p).volume; }

Eigen::AlignedBox3d bounds(const Polyhedron& p) {
  Eigen::AlignedBox3d b;
  for (const auto& v : p.vertices) b.extend(v);
  return b;
}

const std::string kGoodDeck = deck(R"(
# comment line
[simulation]
end_time = 2.5
time_step = 1e-5
safety_factor = 0.5
gravity = [0, 0, -10]
contact_margin = 0.01
threads = 2
overlap_tolerance = 1e-5
settle_velocity = 1e-3
settle_time = 0.25

[joint]
normal_stiffness = 1e9
friction_angle = 35
cohesion = 100
tensile_strength = 50
damping = 1e-4

[[block]]
name = "base"
shape = "box"
size = [4, 2, 1]
center = [0, 0, -0.5]
motion = "fixed"

[[block]]
shape = "box"
size = [1, 2, 3]
center = [0, 0, 1.5]
rotation = [0, 0, 90]
offset = [10, 0, 0]
density = 2000
velocity = [1, 2, 3]
angular_velocity = [0.1, 0, 0]
course = 4
group = "pier"

[[block]]
name = "wedge"
shape = "prism"
polygon = [[0, 0], [1, 0], [0, 1]]
z = [1, 3]
motion = "kinematic"

[[block]]
name = "tet"
shape = "hull"
vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]

[ground_motion]
kind = "sine_pulse"
applied_as = "kinematic"
direction = [3, 4, 0]
start_time = 0.1
acceleration_g = 0.5
period = 0.4

[output]
history_interval = 0.01
histories = ["block2.position", "wedge.contact_force"]
energies = false

[[check]]
kind = "resting_weight"
block = "base"
expected = 12.5
tolerance = 0.001

[[check]]
kind = "energy_no_growth"
)");

TEST(Deck, GoodDeckLandsInTheStructs) {
  const SceneSpec s = parse_deck(kGoodDeck, "decks/good.toml");
  EXPECT_EQ(s.deck_path, "decks/good.toml");
  EXPECT_EQ(s.deck_text, kGoodDeck);

  EXPECT_DOUBLE_EQ(s.simulation.end_time, 2.5);
  EXPECT_DOUBLE_EQ(s.simulation.time_step, 1e-5);
  EXPECT_DOUBLE_EQ(s.simulation.safety_factor, 0.5);
  EXPECT_EQ(s.simulation.gravity, Vec3(0, 0, -10));
  EXPECT_DOUBLE_EQ(s.simulation.contact_margin, 0.01);
  EXPECT_EQ(s.simulation.threads, 2);
  EXPECT_DOUBLE_EQ(s.simulation.overlap_tolerance, 1e-5);
  EXPECT_DOUBLE_EQ(s.simulation.settle_velocity, 1e-3);
  EXPECT_DOUBLE_EQ(s.simulation.settle_time, 0.25);

  EXPECT_DOUBLE_EQ(s.joint.normal_stiffness, 1e9);
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, 0.4e9);  // 0.4 kn when absent
  EXPECT_DOUBLE_EQ(s.joint.friction_angle, 35);
  EXPECT_DOUBLE_EQ(s.joint.cohesion, 100);
  EXPECT_DOUBLE_EQ(s.joint.tensile_strength, 50);
  EXPECT_DOUBLE_EQ(s.joint.damping, 1e-4);

  ASSERT_EQ(s.blocks.size(), 4u);
  const BlockSpec& base = s.blocks[0];
  EXPECT_EQ(base.name, "base");
  EXPECT_EQ(base.motion, BlockMotion::fixed);
  EXPECT_EQ(base.deck_line, 20);
  EXPECT_NEAR(volume(base.shape), 8.0, 1e-12);
  EXPECT_TRUE(bounds(base.shape).min().isApprox(Vec3(-2, -1, -1)));
  EXPECT_TRUE(bounds(base.shape).max().isApprox(Vec3(2, 1, 0)));
  EXPECT_DOUBLE_EQ(base.density, 2600);  // default
  EXPECT_EQ(base.course, -1);

  // Default name, rotation about its own centroid then offset.
  const BlockSpec& b2 = s.blocks[1];
  EXPECT_EQ(b2.name, "block2");
  EXPECT_EQ(b2.deck_line, 27);
  EXPECT_NEAR(volume(b2.shape), 6.0, 1e-12);
  const auto box = bounds(b2.shape);
  EXPECT_NEAR(box.min().x(), 9.0, 1e-12);  // the 2 m side now along x
  EXPECT_NEAR(box.max().x(), 11.0, 1e-12);
  EXPECT_NEAR(box.min().y(), -0.5, 1e-12);
  EXPECT_NEAR(box.max().y(), 0.5, 1e-12);
  EXPECT_NEAR(box.min().z(), 0.0, 1e-12);
  EXPECT_NEAR(box.max().z(), 3.0, 1e-12);
  EXPECT_TRUE(mass_properties(b2.shape).centroid.isApprox(Vec3(10, 0, 1.5), 1e-12));
  EXPECT_DOUBLE_EQ(b2.density, 2000);
  EXPECT_EQ(b2.motion, BlockMotion::free);
  EXPECT_EQ(b2.velocity, Vec3(1, 2, 3));
  EXPECT_EQ(b2.angular_velocity, Vec3(0.1, 0, 0));
  EXPECT_EQ(b2.course, 4);
  EXPECT_EQ(b2.group, "pier");

  const BlockSpec& wedge = s.blocks[2];
  EXPECT_EQ(wedge.motion, BlockMotion::kinematic);
  EXPECT_NEAR(volume(wedge.shape), 0.5 * 2.0, 1e-12);
  EXPECT_NEAR(bounds(wedge.shape).min().z(), 1.0, 1e-12);

  EXPECT_NEAR(volume(s.blocks[3].shape), 1.0 / 6.0, 1e-12);
  EXPECT_EQ(s.blocks[3].shape.vertices.size(), 4u);

  const GroundMotionSpec& g = s.ground_motion;
  EXPECT_EQ(g.kind, GroundMotionKind::sine_pulse);
  EXPECT_EQ(g.applied_as, GroundMotionApplication::kinematic);
  EXPECT_TRUE(g.direction.isApprox(Vec3(0.6, 0.8, 0)));
  EXPECT_DOUBLE_EQ(g.start_time, 0.1);
  EXPECT_DOUBLE_EQ(g.acceleration, 0.5 * 9.81);
  EXPECT_DOUBLE_EQ(g.period, 0.4);
  EXPECT_EQ(g.deck_line, 51);

  EXPECT_DOUBLE_EQ(s.output.history_interval, 0.01);
  EXPECT_FALSE(s.output.energies);
  ASSERT_EQ(s.output.histories.size(), 2u);
  EXPECT_EQ(s.output.histories[0].block, "block2");
  EXPECT_EQ(s.output.histories[0].quantity, "position");
  EXPECT_EQ(s.output.histories[1].block, "wedge");
  EXPECT_EQ(s.output.histories[1].quantity, "contact_force");

  ASSERT_EQ(s.checks.size(), 2u);
  EXPECT_EQ(s.checks[0].kind, "resting_weight");
  EXPECT_EQ(s.checks[0].block, "base");
  EXPECT_DOUBLE_EQ(s.checks[0].expected, 12.5);
  EXPECT_DOUBLE_EQ(s.checks[0].tolerance, 0.001);
  EXPECT_EQ(s.checks[0].deck_line, 64);
  EXPECT_EQ(s.checks[1].kind, "energy_no_growth");
  EXPECT_TRUE(s.checks[1].block.empty());
  EXPECT_TRUE(std::isnan(s.checks[1].expected));
  EXPECT_DOUBLE_EQ(s.checks[1].tolerance, 0.01);
}

TEST(Deck, MinimalDeckTakesDefaults) {
  const SceneSpec s = parse_deck(deck(R"(
[[block]]
shape = "box"
size = [1, 1, 1]
)"),
                                 "min.toml");
  const SimulationSpec sim;
  EXPECT_DOUBLE_EQ(s.simulation.end_time, sim.end_time);
  EXPECT_DOUBLE_EQ(s.simulation.safety_factor, sim.safety_factor);
  EXPECT_EQ(s.simulation.gravity, sim.gravity);
  const JointSpec joint;
  EXPECT_DOUBLE_EQ(s.joint.normal_stiffness, joint.normal_stiffness);
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, joint.shear_stiffness);
  EXPECT_DOUBLE_EQ(s.joint.friction_angle, joint.friction_angle);
  EXPECT_DOUBLE_EQ(s.joint.damping, joint.damping);
  ASSERT_EQ(s.blocks.size(), 1u);
  EXPECT_EQ(s.blocks[0].name, "block1");
  EXPECT_EQ(s.blocks[0].deck_line, 1);
  EXPECT_TRUE(mass_properties(s.blocks[0].shape).centroid.isZero(1e-14));
  EXPECT_EQ(s.ground_motion.kind, GroundMotionKind::none);
  EXPECT_TRUE(s.output.energies);
  EXPECT_TRUE(s.output.histories.empty());
  EXPECT_TRUE(s.checks.empty());
}

TEST(Deck, RotationIsRzRyRxAboutTheCentroid) {
  // A thin box along x, rotated 90° about x (no effect on its x extent) and
  // then 90° about z: it ends up along y, centred where it was.
  const SceneSpec s = parse_deck(deck(R"(
[[block]]
shape = "box"
size = [4, 1, 0.5]
center = [1, 2, 3]
rotation = [90, 0, 90]
)"),
                                 "rot.toml");
  const auto b = bounds(s.blocks[0].shape);
  EXPECT_TRUE((b.max() - b.min()).isApprox(Vec3(0.5, 4, 1), 1e-12)) << (b.max() - b.min()).transpose();
  EXPECT_TRUE(b.center().isApprox(Vec3(1, 2, 3), 1e-12));
}

TEST(Deck, ShearStiffnessGivenExplicitly) {
  const SceneSpec s = parse_deck(deck(R"(
[joint]
normal_stiffness = 10
shear_stiffness = 7
[[block]]
shape = "box"
size = [1, 1, 1]
)"),
                                 "j.toml");
  EXPECT_DOUBLE_EQ(s.joint.shear_stiffness, 7);
}

TEST(Deck, GroundMotionKindsAndUnits) {
  const std::string blocks = deck(R"(
[[block]]
shape = "box"
size = [1, 1, 1]
)");
  auto gm = [&](const std::string& section) { return parse_deck(blocks + section, "g.toml").ground_motion; };
  EXPECT_DOUBLE_EQ(gm("[ground_motion]\nkind = \"constant\"\nacceleration = 2\n").acceleration, 2.0);
  EXPECT_DOUBLE_EQ(gm("[ground_motion]\nkind = \"ramp\"\nrate_g = 0.1\n").rate, 0.1 * 9.81);
  EXPECT_DOUBLE_EQ(gm("[ground_motion]\nkind = \"ramp\"\nrate = 3\n").rate, 3.0);
  EXPECT_EQ(gm("[ground_motion]\nkind = \"none\"\n").kind, GroundMotionKind::none);
}

TEST(Deck, RecordPathIsRelativeToTheDeck) {
  const auto dir = std::filesystem::temp_directory_path() / "polydem_deck_test";
  std::filesystem::create_directories(dir / "records");
  { std::ofstream(dir / "records" / "quake.csv") << "# units: g\n0 0\n0.01 0.1\n"; }
  const std::string text = deck(R"(
[[block]]
shape = "box"
size = [1, 1, 1]
[ground_motion]
kind = "record"
record = "records/quake.csv"
scale = 2
)");
  { std::ofstream(dir / "deck.toml") << text; }
  const SceneSpec s = read_deck((dir / "deck.toml").string());
  EXPECT_EQ(s.ground_motion.kind, GroundMotionKind::record);
  EXPECT_TRUE(std::filesystem::equivalent(s.ground_motion.record_path, dir / "records" / "quake.csv"));
  EXPECT_DOUBLE_EQ(s.ground_motion.scale, 2);
  EXPECT_EQ(s.deck_text, text);
  EXPECT_EQ(s.deck_path, (dir / "deck.toml").string());

  // Not found next to a deck elsewhere.
  expect_error(text, 6, "ground_motion.record", "file not found");
  std::filesystem::remove_all(dir);
}

TEST(Deck, MissingFileIsADeckError) {
  try {
    read_deck("/nonexistent/deck.toml");
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/deck.toml"), std::string::npos);
  }
}

// ------------------------------------------------------------------ overrides

const std::string kTwoBlocks = deck(R"(
[simulation]
end_time = 1

[[block]]
name = "a"
shape = "box"
size = [1, 1, 1]

[[block]]
name = "b"
shape = "box"
size = [1, 1, 1]
center = [0, 0, 1]
)");

TEST(Deck, OverridesReplaceValuesBeforeValidation) {
  const SceneSpec s = parse_deck(kTwoBlocks, "o.toml",
                                 {"simulation.end_time=2", "joint.friction_angle=35", "block[1].density=2000",
                                  "block.2.density = 1500", "simulation.gravity=[0, 0, -1.62]",
                                  "ground_motion.kind=sine_pulse", "ground_motion.acceleration_g=0.2", "ground_motion.period=0.3",
                                  "block[2].name=\"top\"", "output.histories=[\"top.velocity\"]",
                                  "simulation.gravity[1]=0.5"});
  EXPECT_DOUBLE_EQ(s.simulation.end_time, 2);
  EXPECT_DOUBLE_EQ(s.joint.friction_angle, 35);  // [joint] created by the override
  EXPECT_DOUBLE_EQ(s.blocks[0].density, 2000);
  EXPECT_DOUBLE_EQ(s.blocks[1].density, 1500);
  EXPECT_EQ(s.blocks[1].name, "top");
  EXPECT_EQ(s.simulation.gravity, Vec3(0.5, 0, -1.62));
  EXPECT_EQ(s.ground_motion.kind, GroundMotionKind::sine_pulse);  // bare word read as a string
  EXPECT_DOUBLE_EQ(s.ground_motion.acceleration, 0.2 * 9.81);
  ASSERT_EQ(s.output.histories.size(), 1u);
  EXPECT_EQ(s.output.histories[0].block, "top");
  EXPECT_EQ(s.deck_text, kTwoBlocks);  // the deck text stays verbatim
}

TEST(Deck, OverrideErrorsNameTheOverride) {
  expect_override_error(kTwoBlocks, {"block[1].density=-5"}, "key 'block[1].density'", "must be > 0 (got -5)");
  expect_override_error(kTwoBlocks, {"block.2.density=heavy"}, "key 'block[2].density'", "must be a number");
  expect_override_error(kTwoBlocks, {"simulation.end_tim=3"}, "key 'simulation.end_tim'", "unknown key");
  expect_override_error(kTwoBlocks, {"block[3].density=1"}, "key 'block[3]'", "no such element");
  expect_override_error(kTwoBlocks, {"block.density=1"}, "key 'block' is an array of tables", "'block[1].density' for the first");
  expect_override_error(kTwoBlocks + "[[joint]]\nfriction_angle = 30\n", {"joint.friction_angle=35"}, "key 'joint' is an array of tables",
                        "joint[1].friction_angle' for the first (the default joint");
  expect_override_error(kTwoBlocks, {"block[0].density=1"}, "'block[0].density'", "1-based");
  expect_override_error(kTwoBlocks, {"simulation.end_time"}, "'simulation.end_time'", "expected key.path=value");
  expect_override_error(kTwoBlocks, {"simulation.end_time.x=1"}, "key 'simulation.end_time'", "is not a table");
  expect_override_error(kTwoBlocks, {"ground_motion.kind=sine_pulse"}, "key 'ground_motion.acceleration'",
                        "needs acceleration");
  expect_override_error(kTwoBlocks, {"block[2].name=a"}, "key 'block[2].name'", "duplicate block name \"a\"");
}

// ----------------------------------------------------------------- bad decks

const std::string kBox = "shape = \"box\"\nsize = [1, 1, 1]\n";

TEST(DeckErrors, SyntaxError) {
  try {
    parse_deck("[simulation]\nend_time = = 2\n", kFile);
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(kFile + ":2: ", 0), 0u) << e.what();
  }
}

TEST(DeckErrors, UnknownKeysAndSections) {
  expect_error("[simulation]\nend_time = 1\nendtime = 2\n[[block]]\n" + kBox, 3, "simulation.endtime",
               "unknown key");
  expect_error("[[block]]\n" + kBox + "densty = 3\n", 4, "block[1].densty", "unknown key");
  expect_error("[[block]]\n" + kBox + "[solver]\nx = 1\n", 4, "solver", "unknown section");
  expect_error("end_time = 1\n[[block]]\n" + kBox, 1, "end_time", "unknown section");
  expect_error("[[block]]\n" + kBox + "polygon = [[0, 0], [1, 0], [0, 1]]\n", 4, "block[1].polygon",
               "not used by shape \"box\"");
}

TEST(DeckErrors, WrongTypes) {
  expect_error("[simulation]\nend_time = \"long\"\n[[block]]\n" + kBox, 2, "simulation.end_time",
               "must be a number (got string \"long\")");
  expect_error("[simulation]\nthreads = 2.5\n[[block]]\n" + kBox, 2, "simulation.threads", "must be an integer");
  expect_error("[simulation]\ngravity = [0, 0]\n[[block]]\n" + kBox, 2, "simulation.gravity",
               "array of 3 numbers");
  expect_error("[simulation]\ngravity = [0,\n 'x',\n -9.81]\n[[block]]\n" + kBox, 3, "simulation.gravity[2]",
               "must be a number");
  expect_error("[output]\nenergies = 1\n[[block]]\n" + kBox, 2, "output.energies", "true or false");
  expect_error("simulation = 3\n[[block]]\n" + kBox, 1, "simulation", "must be a table");
  expect_error("[block]\n" + kBox, 1, "block", "[[block]]");
  expect_error("[simulation]\nend_time = inf\n[[block]]\n" + kBox, 2, "simulation.end_time", "finite");
}

TEST(DeckErrors, ValuesOutOfRange) {
  expect_error("[[block]]\n" + kBox + "\n[[block]]\n" + kBox + "density = -5\n", 8, "block[2].density",
               "must be > 0 (got -5)");
  expect_error("[simulation]\nend_time = 0\n[[block]]\n" + kBox, 2, "simulation.end_time", "must be > 0");
  expect_error("[simulation]\ntime_step = -1e-6\n[[block]]\n" + kBox, 2, "simulation.time_step", "must be >= 0");
  expect_error("[simulation]\nsafety_factor = 1.5\n[[block]]\n" + kBox, 2, "simulation.safety_factor",
               "(0, 1]");
  expect_error("[joint]\nnormal_stiffness = 0\n[[block]]\n" + kBox, 2, "joint.normal_stiffness", "must be > 0");
  expect_error("[joint]\nshear_stiffness = -1\n[[block]]\n" + kBox, 2, "joint.shear_stiffness", "must be > 0");
  expect_error("[joint]\nfriction_angle = 90\n[[block]]\n" + kBox, 2, "joint.friction_angle", "[0, 90)");
  expect_error("[joint]\nfriction_angle = -1\n[[block]]\n" + kBox, 2, "joint.friction_angle", ">= 0");
  expect_error("[joint]\ncohesion = -1\n[[block]]\n" + kBox, 2, "joint.cohesion", ">= 0");
  expect_error("[joint]\ntensile_strength = -1\n[[block]]\n" + kBox, 2, "joint.tensile_strength", ">= 0");
  expect_error("[joint]\ndamping = -1\n[[block]]\n" + kBox, 2, "joint.damping", ">= 0");
  expect_error("[[block]]\nshape = \"box\"\nsize = [1, 0, 1]\n", 3, "block[1].size", "must be > 0");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"sine_pulse\"\nacceleration = 1\nperiod = 0\n", 7,
               "ground_motion.period", "must be > 0");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\ndirection = [0, 0, 0]\n", 5, "ground_motion.direction",
               "zero");
  expect_error("[[block]]\n" + kBox + "course = -2\n", 4, "block[1].course", "must be in");
  expect_error("[[block]]\n" + kBox + "group = \"\"\n", 4, "block[1].group", "must not be empty");
}

// The overlap joint model carries compression and friction only, under the
// explicit damping scheme: a deck asking for more is refused where it asks.
TEST(DeckErrors, TheOverlapModelRefusesBondsAndTheSplitScheme) {
  expect_error("[simulation]\njoint_model = \"sampled\"\n[[block]]\n" + kBox, 2, "simulation.joint_model",
               "must be one of \"subcontacts\", \"overlap\" (got \"sampled\")");
  expect_error("[simulation]\njoint_model = \"overlap\"\ndamping_scheme = \"split\"\n[[block]]\n" + kBox, 2,
               "simulation.joint_model", "works with damping_scheme = \"explicit\" only");
  expect_error("[simulation]\njoint_model = \"overlap\"\n[joint]\ncohesion = 1e5\n[[block]]\n" + kBox, 3, "joint",
               "cohesion or tensile strength is not modelled");
  expect_error("[joint]\ntensile_strength = 1e5\n[[block]]\n" + kBox, 1, "joint",
               "cohesion or tensile strength is not modelled", {"simulation.joint_model=\"overlap\""});
  EXPECT_NO_THROW(parse_deck("[simulation]\njoint_model = \"overlap\"\n[[block]]\n" + kBox, kFile));
  // Its joints have no points to move.
  expect_error("[simulation]\njoint_model = \"overlap\"\njoint_sampling = \"step\"\n[[block]]\n" + kBox, 3,
               "simulation.joint_sampling", "it needs joint_model = \"subcontacts\"");
  expect_error("[simulation]\njoint_model = \"overlap\"\njoint_sampling = \"clip\"\n[[block]]\n" + kBox, 3,
               "simulation.joint_sampling", "\"clip\" moves subcontacts: it needs joint_model = \"subcontacts\"");
  expect_error("[simulation]\njoint_sampling = \"always\"\n[[block]]\n" + kBox, 2, "simulation.joint_sampling",
               "must be one of \"automatic\", \"detection\", \"step\", \"clip\" (got \"always\")");
  EXPECT_NO_THROW(parse_deck("[simulation]\njoint_sampling = \"step\"\n[[block]]\n" + kBox, kFile));
  // The clipped joints are re-sampled pair by pair when their vertices change.
  expect_error("[simulation]\ndetection_trigger = \"scene\"\njoint_sampling = \"clip\"\n[[block]]\n" + kBox, 3,
               "simulation.joint_sampling", "it needs detection_trigger = \"pair\"");
  EXPECT_NO_THROW(parse_deck("[simulation]\njoint_sampling = \"clip\"\n[[block]]\n" + kBox, kFile));
  // Bonded joints are clipped too.
  EXPECT_NO_THROW(parse_deck("[simulation]\njoint_sampling = \"clip\"\n[joint]\ncohesion = 1e5\n[[block]]\n" + kBox, kFile));
  // "automatic": clipped pair by pair, re-sampled at detection scene-wide.
  const auto sampling = [&](const std::string& sim) {
    return joint_sampling_of(parse_deck("[simulation]\n" + sim + "[[block]]\n" + kBox, kFile).simulation);
  };
  EXPECT_EQ(sampling(""), JointSampling::clip);
  EXPECT_EQ(sampling("detection_trigger = \"scene\"\n"), JointSampling::detection);
  EXPECT_EQ(sampling("joint_model = \"overlap\"\n"), JointSampling::detection);
  EXPECT_EQ(sampling("joint_sampling = \"detection\"\n"), JointSampling::detection);
}

TEST(DeckErrors, BadEnumsListTheAllowedValues) {
  expect_error("[simulation]\ntime_step_bound = \"exact\"\n[[block]]\n" + kBox, 2, "simulation.time_step_bound",
               "must be one of \"block\", \"joint\" (got \"exact\")");
  expect_error("[simulation]\ndamping_scheme = \"implicit\"\n[[block]]\n" + kBox, 2, "simulation.damping_scheme",
               "must be one of \"explicit\", \"split\" (got \"implicit\")");
  expect_error("[joint]\nfriction_normal_force = \"viscous\"\n[[block]]\n" + kBox, 2, "joint.friction_normal_force",
               "must be one of \"elastic\", \"total\" (got \"viscous\")");
  expect_error("[simulation]\ndamping_scheme = \"split\"\n[joint]\nfriction_normal_force = \"total\"\n[[block]]\n" + kBox,
               3, "joint", "works with simulation.damping_scheme = \"explicit\" only");
  expect_error("[[block]]\n" + kBox + "motion = \"flee\"\n", 4, "block[1].motion",
               "must be one of \"free\", \"fixed\", \"kinematic\" (got \"flee\")");
  expect_error("[[block]]\nshape = \"sphere\"\n", 2, "block[1].shape", "\"box\", \"prism\", \"hull\"");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"earthquake\"\n", 5, "ground_motion.kind",
               "\"sine_pulse\", \"record\"");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\napplied_as = \"force\"\n", 5, "ground_motion.applied_as",
               "\"body_force\", \"kinematic\"");
  expect_error("[[block]]\n" + kBox + "[[check]]\nkind = \"wobble\"\n", 5, "check[1].kind", "\"rocking_onset\"");
  expect_error("[[block]]\n" + kBox + "[output]\nhistories = [\"block1.position\", \"block1.spin\"]\n", 5,
               "output.histories[2]", "quantity must be one of");
}

TEST(DeckErrors, NamesAndReferences) {
  expect_error("[[block]]\nname = \"a\"\n" + kBox + "\n[[block]]\nname = \"a\"\n" + kBox, 7, "block[2].name",
               "duplicate block name \"a\"");
  // A default name can collide too.
  expect_error("[[block]]\nname = \"block2\"\n" + kBox + "[[block]]\n" + kBox, 5, "block[2].name",
               "duplicate block name \"block2\"");
  expect_error("[[block]]\n" + kBox + "[output]\nhistories = [\"ghost.position\"]\n", 5, "output.histories[1]",
               "no block named \"ghost\"");
  expect_error("[[block]]\n" + kBox + "[output]\nhistories = [\"position\"]\n", 5, "output.histories[1]",
               "BLOCK.QUANTITY");
  expect_error("[[block]]\n" + kBox + "[[check]]\nkind = \"stick\"\nblock = \"ghost\"\n", 6, "check[1].block",
               "no block named \"ghost\"");
  expect_error("[[block]]\n" + kBox + "[[check]]\nkind = \"stick\"\ntolerance = 0\n", 6, "check[1].tolerance",
               "must be > 0");
}

TEST(DeckErrors, MissingRequiredKeys) {
  expect_error("[simulation]\nend_time = 1\n", 1, "block", "at least one [[block]]");
  expect_error("[[block]]\nname = \"x\"\n", 1, "block[1].shape", "missing");
  expect_error("[[block]]\n" + kBox + "\n[[block]]\nshape = \"box\"\n", 5, "block[2].size", "missing");
  expect_error("[[block]]\nshape = \"prism\"\npolygon = [[0, 0], [1, 0], [0, 1]]\n", 1, "block[1].z", "missing");
  expect_error("[[block]]\nshape = \"hull\"\n", 1, "block[1].vertices", "missing");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"sine_pulse\"\nperiod = 1\n", 4,
               "ground_motion.acceleration", "needs acceleration");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.1\n", 4,
               "ground_motion.period", "needs period");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"ramp\"\n", 4, "ground_motion.rate", "needs rate");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"record\"\n", 4, "ground_motion.record",
               "needs record");
  expect_error("[[block]]\n" + kBox + "[[check]]\nblock = \"block1\"\n", 4, "check[1].kind", "missing");
}

TEST(DeckErrors, BothAccelerationAndAccelerationG) {
  expect_error("[[block]]\n" + kBox +
                   "[ground_motion]\nkind = \"constant\"\nacceleration = 1\nacceleration_g = 0.1\n",
               7, "ground_motion.acceleration_g", "not both");
  expect_error("[[block]]\n" + kBox + "[ground_motion]\nkind = \"ramp\"\nrate = 1\nrate_g = 0.1\n", 7,
               "ground_motion.rate_g", "not both");
}

TEST(DeckErrors, GeometryErrorsNameTheBlockKey) {
  // A point inside the hull of the others: the listed polyhedron is not convex.
  expect_error(deck(R"(
[[block]]
name = "ok"
shape = "box"
size = [1, 1, 1]

[[block]]
shape = "hull"
vertices = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2], [0.2, 0.2, 0.2]]
)"),
               8, "block[2].vertices", "not convex: vertex 5");
  // Coplanar points: the generator's GeometryError, rethrown with the key.
  expect_error("[[block]]\nshape = \"hull\"\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]\n", 3,
               "block[1].vertices", "invalid hull");
  // Repeated polygon point: make_prism rejects it.
  expect_error("[[block]]\nshape = \"prism\"\npolygon = [[0, 0], [1, 0], [1, 0], [0, 1]]\nz = [0, 1]\n", 3,
               "block[1].polygon", "invalid prism");
  // Non-convex polygon.
  expect_error("[[block]]\nshape = \"prism\"\npolygon = [[0, 0], [2, 0], [1, 0.2], [2, 2], [0, 2]]\nz = [0, 1]\n",
               3, "block[1].polygon", "invalid prism");
  expect_error("[[block]]\nshape = \"prism\"\npolygon = [[0, 0], [1, 0], [0, 1]]\nz = [1, 1]\n", 4, "block[1].z",
               "z1 > z0");
}

// --------------------------------------------------------- reference (docs)

// Keys listed in docs/deck.md: rows "| `key` |" of the tables under
// headings "## `[section]`" or "## `[[section]]`".
std::set<std::string> documented_keys(std::string* example) {
  std::ifstream in(std::string(POLYDEM_SOURCE_DIR) + "/docs/deck.md");
  EXPECT_TRUE(in) << "cannot open docs/deck.md";
  std::set<std::string> keys;
  std::string section, line;
  bool in_example = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) {
      section.clear();
      std::string h = line.substr(3);
      if (h.size() > 4 && h.front() == '`' && h.back() == '`') {
        h = h.substr(1, h.size() - 2);
        while (!h.empty() && h.front() == '[') h.erase(0, 1);
        while (!h.empty() && h.back() == ']') h.pop_back();
        section = h;
      }
      continue;
    }
    if (line.rfind("```toml", 0) == 0) {
      in_example = true;
      continue;
    }
    if (in_example) {
      if (line.rfind("```", 0) == 0)
        in_example = false;
      else if (example)
        *example += line + "\n";
      continue;
    }
    if (!section.empty() && line.rfind("| `", 0) == 0) {
      const auto end = line.find('`', 3);
      if (end != std::string::npos) keys.insert(section + "." + line.substr(3, end - 3));
    }
  }
  return keys;
}

TEST(DeckReference, DocsListExactlyTheAcceptedKeys) {
  const std::set<std::string> documented = documented_keys(nullptr);
  const std::vector<std::string> accepted_list = deck_keys();
  const std::set<std::string> accepted(accepted_list.begin(), accepted_list.end());
  EXPECT_EQ(accepted.size(), accepted_list.size()) << "deck_keys() has duplicates";
  for (const auto& k : accepted) EXPECT_TRUE(documented.count(k)) << "accepted but not in docs/deck.md: " << k;
  for (const auto& k : documented) EXPECT_TRUE(accepted.count(k)) << "in docs/deck.md but not accepted: " << k;
  EXPECT_GT(documented.size(), 40u);
}

TEST(DeckReference, DocsExampleIsAValidDeck) {
  std::string example;
  documented_keys(&example);
  ASSERT_FALSE(example.empty());
  const SceneSpec s = parse_deck(example, "docs/deck.md");
  EXPECT_EQ(s.blocks.size(), 3u);
  EXPECT_EQ(s.ground_motion.kind, GroundMotionKind::sine_pulse);
}

}  // namespace
}  // namespace polydem
