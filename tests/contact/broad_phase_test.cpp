// BroadPhase: candidate pairs from the blocks' grown boxes, sorted, with
// pairs of blocks that cannot move left out.
//
// Scene (unit cubes resting on a fixed 10 × 1 × 1 base with its top at z = 0):
//   0 base (fixed), 1 cube at x = 3, 2 cube at x = 0, 3 cube at x = 1.005
//   (5 mm from cube 2), 4 a fixed block beside the base at x = 5.5.
// The boxes grow by 10 mm (half a 20 mm margin).
#include "contact/broad_phase.hpp"

#include "tests/support/blocks.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace polydem {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

constexpr double kGrow = 0.01;

using test::block_spec;

Blocks scene() {
  return build_blocks({block_spec("base", make_box(Vec3(10, 1, 1), Vec3(0, 0, -0.5)), BlockMotion::fixed),
                       block_spec("a", make_box(Vec3(1, 1, 1), Vec3(3, 0, 0.5)), BlockMotion::free),
                       block_spec("b", make_box(Vec3(1, 1, 1), Vec3(0, 0, 0.5)), BlockMotion::free),
                       block_spec("c", make_box(Vec3(1, 1, 1), Vec3(1.005, 0, 0.5)), BlockMotion::free),
                       block_spec("side", make_box(Vec3(1, 1, 1), Vec3(5.5, 0, -0.5)), BlockMotion::fixed)});
}

TEST(BroadPhase, FindsTheSortedPairsWithinTheGrownBoxes) {
  const Blocks b = scene();
  BroadPhase broad(b.count);
  Pairs pairs = {{7, 7}};  // cleared first
  broad.find_pairs(b, kGrow, pairs);
  // Each cube on the base, and the two cubes 5 mm apart; the two fixed
  // blocks touch but are never paired.
  EXPECT_EQ(pairs, (Pairs{{0, 1}, {0, 2}, {0, 3}, {2, 3}}));
}

TEST(BroadPhase, RefitsTheBoxesAfterABlockMoves) {
  Blocks b = scene();
  BroadPhase broad(b.count);
  Pairs pairs;
  broad.find_pairs(b, kGrow, pairs);
  // Cube 1 to 15 mm from cube 3 (closer than the two grown boxes' 20 mm).
  b.state.position[1].x() = 1.505 + 0.5 + 0.015;
  broad.find_pairs(b, kGrow, pairs);
  EXPECT_EQ(pairs, (Pairs{{0, 1}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}));
  // And 30 mm away: no longer a candidate.
  b.state.position[1].x() = 1.505 + 0.5 + 0.03;
  broad.find_pairs(b, kGrow, pairs);
  EXPECT_EQ(pairs, (Pairs{{0, 1}, {0, 2}, {0, 3}, {2, 3}}));
}

}  // namespace
}  // namespace polydem
