// Verification 6: the same deck gives bitwise-identical results on 1 and 2
// threads. The scene is large enough (a 200-stone wall) for every parallel
// loop of the step to run in parallel.
#include "run/run_scene.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

namespace polydem {
namespace {

std::string big_wall_deck() {
  std::ostringstream d;
  d << "[simulation]\nend_time = 0.015\n[joint]\nnormal_stiffness = 98e9\nfriction_angle = 30.0\n"
       "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.6\nperiod = 0.05\ndirection = [0.6, 0.8, 0.0]\n"
       "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [8, 1, 0.5]\ncenter = [0, 0, -0.25]\nmotion = \"fixed\"\n";
  const double unit = 0.3, height = 0.2;
  for (int c = 0; c < 10; ++c) {
    double x = -3.0;
    const int n = c % 2 == 0 ? 20 : 21;
    for (int k = 0; k < n; ++k) {
      const double w = (c % 2 == 1 && (k == 0 || k == n - 1)) ? unit / 2 : unit;
      d << "[[block]]\nshape = \"box\"\nsize = [" << w << ", 0.3, " << height << "]\ncenter = [" << x + w / 2
        << ", 0, " << height * (c + 0.5) << "]\n";
      x += w;
    }
  }
  return d.str();
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// The runs' final state and ledger, bit for bit; their steps and detections.
void expect_same_bits(const RunReport& a, const RunReport& b, const std::string& what = "") {
  EXPECT_EQ(a.steps, b.steps) << what;
  EXPECT_EQ(a.detections, b.detections) << what;
  EXPECT_TRUE(same_bits(a.final_position, b.final_position)) << what;
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity)) << what;
  EXPECT_EQ(std::memcmp(a.final_orientation.data(), b.final_orientation.data(),
                        a.final_orientation.size() * sizeof(Quat)),
            0)
      << what;
  EXPECT_EQ(std::memcmp(&a.energy, &b.energy, sizeof(EnergyLedger)), 0) << what;
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameBits) {
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml");
  spec.simulation.adaptive_threads = false;  // two threads all the way (the governor has its own test)
  ASSERT_GT(spec.blocks.size(), 200u);
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  // Every step in parallel, whatever its size: the point is to compare.
  one.parallel_threshold = 0;
  two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  const RunReport b = run_scene(spec, two);
  expect_same_bits(a, b);
  // And the motion is not trivial.
  double moved = 0;
  for (std::size_t i = 0; i < a.final_position.size(); ++i)
    moved = std::max(moved, a.final_velocity[i].norm());
  EXPECT_GT(moved, 1e-3);
}

// The big wall with `setting` run on 1 and on 2 threads (every step in
// parallel): the same bits. Returns the run on 1 thread and, in `two`, the
// run on 2.
RunReport one_and_two_threads(const std::string& setting, RunReport& two_threads) {
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml", {setting});
  spec.simulation.adaptive_threads = false;
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  one.parallel_threshold = two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  two_threads = run_scene(spec, two);
  expect_same_bits(a, two_threads, setting);
  return a;
}

// The overlap joint model (a wrench per pair, gathered pair by pair) on 1
// and 2 threads: the same bits.
TEST(Determinism, TheOverlapModelGivesTheSameBitsOnOneAndTwoThreads) {
  RunReport b;
  const RunReport a = one_and_two_threads("simulation.joint_model=\"overlap\"", b);
  EXPECT_GT(a.energy.slip, 0.0);
}

// Joints re-sampled pair by pair (simulation.detection_trigger = "pair"):
// the moved pairs found, sampled and spliced in on 1 and 2 threads give
// the same bits, with pairs re-sampled between scene-wide detections.
TEST(Determinism, ThePairTriggerGivesTheSameBitsOnOneAndTwoThreads) {
  RunReport b;
  const RunReport a = one_and_two_threads("simulation.detection_trigger=\"pair\"", b);
  EXPECT_EQ(a.pairs_resampled, b.pairs_resampled);
  EXPECT_GT(a.pairs_resampled, 0);
  EXPECT_GT(a.energy.slip, 0.0);
}

// Points that follow the blocks (simulation.joint_sampling = "step"), moved
// pair by pair in the step's threads: the same bits on 1 and 2 threads.
TEST(Determinism, PointsFollowingTheBlocksGiveTheSameBitsOnOneAndTwoThreads) {
  RunReport b;
  const RunReport a = one_and_two_threads("simulation.joint_sampling=\"step\"", b);
  EXPECT_GT(a.energy.slip, 0.0);
}

// Joints clipped at every step (simulation.joint_sampling = "clip"), in
// parallel over pairs, their rest gathered by pair: the same bits on 1 and
// 2 threads.
TEST(Determinism, ClippedJointsGiveTheSameBitsOnOneAndTwoThreads) {
  RunReport b;
  const RunReport a = one_and_two_threads("simulation.joint_sampling=\"clip\"", b);
  EXPECT_EQ(a.pairs_resampled, b.pairs_resampled);
  EXPECT_GT(a.energy.slip, 0.0);
}

// Joints re-sampled scene-wide (simulation.detection_trigger = "scene"):
// the same bits on 1 and 2 threads.
TEST(Determinism, TheSceneWideTriggerGivesTheSameBitsOnOneAndTwoThreads) {
  RunReport b;
  const RunReport a = one_and_two_threads("simulation.detection_trigger=\"scene\"", b);
  EXPECT_EQ(a.pairs_resampled, 0);
  EXPECT_GT(a.energy.slip, 0.0);
}

// The joint law's kernel in AVX2 lanes and in plain doubles
// (contact/joint_law_kernels.hpp) give the same bits through a whole run: the wall under the pulse, on two
// threads, every step's law on one path or the other.
TEST(Determinism, TheJointLawsTwoCodePathsGiveTheSameBits) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 here: only the portable path runs";
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml");
  spec.simulation.adaptive_threads = false;
  RunControl lanes, portable;
  lanes.threads = portable.threads = 2;
  lanes.parallel_threshold = portable.parallel_threshold = 0;
  lanes.code_path = CodePath::lanes;
  portable.code_path = CodePath::portable;
  const RunReport a = run_scene(spec, lanes);
  const RunReport b = run_scene(spec, portable);
  expect_same_bits(a, b);
  EXPECT_GT(a.energy.slip, 0.0);  // joints slipped: the law's every branch had its say
  // The AVX2 kernel where CodePath::lanes took the AVX-512VL copy.
  if (wide_lanes_available()) {
    RunControl avx2 = lanes;
    avx2.code_path = CodePath::lanes_avx2;
    expect_same_bits(run_scene(spec, avx2), b, "AVX2 kernel");
  } else {
    std::cout << "no AVX-512VL here: the law's AVX-512VL kernel was not run\n";
  }
}

// The blocks' update in AVX2 lanes against the portable one, through every
// branch of the step's block loop: blocks four at a time; a remainder; a
// block under a point load (advance_block); gravity rising (advance_block)
// and risen; stones thrown spinning at 300 rad/s, whose turn per step is
// beyond the exponential's series (the kernel's closed form); fixed blocks. The
// stones are turned about the vertical and the thrown ones about every axis,
// so that no rotation matrix is the identity (whose zeros would hide a
// wrong association); then the spire under a pulse.
TEST(Determinism, TheBlockUpdatesTwoCodePathsGiveTheSameBits) {
  if (!lanes_available()) GTEST_SKIP() << "no AVX2 here: only the portable path runs";
  std::ostringstream d;
  d << "[simulation]\nend_time = 0.03\ngravity_rise_time = 0.01\n[joint]\nnormal_stiffness = 1e10\n"
       "friction_angle = 30.0\ndamping = 1e-5\n"
       "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.4\nperiod = 0.02\ndirection = [1.0, 0.3, 0.0]\n"
       "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [6, 2, 0.5]\ncenter = [0, 0, -0.25]\nmotion = \"fixed\"\n";
  // Base 0, stones 1-6, thrown 7-9, stones 10-14: on one thread the
  // groups (5-8) and (9-12) hold thrown stones, on two threads (8-11) does
  // (libgomp's static halves 0-7 and 8-14), so the closed form runs in
  // different groups on each, besides the remainders.
  auto stone = [&d](int k) {
    d << "[[block]]\nname = \"stone" << k << "\"\nshape = \"box\"\nsize = [0.3, 0.2, 0.2]\ncenter = ["
      << -2.5 + 0.5 * k << ", 0, 0.1]\nrotation = [0, 0, " << 7 * k + 3 << "]\n";
  };
  for (int k = 0; k < 6; ++k) stone(k);
  for (int k = 0; k < 3; ++k)
    d << "[[block]]\nname = \"thrown" << k << "\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.2]\ncenter = ["
      << -1.0 + k << ", 0, 3.0]\nrotation = [" << 10 + k << ", 20, 30]\nvelocity = [0.5, 0, 2]\n"
      << "angular_velocity = [300, " << 50 * k << ", 20]\n";
  for (int k = 6; k < 11; ++k) stone(k);
  d << "[[load]]\nblocks = [\"stone4\"]\nforce = [500.0, 0.0, 0.0]\npoint = [-0.4, 0.05, 0.15]\n";
  SceneSpec spec = parse_deck(d.str(), "blocks.toml");
  spec.simulation.adaptive_threads = false;
  RunControl lanes, portable;
  lanes.parallel_threshold = portable.parallel_threshold = 0;
  lanes.code_path = CodePath::lanes;
  portable.code_path = CodePath::portable;
  RunReport a;
  for (const int threads : {1, 2}) {
    lanes.threads = portable.threads = threads;
    a = run_scene(spec, lanes);
    const RunReport b = run_scene(spec, portable);
    expect_same_bits(a, b, std::to_string(threads) + " threads");
  }
  EXPECT_GT(a.energy.load_work, 0.0);  // the load and the ground did work
  // The stones moved, the thrown ones are still turning.
  EXPECT_GT((a.final_position[5] - Vec3(-2.5 + 0.5 * 4, 0, 0.1)).norm(), 1e-6);
  EXPECT_GT(a.final_velocity[8].norm(), 0.1);

  lanes.threads = portable.threads = 2;
  SceneSpec spire = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/pulse.toml",
                              {"simulation.end_time=0.05", "output.snapshot_interval=0", "ground_motion.period=0.1"});
  spire.simulation.adaptive_threads = false;
  const RunReport c = run_scene(spire, lanes);
  const RunReport e = run_scene(spire, portable);
  expect_same_bits(c, e, "the spire");
}

}  // namespace
}  // namespace polydem

namespace polydem {
namespace {

// The split damping scheme (simulation.damping_scheme = "split": a second
// pass over the subcontacts, two more barriers a step): the wall under the
// pulse on 1 and 2 threads, and on the portable loops, the AVX2 kernels
// and the AVX-512VL copies, bit for bit; and its step is the larger one.
TEST(Determinism, TheSplitDampingSchemeGivesTheSameBitsOnEveryThreadAndPath) {
  SceneSpec spec = parse_deck(big_wall_deck(), "big_wall.toml");
  spec.simulation.adaptive_threads = false;
  spec.simulation.damping_scheme = DampingScheme::split;
  RunControl one, two;
  one.threads = 1;
  two.threads = 2;
  one.parallel_threshold = two.parallel_threshold = 0;
  const RunReport a = run_scene(spec, one);
  expect_same_bits(a, run_scene(spec, two), "2 threads");
  EXPECT_GT(a.energy.damping, 0.0);
  if (lanes_available()) {
    for (const CodePath path : {CodePath::portable, CodePath::lanes_avx2, CodePath::lanes}) {
      RunControl c = two;
      c.code_path = path;
      expect_same_bits(a, run_scene(spec, c), "code path " + std::to_string(static_cast<int>(path)));
    }
  }
  SceneSpec explicit_spec = spec;
  explicit_spec.simulation.damping_scheme = DampingScheme::explicit_lagged;
  EXPECT_LT(a.steps, run_scene(explicit_spec, two).steps);
}

}  // namespace
}  // namespace polydem
