// The deck's groups, joint laws by pair of groups, loads, prescribed motions
// and ground-motion components: good decks land in the structs, bad ones
// are rejected with file, line and key (issue 13).
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <string>

namespace polydem {
namespace {

const std::string kFile = "decks/groups.toml";

// Two blocks: "base" (group "base", fixed) and "stone" (group "stone"),
// lines 1-12.
const std::string kBlocks = R"([[block]]
name = "base"
shape = "box"
size = [2, 2, 0.5]
center = [0, 0, -0.25]
motion = "fixed"
group = "base"
[[block]]
name = "stone"
shape = "box"
size = [1, 1, 1]
group = "stone"
)";

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

TEST(DeckJoints, TheTableFormIsTheOneLawAsBefore) {
  const SceneSpec s = parse_deck(kBlocks + "[joint]\nfriction_angle = 35\nnormal_stiffness = 50e9\n", kFile);
  EXPECT_TRUE(s.joint_pairs.empty());
  EXPECT_EQ(s.joint.friction_angle, 35.0);
  EXPECT_EQ(s.joint.shear_stiffness, 0.4 * 50e9);
}

TEST(DeckJoints, PairsInheritTheDefaultsKeys) {
  const SceneSpec s = parse_deck(kBlocks + R"([[joint]]
between = ["stone", "base"]
friction_angle = 30
cohesion = 0
[[joint]]
friction_angle = 40
cohesion = 1e5
tensile_strength = 5e4
normal_stiffness = 50e9
[[joint]]
between = ["stone", "stone"]
normal_stiffness = 20e9
)",
                                 kFile);
  EXPECT_EQ(s.joint.friction_angle, 40.0);
  EXPECT_EQ(s.joint.cohesion, 1e5);
  ASSERT_EQ(s.joint_pairs.size(), 2u);
  const JointPairSpec& dry = s.joint_pairs[0];
  EXPECT_EQ(dry.group_a, "stone");
  EXPECT_EQ(dry.group_b, "base");
  EXPECT_EQ(dry.deck_line, 13);
  EXPECT_EQ(dry.joint.friction_angle, 30.0);
  EXPECT_EQ(dry.joint.cohesion, 0.0);
  EXPECT_EQ(dry.joint.tensile_strength, 5e4);           // the default's
  EXPECT_EQ(dry.joint.normal_stiffness, 50e9);          // the default's
  EXPECT_EQ(dry.joint.shear_stiffness, 0.4 * 50e9);     // the default's
  const JointPairSpec& inner = s.joint_pairs[1];
  EXPECT_EQ(inner.joint.normal_stiffness, 20e9);
  EXPECT_EQ(inner.joint.shear_stiffness, 0.4 * 20e9);   // follows its own kn
  EXPECT_EQ(inner.joint.friction_angle, 40.0);
}

TEST(DeckJoints, BadPairsAreRejectedWithLineAndKey) {
  expect_error(kBlocks + "[joint]\nbetween = [\"base\", \"stone\"]\n", 14, "joint.between", "belongs to a [[joint]]");
  expect_error(kBlocks + "[[joint]]\nfriction_angle = 30\n[[joint]]\ndamping = 0\n", 15, "joint[2]",
               "a second [[joint]] without `between`");
  expect_error(kBlocks + "[[joint]]\nbetween = \"base\"\n", 14, "joint[1].between", "must be a pair of group names");
  expect_error(kBlocks + "[[joint]]\nbetween = [\"base\", \"mortar\"]\n", 14, "joint[1].between",
               "no block is in group \"mortar\"");
  expect_error(kBlocks + "[[joint]]\nbetween = [\"base\", \"stone\"]\n[[joint]]\nbetween = [\"stone\", \"base\"]\n", 16,
               "joint[2].between", "already has a law");
  expect_error(kBlocks + "[[joint]]\nbetween = [\"base\", \"stone\"]\nfriction_angle = 95\n", 15,
               "joint[1].friction_angle", "must be in [0, 90)");
  expect_error(kBlocks + "[[joint]]\nbetween = [\"base\", \"stone\"]\nfriction = 30\n", 15, "joint[1].friction",
               "unknown key");
}

TEST(DeckGroups, DensityAndBadGroups) {
  const SceneSpec s = parse_deck(kBlocks + "[[group]]\nname = \"stone\"\ndensity = 1800\n", kFile);
  EXPECT_EQ(s.blocks[1].density, 1800.0);
  EXPECT_EQ(s.blocks[0].density, 2600.0);
  expect_error(kBlocks + "[[group]]\nname = \"mortar\"\n", 14, "group[1].name", "no block is in group");
  expect_error(kBlocks + "[[group]]\ndensity = 1800\n", 13, "group[1].name", "missing");
  expect_error(kBlocks + "[[group]]\nname = \"stone\"\ndensity = 0\n", 15, "group[1].density", "must be > 0");
  expect_error(kBlocks + "[[group]]\nname = \"stone\"\n[[group]]\nname = \"stone\"\n", 16, "group[2].name",
               "already has a [[group]]");
}

TEST(DeckLoads, LoadsAndTheirErrors) {
  const SceneSpec s = parse_deck(kBlocks + R"([[load]]
groups = ["stone"]
force = [100, 0, 0]
point = [0, 0, 0.5]
table = [[0, 0], [1, 1]]
)",
                                 kFile);
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].force, Vec3(100, 0, 0));
  EXPECT_TRUE(s.loads[0].at_point);
  EXPECT_EQ(s.loads[0].factor.time, (std::vector<double>{0, 1}));
  expect_error(kBlocks + "[[load]]\nforce = [1, 0, 0]\n", 13, "load[1].blocks", "select the blocks");
  expect_error(kBlocks + "[[load]]\nblocks = [\"stone\"]\n", 13, "load[1].force", "needs force");
  expect_error(kBlocks + "[[load]]\nblocks = [\"rock\"]\nforce = [1, 0, 0]\n", 14, "load[1].blocks",
               "no block named \"rock\"");
  expect_error(kBlocks + "[[load]]\ngroups = [\"rock\"]\nforce = [1, 0, 0]\n", 14, "load[1].groups",
               "no block is in group \"rock\"");
  expect_error(kBlocks + "[[load]]\nblocks = [\"stone\"]\nforce = [1, 0, 0]\ntable = [[0, 1], [0, 2]]\n", 16,
               "load[1].table", "times must increase");
  expect_error(kBlocks + "[[load]]\nblocks = [\"stone\"]\nforce = [1, 0, 0]\ntable = [[0, 1, 2]]\n", 16,
               "load[1].table[1]", "must be an array of 2 numbers");
}

TEST(DeckPrescribe, PrescriptionsAndTheirErrors) {
  const SceneSpec s = parse_deck(kBlocks + "[[prescribe]]\nblocks = [\"base\"]\ntable = [[0, 0, 0, 0], [1, 0.1, 0, 0]]\n",
                                 kFile);
  ASSERT_EQ(s.prescribed.size(), 1u);
  EXPECT_EQ(s.prescribed[0].velocity_table.value[1], Vec3(0.1, 0, 0));
  expect_error(kBlocks + "[[prescribe]]\nblocks = [\"base\"]\nvelocity = [1, 0, 0]\ntable = [[0, 1, 0, 0]]\n", 16,
               "prescribe[1].table", "not both");
  expect_error(kBlocks + "[[prescribe]]\nvelocity = [1, 0, 0]\n", 13, "prescribe[1].blocks", "select the blocks");
  expect_error(kBlocks + "[[prescribe]]\nblocks = [\"base\"]\ndisplacement_table = [[0, 0.1, 0, 0], [1, 0.2, 0, 0]]\n",
               15, "prescribe[1].displacement_table", "must be zero");
  expect_error(kBlocks + "[[prescribe]]\nblocks = [\"base\"]\nvelocity = [1, 0, 0]\n"
                         "displacement_table = [[0, 0, 0, 0], [1, 0.2, 0, 0]]\n",
               16, "prescribe[1].displacement_table", "not two");
}

TEST(DeckGroupHistories, GroupHistoriesAndMonitorGroup) {
  const SceneSpec s = parse_deck(kBlocks + "[output]\nhistories = [\"group:stone.position\"]\n"
                                           "[assessment]\nmonitor_group = \"stone\"\n",
                                 kFile);
  ASSERT_EQ(s.output.histories.size(), 1u);
  EXPECT_EQ(s.output.histories[0].block, "group:stone");
  EXPECT_EQ(s.assessment.monitor_group, "stone");
  expect_error(kBlocks + "[output]\nhistories = [\"group:rock.position\"]\n", 14, "output.histories[1]",
               "no block is in group \"rock\"");
  expect_error(kBlocks + "[output]\nhistories = [\"group:stone.rotation\"]\n", 14, "output.histories[1]",
               "a group's quantity must be one of");
  expect_error(kBlocks + "[assessment]\nmonitor_group = \"base\"\n", 14, "assessment.monitor_group",
               "no free block is in group \"base\"");
  expect_error(kBlocks + "[assessment]\nmonitor_block = \"stone\"\nmonitor_group = \"stone\"\n", 15,
               "assessment.monitor_group", "not both");
}

TEST(DeckGroundMotionComponents, ComponentsAndTheirErrors) {
  const SceneSpec s = parse_deck(kBlocks + R"([ground_motion]
kind = "sine_pulse"
acceleration_g = 0.2
period = 0.5
[[ground_motion.component]]
kind = "constant"
direction = [0, 0, 2]
acceleration = 1.5
start_time = 0.25
)",
                                 kFile);
  ASSERT_EQ(s.ground_motion.components.size(), 1u);
  const GroundMotionSpec& c = s.ground_motion.components[0];
  EXPECT_EQ(c.kind, GroundMotionKind::constant);
  EXPECT_EQ(c.direction, Vec3(0, 0, 1));
  EXPECT_EQ(c.acceleration, 1.5);
  EXPECT_EQ(c.start_time, 0.25);
  expect_error(kBlocks + "[ground_motion]\n[[ground_motion.component]]\nacceleration = 1\n", 14,
               "ground_motion.component[1].kind", "every component needs kind");
  expect_error(kBlocks + "[ground_motion]\n[[ground_motion.component]]\nkind = \"constant\"\n", 14,
               "ground_motion.component[1].acceleration", "needs acceleration");
  expect_error(kBlocks + "[[ground_motion.component]]\nkind = \"record\"\nrecord = \"nowhere.AT2\"\n", 15,
               "ground_motion.component[1].record", "file not found");
  expect_error(kBlocks + "[[ground_motion.component]]\nkind = \"constant\"\nacceleration = 1\ntower_frequency = 2\n",
               16, "ground_motion.component[1].tower_frequency", "unknown key");
}

}  // namespace
}  // namespace polydem
