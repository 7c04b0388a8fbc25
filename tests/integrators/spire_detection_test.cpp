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
  const JointLaws laws(make_joint_law(spec.joint));
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
  const CriticalStep full1 = critical_time_step_from_contacts(blocks, c1, laws, spec.joint, 0.8, 0, 1);
  const CriticalStep full2 = critical_time_step_from_contacts(blocks, c1, laws, spec.joint, 0.8, 0, 2);
  EXPECT_EQ(full1.chosen, full2.chosen);
  EXPECT_EQ(full1.omega_max, full2.omega_max);
  EXPECT_EQ(full1.governing_block, full2.governing_block);
  for (const double f : {0.5, 1.0 + 1e-12, 2.0}) {
    const CriticalStep a = critical_time_step_from_contacts(blocks, c1, laws, spec.joint, 0.8, f * full1.chosen, 1);
    const CriticalStep b = critical_time_step_from_contacts(blocks, c1, laws, spec.joint, 0.8, f * full1.chosen, 2);
    EXPECT_EQ(a.chosen, b.chosen) << f;
    EXPECT_EQ(a.omega_max, b.omega_max) << f;
    EXPECT_EQ(a.governing_block, b.governing_block) << f;
  }
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
  det.detect(start, contacts, false, JointLaws(make_joint_law(spec.joint)));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
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
      if (tight) {
        b.state.position[i].x() += scale * u(rng);
        continue;
      }
      b.state.position[i] += scale * Vec3(u(rng), u(rng), u(rng));
      const Vec3 turn = (scale / b.props.radius[i]) * Vec3(u(rng), u(rng), u(rng));
      b.state.orientation[i] =
          (Quat(Eigen::AngleAxisd(turn.norm(), turn.normalized())) * b.state.orientation[i]).normalized();
      if (trial % 2) b.state.orientation[i].coeffs() *= -1.0;  // the same turn, the other sign
      b.state.velocity[i] = (scale / 1e-4) * Vec3(u(rng), u(rng), u(rng));
      b.state.angular_velocity[i] = (scale / 1e-4 / b.props.radius[i]) * Vec3(u(rng), u(rng), u(rng));
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

}  // namespace
}  // namespace polydem
