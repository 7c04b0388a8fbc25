// Detection on the spire's 402 blocks.
//
// A detection on two threads gives the same bits as on one: the narrow phase
// and patches (one slot per candidate), the history carried pair by pair,
// the held normal strain pair by pair, the re-sampled strain energy (terms
// in parallel, summed in order) and the step check block by block (the
// highest taken in block order). On the spire's 402 blocks, displaced and
// turned a little from their detected poses with stored shear forces, so
// that every stage has work; the whole contact set is compared through its
// checkpoint bytes, which hold every array.
#include "contact/detection.hpp"
#include "integrators/critical_time_step.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

namespace polydem {
namespace {

std::string bytes_of(const ContactSet& c) {
  std::string out;
  ByteWriter w(out);
  c.save(w);
  return out;
}

TEST(ParallelDetection, TwoThreadsGiveTheSameBitsOnTheSpire) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  Blocks blocks = build_blocks(spec.blocks);
  const JointLaws laws = make_joint_laws(blocks, spec.joint, {});
  const double margin = 0.005;
  ContactDetector one(blocks, margin), two(blocks, margin);
  one.set_threads(1);
  two.set_threads(2);
  ContactSet c1, c2;
  one.detect(blocks, c1, false, laws);
  two.detect(blocks, c2, false, laws);
  ASSERT_EQ(bytes_of(c1), bytes_of(c2));
  // Enough for every parallel stage to run in parallel (their thresholds:
  // 64 candidates, 256 pairs, 2048 subcontacts, 64 free blocks).
  ASSERT_GE(c1.pairs.size(), 256u);
  ASSERT_GE(c1.sub.size(), 2048u);
  ASSERT_GE(blocks.free_blocks.size(), 64u);

  // Stored shear to carry, and the blocks moved by up to a millimetre and
  // turned by up to a milliradian, some into their neighbours.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t s = 0; s < c1.sub.size(); ++s) {
    const Vec3 f(1e3 * u(rng), 1e3 * u(rng), 1e3 * u(rng));
    c1.sub.shear_force.set(s, f);
    c2.sub.shear_force.set(s, f);
  }
  for (int i : blocks.free_blocks) {
    blocks.state.position[i] += Vec3(1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng));
    const Vec3 turn(1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng));
    blocks.state.orientation[i] =
        (Quat(Eigen::AngleAxisd(turn.norm(), turn.normalized())) * blocks.state.orientation[i]).normalized();
    blocks.state.rotation[i] = blocks.state.orientation[i].toRotationMatrix();
  }
  one.detect(blocks, c1, false, laws);
  two.detect(blocks, c2, false, laws);
  EXPECT_EQ(bytes_of(c1), bytes_of(c2));
  EXPECT_NE(c1.dropped_shear_energy, 0.0);     // the carry had history to move
  EXPECT_NE(c1.resampled_normal_energy, 0.0);  // and the re-sampling strain to book

  // The step check: the full estimate, and one that skips blocks.
  const CriticalStep full1 = critical_time_step_from_contacts(blocks, c1, laws, spec.joint.damping, 0.8, 0, 1);
  const CriticalStep full2 = critical_time_step_from_contacts(blocks, c1, laws, spec.joint.damping, 0.8, 0, 2);
  EXPECT_EQ(full1.chosen, full2.chosen);
  EXPECT_EQ(full1.omega_max, full2.omega_max);
  EXPECT_EQ(full1.governing_block, full2.governing_block);
  for (const double f : {0.5, 1.0 + 1e-12, 2.0}) {
    const CriticalStep a = critical_time_step_from_contacts(blocks, c1, laws, spec.joint.damping, 0.8, f * full1.chosen, 1);
    const CriticalStep b = critical_time_step_from_contacts(blocks, c1, laws, spec.joint.damping, 0.8, f * full1.chosen, 2);
    EXPECT_EQ(a.chosen, b.chosen) << f;
    EXPECT_EQ(a.omega_max, b.omega_max) << f;
    EXPECT_EQ(a.governing_block, b.governing_block) << f;
  }
}

// Block i moved by random amounts of order `scale`: along x only (`tight`:
// the 1-norm bound is then the travel itself), or moved, turned (the same
// turn with the quaternion's other sign when `flip`) and set moving.
void move_block(Blocks& b, int i, double scale, bool tight, bool flip, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  if (tight) {
    b.state.position[i].x() += scale * u(rng);
    return;
  }
  b.state.position[i] += scale * Vec3(u(rng), u(rng), u(rng));
  const Vec3 turn = (scale / b.props.radius[i]) * Vec3(u(rng), u(rng), u(rng));
  b.state.orientation[i] =
      (Quat(Eigen::AngleAxisd(turn.norm(), turn.normalized())) * b.state.orientation[i]).normalized();
  if (flip) b.state.orientation[i].coeffs() *= -1.0;
  b.state.velocity[i] = (scale / 1e-4) * Vec3(u(rng), u(rng), u(rng));
  b.state.angular_velocity[i] = (scale / 1e-4 / b.props.radius[i]) * Vec3(u(rng), u(rng), u(rng));
}

// The cheap bound in front of needs_detection's exact test (1-norms, no
// square roots or quaternion products) never changes its answer: the spire's
// blocks moved, turned and set moving by random amounts spanning the
// threshold, with and without the bound.
TEST(DetectionCheck, TheBoundNeverChangesTheAnswer) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  const Blocks start = build_blocks(spec.blocks);
  const double margin = 0.005;
  ContactDetector det(start, margin);
  ContactSet contacts;
  det.detect(start, contacts, false, make_joint_laws(start, spec.joint, {}));
  std::mt19937_64 rng(11);
  int yes = 0, no = 0, tight_yes = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Blocks b = start;
    // Amplitudes from far below to beyond half the margin, on all blocks
    // or on a few (the two largest travels decide).
    const double scale = margin * std::pow(10.0, -3.0 + 3.5 * (trial % 40) / 40.0);
    const bool few = trial % 3 == 0;
    // Some trials move a few blocks along x only, without turn or speed:
    // there the bound is the exact travel (a 1-norm along an axis is the
    // length), so a bound that claimed more than it proves would show.
    const bool tight = trial % 5 == 1;
    for (int i : b.free_blocks) {
      if ((few || tight) && i % 97 != 0) continue;
      move_block(b, i, scale, tight, trial % 2 == 1, rng);
    }
    const double dt = trial % 4 == 0 || tight ? 0.0 : 1e-5;
    const bool exact = det.needs_detection(b, dt, false);
    EXPECT_EQ(det.needs_detection(b, dt, true), exact) << trial;
    (exact ? yes : no) += 1;
    if (exact && tight) ++tight_yes;
  }
  EXPECT_GT(yes, 50);
  EXPECT_GT(no, 50);
  EXPECT_GT(tight_yes, 5);
}

// The same for the pair by pair test (moved_pairs): the bound in front of
// each pair's exact test never changes which pairs are re-sampled, on the
// spire's pairs with the blocks moved, turned and set moving across the
// travel (and along x alone, where the bound is the exact travel).
TEST(DetectionCheck, ThePairBoundNeverChangesWhichPairsMoved) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  const Blocks start = build_blocks(spec.blocks);
  const double margin = 0.005, travel = 1e-4;
  ContactDetector det(start, margin, travel);
  det.set_pair_trigger(true);
  ContactSet contacts;
  det.detect(start, contacts, false, make_joint_laws(start, spec.joint, {}));
  ASSERT_GT(contacts.pairs.size(), 256u);
  std::mt19937_64 rng(13);
  std::size_t some = 0, none = 0, tight_some = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Blocks b = start;
    const double scale = travel * std::pow(10.0, -2.0 + 3.0 * (trial % 40) / 40.0);
    const bool tight = trial % 5 == 1;
    for (int i : b.free_blocks)
      if (!tight || i % 7 == 0) move_block(b, i, scale, tight, trial % 2 == 1, rng);
    const double dt = trial % 4 == 0 || tight ? 0.0 : 1e-6;
    std::vector<int> exact, bounded;
    det.moved_pairs(b, contacts, dt, exact, false);
    det.moved_pairs(b, contacts, dt, bounded, true);
    EXPECT_EQ(bounded, exact) << trial;
    (exact.empty() ? none : some) += 1;
    if (tight && !exact.empty() && exact.size() < contacts.pairs.size()) ++tight_some;
  }
  EXPECT_GT(some, 30u);
  EXPECT_GT(none, 30u);
  EXPECT_GT(tight_some, 5u);
}

// The test's bound gathered block by block (TravelBound: ranges of blocks as
// the step's threads take them, kinematic blocks from a list, merged) never
// settles a step the exact test would detect at: the same random states as
// above, the travels taken from references near and far from the drift
// (the last step's, zero, 3 mm off). It settles most of the clear steps
// (each check in the step would otherwise run the exact test).
TEST(DetectionCheck, TheThreadsBoundNeverSettlesAStepTheTestWouldDetectAt) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  Blocks start = build_blocks(spec.blocks);
  const double margin = 0.005;
  ContactDetector det(start, margin);
  ContactSet contacts;
  det.detect(start, contacts, false, make_joint_laws(start, spec.joint, {}));
  std::vector<int> kinematic;
  for (int i = 5; i < start.count; i += 61) {
    if (start.props.motion[i] != BlockMotion::free) continue;
    start.props.motion[i] = BlockMotion::kinematic;  // as a prescribed block: moved after the threads
    kinematic.push_back(i);
  }
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int yes = 0, no = 0, settled = 0;
  Vec3 last_drift = Vec3::Zero();
  for (int trial = 0; trial < 600; ++trial) {
    Blocks b = start;
    const double scale = margin * std::pow(10.0, -3.0 + 3.5 * (trial % 40) / 40.0);
    const bool few = trial % 3 == 0;
    const bool tight = trial % 5 == 1;  // a few blocks along x: the bound is the travel itself
    const Vec3 common = trial % 7 == 2 ? Vec3(2e-3 * u(rng), 2e-3 * u(rng), 0) : Vec3::Zero();
    for (int i = 0; i < b.count; ++i) {
      if (b.props.motion[i] == BlockMotion::fixed) continue;
      b.state.position[i] += common;
      if ((few || tight) && i % 97 != 0 && i % 61 != 5) continue;
      move_block(b, i, scale, tight, trial % 2 == 1, rng);
    }
    const double dt = trial % 4 == 0 || tight ? 0.0 : 1e-5;
    const bool exact = det.needs_detection(b, dt, false);
    (exact ? yes : no) += 1;
    const Vec3 refs[] = {last_drift, Vec3::Zero(), last_drift + Vec3(3e-3, -3e-3, 1e-3)};
    for (const Vec3& ref : refs) {
      const int parts = 1 + trial % 3;  // one, two or three threads' ranges
      TravelBound all;
      for (int t = 0; t < parts; ++t) {
        TravelBound part;
        const int chunk = (b.count + parts - 1) / parts;
        const int begin = std::min(b.count, t * chunk), end = std::min(b.count, begin + chunk);
        det.add_travels(b, begin, end, ref, dt, part);
        merge_travels(all, part);
      }
      det.add_travels(b, kinematic, ref, dt, all);
      Vec3 drift;
      const bool clear = det.clearly_no_detection(all, ref, drift);
      EXPECT_FALSE(clear && exact) << "trial " << trial << ", ref " << ref.transpose();
      if (&ref == &refs[0]) {
        if (clear) ++settled;
        last_drift = drift;
      }
    }
  }
  EXPECT_GT(yes, 100);
  EXPECT_GT(no, 100);
  EXPECT_GT(settled, no / 2) << "the bound from the last drift settles most clear steps";
  std::cout << "exact test: " << yes << " detect, " << no << " clear; the threads' bound settled " << settled
            << "\n";
}

// Where the threads' bound needs each of its terms: travels that the drift c
// of the whole box brings closer together than the reference does. (a) Three
// spire stones moved by a along +x, +y and −x: c = (0, a/2, 0) and the test's
// sum is 2·√(5/4)·a ≈ 2.24a; from ref = 0 the 1-norms alone give 2a, from
// ref = c the plain displacements 2a too, so a bound without the 2|c − ref|₁
// slack, or taken from the displacements instead of from ref, settles a step
// at 2.1a = the threshold that the test detects at. (b) One block on a fixed
// base moved by a: the test counts the fixed base's |c| = a/2 beside the
// block's a/2; without the fixed blocks' term the bound is a/2.
TEST(DetectionCheck, TheThreadsBoundKeepsEveryTerm) {
  const SceneSpec spec = read_deck(std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/earthquake.toml");
  const Blocks start = build_blocks(spec.blocks);
  const double margin = 0.005, threshold = 0.5 * margin;
  ContactDetector det(start, margin);
  ContactSet contacts;
  det.detect(start, contacts, false, make_joint_laws(start, spec.joint, {}));
  auto settled = [&](const Blocks& b, const Vec3& ref) {
    TravelBound t;
    det.add_travels(b, 0, b.count, ref, 0.0, t);
    Vec3 drift;
    return det.clearly_no_detection(t, ref, drift);
  };
  for (const double a : {threshold / 2.1, 0.3 * threshold / 2.24}) {
    Blocks b = start;
    const int i = b.free_blocks[40], j = b.free_blocks[200], k = b.free_blocks[300];
    b.state.position[i].x() += a;
    b.state.position[j].y() += a;
    b.state.position[k].x() -= a;
    const bool exact = det.needs_detection(b, 0.0, false);
    EXPECT_EQ(exact, a > 0.5 * threshold / 2.1) << a;
    for (const Vec3& ref : {Vec3(Vec3::Zero()), Vec3(0, 0.5 * a, 0)})
      EXPECT_EQ(settled(b, ref), !exact) << "a " << a << ", ref " << ref.transpose();
  }
  const std::string deck =
      "[simulation]\nend_time = 0.01\n[joint]\nnormal_stiffness = 1e9\n[[block]]\nname = \"base\"\n"
      "shape = \"box\"\nsize = [2, 2, 0.5]\ncenter = [0, 0, -0.25]\nmotion = \"fixed\"\n[[block]]\n"
      "shape = \"box\"\nsize = [0.3, 0.3, 0.2]\ncenter = [0, 0, 0.1]\n";
  const SceneSpec one = parse_deck(deck, "block.toml");
  const Blocks pair = build_blocks(one.blocks);
  ContactDetector det2(pair, margin);
  ContactSet c2;
  det2.detect(pair, c2, false, make_joint_laws(pair, one.joint, {}));
  for (const double a : {1.5 * threshold, 0.3 * threshold}) {
    Blocks b = pair;
    b.state.position[1].x() += a;
    const bool exact = det2.needs_detection(b, 0.0, false);
    EXPECT_EQ(exact, a > threshold) << a;
    TravelBound t;
    det2.add_travels(b, 0, b.count, Vec3(0.5 * a, 0, 0), 0.0, t);
    Vec3 drift;
    EXPECT_EQ(det2.clearly_no_detection(t, Vec3(0.5 * a, 0, 0), drift), !exact) << a;
    EXPECT_EQ(drift, Vec3(0.5 * a, 0, 0));
  }
}

}  // namespace
}  // namespace polydem
