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

}  // namespace
}  // namespace polydem
