// Groups, joint laws by pair of groups, densities by group, point loads and
// prescribed motions, each against an exact or analytical result (issue 13).
#include "core/loads.hpp"
#include "io/deck.hpp"
#include "io/summary.hpp"
#include "run/run_scene.hpp"

#include "restart_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <filesystem>
#include <numbers>
#include <string>

namespace polydem {
namespace {

// The column `name` of a history table at row k.
double at(const HistoryTable& t, const std::string& name, std::size_t k) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == name) return t.rows[k * t.columns.size() + c];
  ADD_FAILURE() << "no history column " << name;
  return std::nan("");
}

// d(column)/dt between rows a and b.
double rate(const HistoryTable& t, const std::string& name, std::size_t a, std::size_t b) {
  return (at(t, name, b) - at(t, name, a)) / (at(t, "time", b) - at(t, "time", a));
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// ------------------------------------------------------------ groups

TEST(Groups, BlocksCarryTheirGroupIndexAndTheNames) {
  const SceneSpec s = parse_deck(R"(
[[block]]
name = "a"
shape = "box"
size = [1, 1, 1]
group = "upper"
[[block]]
name = "b"
shape = "box"
size = [1, 1, 1]
center = [3, 0, 0]
[[block]]
name = "c"
shape = "box"
size = [1, 1, 1]
center = [6, 0, 0]
group = "lower"
[[block]]
name = "d"
shape = "box"
size = [1, 1, 1]
center = [9, 0, 0]
group = "upper"
)",
                                 "groups.toml");
  const Blocks b = build_blocks(s.blocks);
  ASSERT_EQ(b.group_names.size(), 2u);
  EXPECT_EQ(b.group_names[0], "upper");
  EXPECT_EQ(b.group_names[1], "lower");
  EXPECT_EQ(b.props.group, (std::vector<int>{0, -1, 1, 0}));
  EXPECT_EQ(b.find_group("lower"), 1);
  EXPECT_EQ(b.find_group("none"), -1);
}

// [[group]] density: every block of the group gets it; mass = ρ·V exactly.
TEST(Groups, DensityByGroupGivesMassRhoTimesVolume) {
  const SceneSpec s = parse_deck(R"(
[[block]]
name = "a"
shape = "box"
size = [1, 2, 0.5]
group = "lime"
[[block]]
name = "b"
shape = "box"
size = [1, 1, 1]
center = [3, 0, 0]
density = 2000
[[block]]
name = "c"
shape = "prism"
polygon = [[5, 0], [6, 0], [5.5, 1]]
z = [0, 0.3]
group = "lime"
[[group]]
name = "lime"
density = 1800
)",
                                 "density.toml");
  const Blocks b = build_blocks(s.blocks);
  EXPECT_EQ(b.props.mass[0], 1800.0 * 1.0);             // 1 × 2 × 0.5 m³
  EXPECT_EQ(b.props.mass[1], 2000.0 * 1.0);             // not in the group: its own density
  EXPECT_NEAR(b.props.mass[2], 1800.0 * 0.15, 1e-12);  // ½·1·1 m² × 0.3 m
  EXPECT_EQ(b.props.mass[2], 1800.0 * mass_properties(s.blocks[2].shape).volume);
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].density, 1800.0);
}

// ------------------------------------------------- joint laws by pair

// A stone on a base under gravity tilted by 35°: the default law
// (φ = 45°) holds it, the base–stone law (φ = 30°) lets it slide at
// a = g (sin θ − cos θ tan φ).
const char* kSlope = R"(
[simulation]
end_time = 0.6
gravity = [5.62678484060376, 0.0, -8.03588155447501]

[[joint]]
friction_angle = 45.0
damping = 2.1e-5

[[joint]]
between = ["base", "stone"]
friction_angle = 30.0

[[block]]
name = "base"
shape = "box"
size = [8.0, 2.0, 0.5]
center = [2.0, 0.0, -0.25]
motion = "fixed"
group = "base"

[[block]]
name = "stone"
shape = "box"
size = [1.0, 1.0, 0.5]
center = [0.0, 0.0, 0.25]
group = "stone"

[output]
history_interval = 0.05
histories = ["stone.velocity"]
)";

TEST(JointLawsByGroup, AStoneSlidesAtThePairsFrictionAngle) {
  const SceneSpec s = parse_deck(kSlope, "slope.toml");
  ASSERT_EQ(s.joint_pairs.size(), 1u);
  EXPECT_EQ(s.joint.friction_angle, 45.0);
  EXPECT_EQ(s.joint_pairs[0].joint.friction_angle, 30.0);
  EXPECT_EQ(s.joint_pairs[0].joint.normal_stiffness, s.joint.normal_stiffness);  // inherited
  const RunReport r = run_scene(s);
  const double g = std::hypot(5.62678484060376, 8.03588155447501);
  const double th = 35.0 * std::numbers::pi / 180, phi = 30.0 * std::numbers::pi / 180;
  const double expected = g * (std::sin(th) - std::cos(th) * std::tan(phi));
  // From 0.1 s (the joint has settled) to the end.
  const double a = rate(r.histories, "stone.velocity.x", 2, r.histories.row_count() - 1);
  EXPECT_NEAR(a, expected, 1e-4 * expected) << "a = " << a << ", expected " << expected;
  EXPECT_LT(r.energy_balance_error, 1e-6);
}

TEST(JointLawsByGroup, WithoutThePairTheDefaultHoldsTheStone) {
  // The same stone in another group: the default law, φ = 45° > 35°, acts.
  std::string deck = kSlope;
  replace(deck, "group = \"stone\"", "group = \"other\"");
  replace(deck, "between = [\"base\", \"stone\"]", "between = [\"base\", \"base\"]");
  const RunReport r = run_scene(parse_deck(deck, "slope.toml"));
  const std::size_t last = r.histories.row_count() - 1;
  EXPECT_LT(std::abs(at(r.histories, "stone.velocity.x", last)), 1e-5);
}

// A stack on a fixed base with a soft lower joint and a stiff upper one
// comes to rest with each joint closed by its load over its stiffness:
// w = W / (kn·A) per joint, W the weight above it.
TEST(JointLawsByGroup, AStackSettlesByEachJointsOwnStiffness) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.001

[[joint]]
normal_stiffness = 98e9
friction_angle = 30.0
damping = 2.1e-5

[[joint]]
between = ["base", "lower"]
normal_stiffness = 10e9

[[block]]
name = "base"
shape = "box"
size = [2.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"
group = "base"

[[block]]
name = "lower"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, 0.5]
group = "lower"

[[block]]
name = "upper"
shape = "box"
size = [1.0, 1.0, 0.5]
center = [0.0, 0.0, 1.25]
group = "upper"

[equilibrium]
ratio = 1e-10
)",
                                 "stack.toml");
  const RunReport r = run_scene(s);
  ASSERT_TRUE(r.equilibrium.ran);
  const double g = 9.81, A = 1.0;
  const double m_lower = 2600.0, m_upper = 1300.0;
  const double w1 = (m_lower + m_upper) * g / (10e9 * A);  // base–lower: its own law
  const double w2 = m_upper * g / (98e9 * A);              // lower–upper: the default
  const double settle_lower = 0.5 - r.final_position[1].z();
  const double settle_upper = 1.25 - r.final_position[2].z();
  EXPECT_NEAR(settle_lower, w1, 1e-6 * w1);
  EXPECT_NEAR(settle_upper - settle_lower, w2, 1e-6 * w2);
}

// ------------------------------------------------------------ loads

// A free stone on a frictionless base pushed by a constant horizontal
// force: a = F/m.
TEST(Loads, AConstantForceAcceleratesAFreeBlockAtFOverM) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.2

[joint]
friction_angle = 0.0

[[block]]
name = "base"
shape = "box"
size = [20.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "stone"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, 0.5]

[[load]]
blocks = ["stone"]
force = [5200.0, 0.0, 0.0]

[output]
history_interval = 0.01
histories = ["stone.velocity"]
)",
                                 "push.toml");
  const RunReport r = run_scene(s);
  const double a = rate(r.histories, "stone.velocity.x", 1, r.histories.row_count() - 1);
  EXPECT_NEAR(a, 5200.0 / 2600.0, 1e-9 * 2.0);
  EXPECT_LT(r.energy_balance_error, 1e-6);
  EXPECT_GT(r.energy.load_work, 0.0);
}

// A moment about a principal axis spins a free block at dω/dt = M/I.
TEST(Loads, AMomentSpinsAFreeBlockAtMOverI) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.1
gravity = [0, 0, 0]

[[block]]
name = "stone"
shape = "box"
size = [2.0, 1.0, 0.5]
group = "g"

[[load]]
groups = ["g"]
moment = [0.0, 0.0, 300.0]

[output]
history_interval = 0.01
histories = ["stone.angular_velocity"]
)",
                                 "spin.toml");
  const RunReport r = run_scene(s);
  const double m = 2600.0 * 1.0;
  const double Iz = m * (2.0 * 2.0 + 1.0 * 1.0) / 12.0;
  const double alpha = rate(r.histories, "stone.angular_velocity.z", 1, r.histories.row_count() - 1);
  EXPECT_NEAR(alpha, 300.0 / Iz, 1e-9 * 300.0 / Iz);
  EXPECT_LT(r.energy_balance_error, 1e-6);
}

// A force at a point off the centroid also turns the block: torque r×F.
TEST(Loads, AForceAtAPointAddsItsMoment) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.01
gravity = [0, 0, 0]

[[block]]
name = "stone"
shape = "box"
size = [2.0, 1.0, 0.5]

[[load]]
blocks = ["stone"]
force = [0.0, 100.0, 0.0]
point = [1.0, 0.0, 0.0]
table = [[0.0, 1.0], [1.0, 1.0]]

[output]
histories = ["stone.angular_velocity", "stone.velocity"]
)",
                                 "point.toml");
  const RunReport r = run_scene(s);
  const double m = 2600.0, Iz = m * 5.0 / 12.0;
  const std::size_t last = r.histories.row_count() - 1;
  EXPECT_NEAR(rate(r.histories, "stone.velocity.y", 1, last), 100.0 / m, 1e-6 * 100.0 / m);
  // The arm turns with the block (a small angle here: 1e-4 rad), so 1e-6.
  EXPECT_NEAR(rate(r.histories, "stone.angular_velocity.z", 1, last), 100.0 / Iz, 1e-6 * 100.0 / Iz);
}

TEST(Loads, ATableIsPiecewiseLinearAndConstantBeyondItsEnds) {
  TimeTable t;
  t.time = {0.0, 1.0, 3.0};
  t.value = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(-2, 0, 0)};
  EXPECT_EQ(table_value(t, -1.0).x(), 0.0);
  EXPECT_EQ(table_value(t, 0.5).x(), 1.0);
  EXPECT_EQ(table_value(t, 1.0).x(), 2.0);
  EXPECT_EQ(table_value(t, 2.0).x(), 0.0);
  EXPECT_EQ(table_value(t, 5.0).x(), -2.0);
  EXPECT_EQ(table_value(TimeTable{}, 7.0).x(), 1.0);
}

// A kinematic pusher whose velocity rises linearly (a table: v = 4 m/s² · t)
// pushes a free block in space through their joint: once the start's
// ringing has died away, the block accelerates with the pusher and the
// joint carries m·a; the ledger (the pusher's work through the joint)
// balances.
TEST(Prescribe, APusherAtAPrescribedVelocityCarriesTheBlockAlong) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.3
gravity = [0, 0, 0]

[[block]]
name = "pusher"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [-0.5, 0.0, 0.0]

[[block]]
name = "stone"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.5, 0.0, 0.0]

[[prescribe]]
blocks = ["pusher"]
table = [[0.0, 0.0, 0.0, 0.0], [1.0, 4.0, 0.0, 0.0]]

[output]
history_interval = 0.01
histories = ["stone.velocity", "stone.contact_force", "pusher.velocity", "pusher.position"]
)",
                                 "pusher.toml");
  const RunReport r = run_scene(s);
  const std::size_t last = r.histories.row_count() - 1;
  const double t = at(r.histories, "time", last);
  EXPECT_NEAR(rate(r.histories, "stone.velocity.x", 10, last), 4.0, 1e-6 * 4.0);
  EXPECT_NEAR(at(r.histories, "stone.contact_force.x", last), 2600.0 * 4.0, 1e-6 * 2600.0 * 4.0);
  // The pusher's path: x = −0.5 + 2·t² (the midpoint rule is exact for a linear v).
  EXPECT_NEAR(at(r.histories, "pusher.position.x", last), -0.5 + 2.0 * t * t, 1e-12);
  EXPECT_LT(r.energy_balance_error, 1e-6);
  EXPECT_GT(r.energy.load_work, 0.0);
}

// A displacement history puts the block where it says, step by step: here
// 10 mm along x over 0.1 s, held after.
TEST(Prescribe, ADisplacementTableIsFollowedExactly) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.15
gravity = [0, 0, 0]

[[block]]
name = "jack"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.25, 0.0, 0.0]

[[prescribe]]
blocks = ["jack"]
displacement_table = [[0.0, 0.0, 0.0, 0.0], [0.1, 0.01, 0.0, 0.0]]

[output]
history_interval = 0.01
histories = ["jack.position", "jack.velocity"]
)",
                                 "jack.toml");
  const RunReport r = run_scene(s);
  EXPECT_NEAR(r.final_position[0].x(), 0.25 + 0.01, 1e-15);
  // Half way, at a record time t: x = 0.25 + 0.1·t (the position is at the force time).
  const double t = at(r.histories, "time", 5);
  EXPECT_NEAR(at(r.histories, "jack.position.x", 5), 0.25 + 0.1 * t, 1e-15);
  EXPECT_NEAR(at(r.histories, "jack.velocity.x", 5), 0.1, 1e-9);
  EXPECT_EQ(at(r.histories, "jack.velocity.x", r.histories.row_count() - 1), 0.0);
}

// A prescribed angular velocity turns the block about its centroid.
TEST(Prescribe, AnAngularVelocityTurnsTheBlock) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.5
time_step = 1e-4
gravity = [0, 0, 0]

[[block]]
name = "wheel"
shape = "box"
size = [1.0, 1.0, 1.0]

[[prescribe]]
blocks = ["wheel"]
velocity = [0.1, 0.0, 0.0]
angular_velocity = [0.0, 0.0, 2.0]
)",
                                 "wheel.toml");
  const RunReport r = run_scene(s);
  EXPECT_NEAR(r.final_position[0].x(), 0.1 * r.end_time, 1e-12);
  const Eigen::AngleAxisd turned(r.final_orientation[0] * build_blocks(s.blocks).state.orientation[0].inverse());
  EXPECT_NEAR(turned.angle(), 2.0 * r.end_time, 1e-9);
  EXPECT_NEAR(std::abs(turned.axis().z()), 1.0, 1e-12);
}

// --------------------------------------------- ground motion components

// A stone on a fixed base under the example's synthetic record along x.
std::string record_deck(const std::string& extra) {
  std::string d = R"(
[simulation]
end_time = 0.3

[[block]]
name = "base"
shape = "box"
size = [4.0, 4.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "stone"
shape = "box"
size = [0.4, 0.4, 1.2]
center = [0.0, 0.0, 0.6]

[output]
history_interval = 0.01
histories = ["stone.position", "stone.velocity", "stone.contact_force"]

[ground_motion]
kind = "record"
record = "examples/spire/synthetic_record.csv"
scale = 2000.0
direction = [1, 0, 0]
)";
  return d + extra;
}

SceneSpec parse_here(const std::string& text) {
  // The deck's directory is the source tree, so the example record is found.
  return parse_deck(text, std::string(POLYDEM_SOURCE_DIR) + "/deck.toml");
}

void expect_same_bits(const RunReport& a, const RunReport& b, bool histories = true) {
  ASSERT_EQ(a.steps, b.steps);
  ASSERT_EQ(a.final_position.size(), b.final_position.size());
  for (std::size_t i = 0; i < a.final_position.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.final_position[i][k], b.final_position[i][k]) << "block " << i;
      EXPECT_EQ(a.final_velocity[i][k], b.final_velocity[i][k]) << "block " << i;
    }
  }
  if (histories) {
    EXPECT_EQ(a.histories.rows, b.histories.rows);
  }
  EXPECT_EQ(a.energies.rows, b.energies.rows);
}

// Two further components of zero scale (the y and z records of a set with
// only x given) leave the run bitwise what the one-component run is.
TEST(GroundMotionComponents, TwoZeroComponentsGiveTheOneComponentRunsBits) {
  const RunReport one = run_scene(parse_here(record_deck("")));
  const RunReport three = run_scene(parse_here(record_deck(R"(
[[ground_motion.component]]
kind = "record"
record = "examples/spire/synthetic_record.csv"
direction = [0, 1, 0]
scale = 0.0

[[ground_motion.component]]
kind = "record"
record = "examples/spire/synthetic_record.csv"
direction = [0, 0, 1]
scale = 0.0
start_time = 0.05
)")));
  expect_same_bits(one, three);
  // And the motion did something: the stone moved.
  EXPECT_GT(std::abs(one.final_position[1].x()), 1e-6);
}

// The same record given as a component (the section's own kind "none")
// is the same run, bit for bit.
TEST(GroundMotionComponents, ARecordAsAComponentIsTheSameRun) {
  const RunReport own = run_scene(parse_here(record_deck("")));
  std::string deck = record_deck(R"(
[[ground_motion.component]]
kind = "record"
record = "examples/spire/synthetic_record.csv"
scale = 2000.0
direction = [1, 0, 0]
)");
  replace(deck, "kind = \"record\"\nrecord = \"examples/spire/synthetic_record.csv\"\nscale = 2000.0\ndirection = [1, 0, 0]\n\n",
          "kind = \"none\"\n\n");
  const SceneSpec s = parse_here(deck);
  ASSERT_EQ(s.ground_motion.kind, GroundMotionKind::none);
  ASSERT_EQ(s.ground_motion.components.size(), 1u);
  // The histories differ by one column: ground.acceleration is the
  // section's own component's, and here it has none.
  expect_same_bits(own, run_scene(s), false);
}

// A vertical component a_z on a resting stone changes its joint force by
// m·a_z: the inertial force −m·a_z of the base frame adds to the weight.
TEST(GroundMotionComponents, AVerticalComponentChangesTheRestingForceByMTimesAz) {
  const std::string base = R"(
[simulation]
end_time = 0.6

[[block]]
name = "base"
shape = "box"
size = [2.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "stone"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, 0.5]

[equilibrium]

[output]
history_interval = 0.01
histories = ["stone.contact_force"]
)";
  const double az = 0.3 * 9.81;
  const RunReport still = run_scene(parse_deck(base, "still.toml"));
  const RunReport shaken = run_scene(parse_deck(base + R"(
[ground_motion]
kind = "none"

[[ground_motion.component]]
kind = "constant"
direction = [0, 0, 1]
acceleration_g = 0.3
rise_time = 0.3
)",
                                                "shaken.toml"));
  const std::size_t last = still.histories.row_count() - 1;
  const double m = 2600.0;
  const double f0 = at(still.histories, "stone.contact_force.z", last);
  const double f1 = at(shaken.histories, "stone.contact_force.z", last);
  EXPECT_NEAR(f0, m * 9.81, 1e-6 * m * 9.81);
  EXPECT_NEAR(f1 - f0, m * az, 1e-6 * m * az) << "f1 = " << f1 << ", f0 = " << f0;
}

// The reader on a real PEER record (../shared/data): El Centro as the second
// horizontal component, its samples scaled and applied along y.
TEST(GroundMotionComponents, ReadsAPeerRecordAsAComponent) {
  const std::string at2 = std::string(POLYDEM_SHARED_DIR) + "/data/elcentro-1940-ns.AT2";
  if (!std::filesystem::exists(at2)) GTEST_SKIP() << "../shared/data is absent: " << at2;
  const SceneSpec s = parse_deck(record_deck("\n[[ground_motion.component]]\nkind = \"record\"\nrecord = \"" + at2 +
                                             "\"\ndirection = [0, 1, 0]\nscale = 0.5\nstart_time = 0.1\n"),
                                 std::string(POLYDEM_SOURCE_DIR) + "/deck.toml");
  ASSERT_EQ(s.ground_motion.components.size(), 1u);
  const GroundMotionSpec& c = s.ground_motion.components[0];
  EXPECT_EQ(c.record_time.size(), 1560u);
  const GroundMotion g = make_ground_motion(s.ground_motion, s.ground_motion.record_time,
                                            s.ground_motion.record_acceleration);
  ASSERT_EQ(g.components.size(), 1u);
  // At t = 0.1 + t_k the y acceleration is 0.5 × the k-th sample.
  const std::size_t k = 100;
  const Vec3 a = g.acceleration_vector(0.1 + c.record_time[k]);
  EXPECT_NEAR(a.y() - g.acceleration_at(0.1 + c.record_time[k]) * g.direction.y(), 0.5 * c.record_acceleration[k],
              1e-12);
  EXPECT_EQ(g.components[0].direction, Vec3(0, 1, 0));
}

// ------------------------------------------------- histories by group

// Two stones in free flight: the group's position is the mass-weighted
// centroid, its velocity the momentum over the mass.
TEST(GroupHistories, PositionAndVelocityAreMassWeighted) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.1
gravity = [0, 0, 0]

[[block]]
name = "a"
shape = "box"
size = [1, 1, 1]
velocity = [1.0, 0.0, 0.0]
group = "pair"

[[block]]
name = "b"
shape = "box"
size = [1, 1, 1]
center = [3, 0, 0]
density = 7800
velocity = [0.0, 2.0, 0.0]
group = "pair"

[output]
history_interval = 0.05
histories = ["group:pair.position", "group:pair.velocity"]
)",
                                 "pair.toml");
  const RunReport r = run_scene(s);
  const double ma = 2600.0, mb = 7800.0, m = ma + mb;
  const std::size_t last = r.histories.row_count() - 1;
  const double t = at(r.histories, "time", last);
  EXPECT_NEAR(at(r.histories, "group:pair.position.x", last), (ma * (0.0 + t) + mb * 3.0) / m, 1e-12);
  EXPECT_NEAR(at(r.histories, "group:pair.position.y", last), mb * 2.0 * t / m, 1e-12);
  EXPECT_NEAR(at(r.histories, "group:pair.velocity.x", last), ma * 1.0 / m, 1e-12);
  EXPECT_NEAR(at(r.histories, "group:pair.velocity.y", last), mb * 2.0 / m, 1e-12);
}

// A stack of two stones in one group on a base: the group's contact force is
// the base's push on it, the whole weight (the joint inside cancels).
TEST(GroupHistories, AGroupsContactForceIsWhatTheRestPutsOnIt) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.001

[[block]]
name = "base"
shape = "box"
size = [2.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "lower"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, 0.5]
group = "wall"

[[block]]
name = "upper"
shape = "box"
size = [1.0, 1.0, 0.5]
center = [0.0, 0.0, 1.25]
group = "wall"

[equilibrium]
ratio = 1e-8

[output]
histories = ["group:wall.contact_force", "lower.contact_force"]

[assessment]
monitor_group = "wall"
)",
                                 "wall.toml");
  const RunReport r = run_scene(s);
  const std::size_t last = r.histories.row_count() - 1;
  const double w = (2600.0 + 1300.0) * 9.81;
  EXPECT_NEAR(at(r.histories, "group:wall.contact_force.z", last), w, 1e-6 * w);
  // The lower stone alone carries its weight and pushes up on the upper.
  EXPECT_NEAR(at(r.histories, "lower.contact_force.z", last), 2600.0 * 9.81, 1e-6 * w);
  EXPECT_EQ(r.assessment.monitor_block, "upper");  // the group's highest free block
}

// The example: the spire on a dry base under mortared courses, three
// components. Read, and run for a few milliseconds: the two laws act, the
// groups are the generator's.
TEST(MortaredCoursesExample, ReadsAndRuns) {
  const SceneSpec s = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/mortared_courses.toml",
                                {"simulation.end_time=0.001", "output.history_interval=0.0005"});
  ASSERT_EQ(s.joint_pairs.size(), 1u);
  EXPECT_EQ(s.joint.cohesion, 1.0e5);
  EXPECT_EQ(s.joint_pairs[0].joint.cohesion, 0.0);
  EXPECT_EQ(s.ground_motion.components.size(), 2u);
  const RunReport r = run_scene(s);
  EXPECT_FALSE(r.unstable);
  EXPECT_EQ(r.assessment.monitor_block, "tip");
  // The generator's groups: the base, one per course, the tip.
  const Blocks blocks = build_blocks(s.blocks);
  EXPECT_EQ(blocks.group_names.front(), "base");
  EXPECT_EQ(blocks.group_names.back(), "tip");
  EXPECT_EQ(blocks.group_names.size(), 22u);  // 20 courses of 0.3 m under the 3.4 m tip
  EXPECT_GE(blocks.find_group("course19"), 0);
}

// summary.json lists each group's blocks, mass and dislodged share: a
// loose stone falls off its ledge (dislodged), the wall it sat on stays.
TEST(GroupSummary, ListsEachGroupsMassAndDislodgedShare) {
  const SceneSpec s = parse_deck(R"(
[simulation]
end_time = 0.4

[[block]]
name = "ledge"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, -0.5]
motion = "fixed"
group = "ledge"

[[block]]
name = "w1"
shape = "box"
size = [1.0, 1.0, 0.5]
center = [0.0, 0.0, 0.25]
group = "wall"

[[block]]
name = "w2"
shape = "box"
size = [1.0, 1.0, 0.5]
center = [0.0, 0.0, 0.75]
group = "wall"

[[block]]
name = "loose"
shape = "box"
size = [0.2, 0.2, 0.2]
center = [3.0, 0.0, 0.1]
group = "loose"
)",
                                 "ledge.toml");
  const RunReport r = run_scene(s);
  const Json j = summary_json(s, r, 1);
  const Json* groups = j.find("groups");
  ASSERT_NE(groups, nullptr);
  ASSERT_EQ(groups->size(), 3u);
  const Json& wall = groups->at(1);
  EXPECT_EQ(wall.find("name")->as_string(), "wall");
  EXPECT_EQ(wall.find("blocks")->as_number(), 2.0);
  EXPECT_NEAR(wall.find("mass_kg")->as_number(), 2600.0, 1e-9);
  EXPECT_EQ(wall.find("dislodged_mass_fraction")->as_number(), 0.0);
  const Json& loose = groups->at(2);
  EXPECT_EQ(loose.find("dislodged_blocks")->as_number(), 1.0);
  EXPECT_EQ(loose.find("dislodged_mass_fraction")->as_number(), 1.0);
}

// ------------------------------------------------------------ determinism

// A 200-stone wall whose courses alternate between two groups with their
// own laws on a dry base, a point load on one group, a pusher and three
// ground-motion components: 1 and 2 threads give the same bits, with every
// step in parallel.
std::string group_wall_deck() {
  std::ostringstream d;
  d << "[simulation]\nend_time = 0.01\n"
       "[[joint]]\nfriction_angle = 35.0\ncohesion = 2e4\ntensile_strength = 1e4\n"
       "[[joint]]\nbetween = [\"base\", \"even\"]\nfriction_angle = 30.0\ncohesion = 0\ntensile_strength = 0\n"
       "[[joint]]\nbetween = [\"odd\", \"even\"]\nnormal_stiffness = 40e9\n"
       "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.6\nperiod = 0.05\n"
       "[[ground_motion.component]]\nkind = \"sine_pulse\"\nacceleration_g = 0.4\nperiod = 0.04\ndirection = [0, 1, 0]\n"
       "[[ground_motion.component]]\nkind = \"constant\"\nacceleration_g = 0.2\ndirection = [0, 0, 1]\n"
       "[[load]]\ngroups = [\"odd\"]\nforce = [50, 0, 0]\ntable = [[0, 0], [0.01, 1]]\n"
       "[[prescribe]]\nblocks = [\"pusher\"]\nvelocity = [0.5, 0, 0]\n"
       "[[block]]\nname = \"base\"\ngroup = \"base\"\nshape = \"box\"\nsize = [8, 1, 0.5]\ncenter = [0, 0, -0.25]\n"
       "motion = \"fixed\"\n"
       "[[block]]\nname = \"pusher\"\nshape = \"box\"\nsize = [0.3, 0.3, 0.2]\ncenter = [-3.15, 0, 0.1]\n";
  const double unit = 0.3, height = 0.2;
  for (int c = 0; c < 10; ++c) {
    double x = -3.0;
    const int n = c % 2 == 0 ? 20 : 21;
    for (int k = 0; k < n; ++k) {
      const double w = (c % 2 == 1 && (k == 0 || k == n - 1)) ? unit / 2 : unit;
      d << "[[block]]\ngroup = \"" << (c % 2 == 0 ? "even" : "odd") << "\"\nshape = \"box\"\nsize = [" << w
        << ", 0.3, " << height << "]\ncenter = [" << x + w / 2 << ", 0, " << height * (c + 0.5) << "]\n";
      x += w;
    }
  }
  return d.str();
}

TEST(GroupsDeterminism, OneAndTwoThreadsGiveTheSameBits) {
  const SceneSpec spec = parse_deck(group_wall_deck(), "group_wall.toml");
  ASSERT_EQ(spec.joint_pairs.size(), 2u);
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  one.parallel_threshold = 0;
  two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  const RunReport b = run_scene(spec, two);
  ASSERT_EQ(a.final_position.size(), b.final_position.size());
  EXPECT_EQ(std::memcmp(a.final_position.data(), b.final_position.data(), a.final_position.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.final_velocity.data(), b.final_velocity.data(), a.final_velocity.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0);
  double moved = 0;
  for (const Vec3& v : a.final_velocity) moved = std::max(moved, v.norm());
  EXPECT_GT(moved, 1e-3);
  EXPECT_LT(a.energy_balance_error, 0.1);  // the numerical line over the energy put in: 7.2 % measured
}

// A restart from a checkpoint taken mid-run (point loads ramping, the
// pusher moving, their ledger's last-step forces) ends bit for bit as the
// run that was not stopped.
TEST(GroupsDeterminism, ARestartContinuesBitwise) {
  expect_restart_continues_bitwise(
      parse_deck(group_wall_deck() + "[output]\ncheckpoint_interval = 0.004\n", "group_wall.toml"));
}

}  // namespace
}  // namespace polydem
