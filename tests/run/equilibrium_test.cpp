// The static stage ([equilibrium], run/equilibrium.hpp) and the gravity rise
// time (simulation.gravity_rise_time) against the statics of a rigid block
// on its joint springs, and sudden gravity on undamped frictional joints
// against them (it ratchets: metres, where statics says millimetres).
//
// The scene: a 1 m cube (2600 kg) on the plane z = 0 under gravity tilted by
// θ = 40° about y (as examples/verification/slope_*.toml), kn = ks = 1e7
// Pa/m, φ = 50°, no joint damping. The patch is the cube's base: four
// corner subcontacts of tributary area A/4.
//
// Statics (solved exactly below): the rigid block's displacement u and
// rotation ϕ about its centroid; a corner at r (from the centroid) moves by
// d = u + ϕ×r; its springs give Fn = −(kn A/4) d_z and Fs = −(ks A/4) d_t;
// force and moment equilibrium with the weight m·g at the centroid, a 6×6
// linear system. Its stick solution loads the two upslope corners with
// |Fs|/Fn = 5.2 > tan φ: under any proportional loading they slip from the
// start, carrying Fs = Fn·tan φ against the sliding direction, and the
// system stays linear with that slip set. The normal displacement and the
// rotation do not depend on which corners slip (the shear forces all act in
// the base plane: their moment about the centroid is the same however they
// are shared); the down-slope displacement does, and so on the loading path.
#include "io/deck.hpp"
#include "run/run_scene.hpp"
#include "run/scene_error.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

namespace polydem {
namespace {

constexpr double kTheta = 40.0, kPhi = 50.0, kK = 1e7, kMass = 2600.0, kSide = 1.0;

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

Vec3 tilted_gravity() { return kGravity * Vec3(std::sin(rad(kTheta)), 0.0, -std::cos(rad(kTheta))); }

Mat3 skew(const Vec3& r) {
  Mat3 s;
  s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return s;
}

struct Statics {
  Vec3 u, rotation;  // m, rad: the centroid's displacement and the rotation vector
};

// The rigid block on its four corner springs (see the file's header), with
// the corners whose trial shear exceeds Coulomb slipping; exact up to the
// linear solve.
Statics block_on_corner_springs(bool allow_slip) {
  const double a = kSide / 2, ka = kK * kSide * kSide / 4, mu = std::tan(rad(kPhi));
  std::array<Vec3, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = Vec3((k & 1) ? a : -a, (k & 2) ? a : -a, -a);
  std::array<bool, 4> slip{};
  Statics s;
  for (int pass = 0; pass < 4; ++pass) {
    Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
    for (int k = 0; k < 4; ++k) {
      Eigen::Matrix<double, 3, 6> B;
      B << Mat3::Identity(), -skew(corners[k]);  // d = u + ϕ×r = u − r×ϕ
      Mat3 D = Mat3::Zero();                     // corner force = −D·d
      D(2, 2) = ka;
      if (slip[k]) {
        D(0, 2) = -mu * ka;  // sliding down the slope (+x): Fs_x = −tan φ·Fn = tan φ·ka·d_z
      } else {
        D(0, 0) = D(1, 1) = ka;
      }
      Eigen::Matrix<double, 6, 3> T;  // force and moment of a corner force about the centroid
      T << Mat3::Identity(), skew(corners[k]);
      K += T * D * B;
    }
    Eigen::Matrix<double, 6, 1> f;
    f << kMass * tilted_gravity(), Vec3::Zero();
    const Eigen::Matrix<double, 6, 1> x = K.fullPivLu().solve(f);
    s.u = x.head<3>();
    s.rotation = x.tail<3>();
    if (!allow_slip) break;
    bool changed = false;
    for (int k = 0; k < 4; ++k) {
      const Vec3 d = s.u + s.rotation.cross(corners[k]);
      const double fn = -ka * d.z(), fs = ka * std::hypot(d.x(), d.y());
      if (!slip[k] && fs > mu * fn) slip[k] = changed = true;
    }
    if (!changed) break;
  }
  return s;
}

enum class Loading { sudden, equilibrium, rise };

std::string slope_deck(Loading loading, double end_time, double rise_time = 0) {
  const Vec3 g = tilted_gravity();
  std::ostringstream d;
  d.precision(17);
  d << "[simulation]\nend_time = " << end_time << "\ngravity = [" << g.x() << ", 0.0, " << g.z() << "]\n";
  if (loading == Loading::rise) d << "gravity_rise_time = " << rise_time << "\n";
  if (loading == Loading::equilibrium) d << "\n[equilibrium]\nratio = 1e-7\n";
  d << "\n[joint]\nnormal_stiffness = " << kK << "\nshear_stiffness = " << kK << "\nfriction_angle = " << kPhi
    << "\ndamping = 0.0\n\n"
    << "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [8.0, 4.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
    << "motion = \"fixed\"\n\n"
    << "[[block]]\nname = \"stone\"\nshape = \"box\"\nsize = [1.0, 1.0, 1.0]\ncenter = [0.0, 0.0, 0.5]\n"
    << "density = 2600.0\n\n[output]\nenergies = false\n";
  return d.str();
}

struct Moved {
  Vec3 u, rotation;
};

Moved run_slope(const std::string& text, RunReport* out = nullptr) {
  const SceneSpec spec = parse_deck(text, "slope.toml");
  RunReport r = run_scene(spec);
  const int i = 1;
  Moved m;
  m.u = r.final_position[i] - Vec3(0.0, 0.0, 0.5);
  const Eigen::AngleAxisd aa(r.final_orientation[i]);
  m.rotation = aa.angle() * aa.axis();
  if (out) *out = std::move(r);
  return m;
}

// The path-independent part of the statics: the normal displacement and the
// rotation about y, to 1 %.
void expect_normal_and_rotation(const Moved& m, const Statics& s) {
  EXPECT_NEAR(m.u.z(), s.u.z(), 0.01 * std::abs(s.u.z()));
  EXPECT_NEAR(m.rotation.y(), s.rotation.y(), 0.01 * std::abs(s.rotation.y()));
  EXPECT_NEAR(m.u.y(), 0.0, 1e-9);
}

TEST(SlopeStatics, AnalyticalSolution) {
  const Statics stick = block_on_corner_springs(false), slip = block_on_corner_springs(true);
  // Stick: shear 1.64 mm plus the rotation's 1.64 mm at the centroid; normal 1.95 mm.
  EXPECT_NEAR(stick.u.x(), 3.279e-3, 1e-6);
  EXPECT_NEAR(stick.u.z(), -1.954e-3, 1e-6);
  EXPECT_NEAR(std::hypot(stick.u.x(), stick.u.z()), 3.817e-3, 1e-6);
  // With the upslope corners slipping the block goes further down the slope;
  // normal displacement and rotation are the same.
  EXPECT_NEAR(slip.u.x(), 4.544e-3, 1e-6);
  EXPECT_NEAR(slip.u.z(), stick.u.z(), 1e-12);
  EXPECT_NEAR(slip.rotation.y(), stick.rotation.y(), 1e-12);
}

// Gravity rising over 3 s (about 30 periods of the block on its joints):
// quasi-static proportional loading, the statics with the upslope corners
// slipping, to 2 %. Sudden gravity on the same deck goes metres.
TEST(SlopeStatics, GravityRiseTimeMatchesStatics) {
  const Statics s = block_on_corner_springs(true);
  const Moved m = run_slope(slope_deck(Loading::rise, 4.0, 3.0));
  EXPECT_NEAR(m.u.x(), s.u.x(), 0.02 * s.u.x());
  expect_normal_and_rotation(m, s);
}

// The static stage (local damping 0.8, ratio 1e-7) reaches an equilibrium
// with the statics' normal displacement and rotation to 1 %; its down-slope
// displacement is that of a path with a dynamic first swing (the stage
// applies the weight at once): more slip at the corners than under a slow
// rise, within 15 % of the proportional-loading statics.
TEST(SlopeStatics, StaticStageMatchesStatics) {
  const Statics s = block_on_corner_springs(true);
  RunReport r;
  const Moved m = run_slope(slope_deck(Loading::equilibrium, 0.2), &r);
  ASSERT_TRUE(r.equilibrium.ran);
  EXPECT_LE(r.equilibrium.ratio, 1e-7);
  EXPECT_GT(m.u.x(), 0.98 * s.u.x());
  EXPECT_LT(m.u.x(), 1.15 * s.u.x());
  expect_normal_and_rotation(m, s);
  // The dynamic stage starts at rest from the equilibrium and stays there.
  EXPECT_NEAR(r.assessment.peak_displacement, 0.0, 1e-6);
}

TEST(SlopeStatics, SuddenGravityWithoutDampingRatchets) {
  const SceneSpec spec = parse_deck(slope_deck(Loading::sudden, 2.0), "slope.toml");
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_NE(spec.warnings[0].find("slope.toml:"), std::string::npos) << spec.warnings[0];
  EXPECT_NE(spec.warnings[0].find("key 'joint.damping'"), std::string::npos) << spec.warnings[0];
  const RunReport r = run_scene(spec);
  EXPECT_GT((r.final_position[1] - Vec3(0.0, 0.0, 0.5)).norm(), 0.5);  // metres, against 4.5 mm
}

TEST(Equilibrium, NoWarningWithAStaticStageOrARiseTime) {
  EXPECT_TRUE(parse_deck(slope_deck(Loading::equilibrium, 0.1), "s.toml").warnings.empty());
  EXPECT_TRUE(parse_deck(slope_deck(Loading::rise, 0.1, 1.0), "s.toml").warnings.empty());
}

TEST(Equilibrium, StageAndRiseTimeTogetherAreAnError) {
  EXPECT_THROW(parse_deck(slope_deck(Loading::rise, 0.1, 1.0) + "\n[equilibrium]\n", "s.toml"), DeckError);
}

TEST(Equilibrium, NotConvergingNamesTheKey) {
  const SceneSpec spec = parse_deck(slope_deck(Loading::equilibrium, 0.1), "s.toml", {"equilibrium.max_steps=5"});
  try {
    run_scene(spec);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key, "equilibrium.max_steps");
  }
}

// A block resting on a flat base: the stage converges to the tolerance and
// the joints then carry m·g to that tolerance.
TEST(Equilibrium, RestingBlockCarriesItsWeight) {
  const std::string text =
      "[simulation]\nend_time = 0.01\n\n[equilibrium]\nratio = 1e-6\n\n[joint]\nnormal_stiffness = 1e9\n\n"
      "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [2.0, 2.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
      "motion = \"fixed\"\n\n[[block]]\nname = \"stone\"\nshape = \"box\"\nsize = [1.0, 1.0, 0.5]\n"
      "center = [0.0, 0.0, 0.25]\n\n[[check]]\nkind = \"resting_weight\"\nblock = \"stone\"\ntolerance = 2e-6\n";
  const RunReport r = run_scene(parse_deck(text, "rest.toml"));
  ASSERT_TRUE(r.equilibrium.ran);
  EXPECT_LE(r.equilibrium.ratio, 1e-6);
  EXPECT_GT(r.equilibrium.steps, 0);
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_TRUE(r.checks[0].passed) << r.checks[0].measured << " vs " << r.checks[0].expected;
}

// Density scaling: a 2 m block and a 0.2 m one resting side by side on a
// base. Each settles by w = ρ·g·h/kn (uniform pressure); the scaled stage
// reaches the same state (to the stage's tolerance) in fewer steps, because
// the heavy block does not vibrate 3 times slower than the one that sets
// the step.
TEST(Equilibrium, DensityScalingReachesTheSameStateInFewerSteps) {
  const std::string text =
      "[simulation]\nend_time = 0.001\n\n[equilibrium]\nratio = 1e-7\n\n[joint]\nnormal_stiffness = 1e9\n"
      "shear_stiffness = 4e8\ndamping = 0\n\n"
      "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [6.0, 4.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
      "motion = \"fixed\"\n\n[[block]]\nname = \"big\"\nshape = \"box\"\nsize = [2.0, 2.0, 2.0]\n"
      "center = [-1.5, 0.0, 1.0]\n\n[[block]]\nname = \"small\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.2]\n"
      "center = [1.5, 0.0, 0.1]\n";
  const RunReport plain = run_scene(parse_deck(text, "ds.toml"));
  const RunReport scaled = run_scene(parse_deck(text, "ds.toml", {"equilibrium.density_scaling=true"}));
  ASSERT_TRUE(plain.equilibrium.ran && scaled.equilibrium.ran);
  EXPECT_LE(scaled.equilibrium.ratio, 1e-7);
  std::printf("density scaling: %ld steps, without %ld\n", scaled.equilibrium.steps, plain.equilibrium.steps);
  EXPECT_LT(scaled.equilibrium.steps, plain.equilibrium.steps);
  // The settlement of each block, w = ρ g h / kn (2600 kg/m³), to 1e-4 of w
  // (the stage's tolerance 1e-7 of the mean weight on springs of 1e9 Pa/m).
  for (const auto& [r, label] : {std::pair{&plain, "plain"}, std::pair{&scaled, "scaled"}}) {
    const double g = 9.81;
    const double w_big = 2600 * g * 2.0 / 1e9, w_small = 2600 * g * 0.2 / 1e9;
    EXPECT_NEAR(r->final_position[1].z(), 1.0 - w_big, 1e-4 * w_big) << label;
    EXPECT_NEAR(r->final_position[2].z(), 0.1 - w_small, 1e-4 * w_small) << label;
  }
}

// Density scaling on blocks held on two faces (a stack of three 1 m cubes
// beside a 5 cm one that sets the step): the stage must stay stable where a
// block's joints are stiffer than its all-faces bound alone would say, and
// each joint settles by the weight above it, w = n·ρ·g·h/kn. With either
// time-step bound: under the joint bound the 5 cm cube on the fixed base
// allows a √2 larger step, so the scaled blocks must not all rise to its
// frequency (Simulation::begin_static_stage).
class DensityScalingOnAStack : public ::testing::TestWithParam<const char*> {};

TEST_P(DensityScalingOnAStack, StaysStable) {
  std::string text =
      "[simulation]\nend_time = 0.001\n\n[equilibrium]\nratio = 1e-7\ndensity_scaling = true\n\n[joint]\n"
      "normal_stiffness = 1e9\nshear_stiffness = 4e8\ndamping = 0\n\n"
      "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [8.0, 4.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
      "motion = \"fixed\"\n\n[[block]]\nname = \"cube\"\nshape = \"box\"\nsize = [0.05, 0.05, 0.05]\n"
      "center = [2.5, 0.0, 0.025]\n";
  for (int k = 0; k < 3; ++k)
    text += "\n[[block]]\nshape = \"box\"\nsize = [1.0, 1.0, 1.0]\ncenter = [-1.5, 0.0, " + std::to_string(0.5 + k) + "]\n";
  const RunReport r =
      run_scene(parse_deck(text, "stack.toml", {std::string("simulation.time_step_bound=\"") + GetParam() + "\""}));
  ASSERT_FALSE(r.unstable) << r.instability;
  EXPECT_LE(r.equilibrium.ratio, 1e-7);
  const double w = 2600 * 9.81 * 1.0 / 1e9;  // one cube's weight over kn·A
  EXPECT_NEAR(r.final_position[2].z(), 0.5 - 3 * w, 1e-3 * w);
  EXPECT_NEAR(r.final_position[3].z(), 1.5 - 5 * w, 1e-3 * w);
  EXPECT_NEAR(r.final_position[4].z(), 2.5 - 6 * w, 1e-3 * w);
}

INSTANTIATE_TEST_SUITE_P(Equilibrium, DensityScalingOnAStack, ::testing::Values("block", "joint"));

// The 52-stone dry-stone wall converges to the ratio tolerance, and stays.
TEST(Equilibrium, DryStoneWallConverges) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/dry_stone_wall.toml";
  const SceneSpec spec = read_deck(path, {"equilibrium.ratio=1e-5", "simulation.end_time=0.05"});
  const RunReport r = run_scene(spec);
  ASSERT_TRUE(r.equilibrium.ran);
  EXPECT_LE(r.equilibrium.ratio, 1e-5);
  EXPECT_TRUE(r.all_checks_passed());
  EXPECT_LT(r.assessment.peak_displacement, 1e-5);
}

// The static stage under the split damping scheme (its second pass with
// local damping and the joints' dashpots both acting): the same wall
// converges, at the split scheme's larger step, to the same rest.
TEST(Equilibrium, DryStoneWallConvergesUnderTheSplitDampingScheme) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/dry_stone_wall.toml";
  const RunReport e = run_scene(read_deck(path, {"equilibrium.ratio=1e-5", "simulation.end_time=0.05"}));
  const RunReport r = run_scene(
      read_deck(path, {"equilibrium.ratio=1e-5", "simulation.end_time=0.05", "simulation.damping_scheme=\"split\""}));
  ASSERT_TRUE(r.equilibrium.ran);
  EXPECT_LE(r.equilibrium.ratio, 1e-5);
  EXPECT_TRUE(r.all_checks_passed());
  EXPECT_LT(r.assessment.peak_displacement, 1e-5);
  EXPECT_GT(r.damping_split_fraction, 0.0);
  EXPECT_GT(r.time_step, e.time_step);
  // The same rest to a small fraction of the joints' settlement (~µm).
  double apart = 0;
  for (std::size_t i = 0; i < r.final_position.size(); ++i)
    apart = std::max(apart, (r.final_position[i] - e.final_position[i]).norm());
  EXPECT_LT(apart, 1e-7);
}

// Decks that leave the new keys at their defaults, given or not, run the
// same bits (the behaviour against the previous binary is checked on the
// example decks).
TEST(Equilibrium, DefaultsChangeNoBits) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/slope_slide.toml";
  const RunReport a = run_scene(read_deck(path, {"simulation.end_time=0.2"}));
  const RunReport b = run_scene(read_deck(
      path, {"simulation.end_time=0.2", "simulation.gravity_rise_time=0", "equilibrium.enabled=false"}));
  ASSERT_FALSE(b.equilibrium.ran);
  ASSERT_EQ(a.steps, b.steps);
  for (std::size_t i = 0; i < a.final_position.size(); ++i) {
    EXPECT_EQ(a.final_position[i], b.final_position[i]);
    EXPECT_EQ(a.final_velocity[i], b.final_velocity[i]);
  }
}

}  // namespace
}  // namespace polydem
