// How the step's threads share pairs and blocks (integrators/thread_split.hpp):
// every block in exactly one thread's range for any thread count, a
// thread's blocks starting at the first block of its pairs where that is
// near the even split, and the even split kept roughly where the pairs
// crowd onto one block or there are none.
#include "integrators/thread_split.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace polydem {
namespace {

// Pairs (a, b), a < b, in block order, as the detection hands them over.
std::vector<ContactPair> pairs_of(std::vector<std::pair<int, int>> ab) {
  std::sort(ab.begin(), ab.end());
  std::vector<ContactPair> out;
  for (const auto& [a, b] : ab) {
    ContactPair p;
    p.a = a;
    p.b = b;
    out.push_back(p);
  }
  return out;
}

// The ranges [split(t), split(t + 1)) cover 0 .. blocks in order.
void expect_partition(const std::vector<ContactPair>& pairs, int blocks, int nt) {
  std::vector<int> owner(static_cast<std::size_t>(blocks), -1);
  for (int t = 0; t < nt; ++t) {
    const int begin = block_split(pairs, blocks, nt, t), end = block_split(pairs, blocks, nt, t + 1);
    ASSERT_LE(begin, end) << "thread " << t << " of " << nt;
    for (int i = begin; i < end; ++i) {
      EXPECT_EQ(owner[static_cast<std::size_t>(i)], -1) << "block " << i << " twice";
      owner[static_cast<std::size_t>(i)] = t;
    }
  }
  for (int i = 0; i < blocks; ++i) EXPECT_GE(owner[static_cast<std::size_t>(i)], 0) << "block " << i << " missed";
}

TEST(ThreadSplit, EveryBlockOnceForAnyThreadCount) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int blocks = 1 + static_cast<int>(rng() % 500);
    std::vector<std::pair<int, int>> ab;
    const int n = static_cast<int>(rng() % (3 * blocks + 1));
    for (int k = 0; k < n && blocks > 1; ++k) {
      // Crowded onto a few blocks in some trials (a ground first in the pairs).
      const int a = trial % 4 == 0 ? static_cast<int>(rng() % 2) : static_cast<int>(rng() % (blocks - 1));
      const int b = a + 1 + static_cast<int>(rng() % (blocks - a - 1));
      ab.emplace_back(a, b);
    }
    const auto pairs = pairs_of(ab);
    for (int nt = 1; nt <= 9; ++nt) expect_partition(pairs, blocks, nt);
  }
  expect_partition({}, 0, 2);
  expect_partition({}, 7, 2);
  expect_partition({}, 3, 8);
}

TEST(ThreadSplit, BlocksFollowThePairsNearTheEvenSplit) {
  // A chain of 400 blocks, each with its next: pair k is (k, k + 1); but the
  // first 30 blocks also touch their second neighbour, so the pairs' middle
  // falls at block 185, before the blocks' middle and within the slack.
  std::vector<std::pair<int, int>> ab;
  for (int k = 0; k + 1 < 400; ++k) ab.emplace_back(k, k + 1);
  for (int k = 0; k < 30; ++k) ab.emplace_back(k, k + 2);
  const auto pairs = pairs_of(ab);
  const int split = block_split(pairs, 400, 2, 1);
  EXPECT_EQ(split, pairs[thread_range(pairs.size(), std::size_t(2), std::size_t(1)).first].a);
  EXPECT_EQ(split, 185);
}

TEST(ThreadSplit, PairsOnOneGroundOrNoneKeepTheBlocksShared) {
  // 200 stones on a ground (block 0), each also touching the next: half the
  // pairs are (0, j), so the pairs' middle is at block 0 or 1.
  std::vector<std::pair<int, int>> ab;
  for (int j = 1; j <= 200; ++j) ab.emplace_back(0, j);
  for (int j = 1; j < 200; ++j) ab.emplace_back(j, j + 1);
  const auto pairs = pairs_of(ab);
  EXPECT_EQ(block_split(pairs, 201, 2, 1), 101 - 201 / 16) << "the even split less the slack";
  EXPECT_EQ(block_split({}, 201, 2, 1), 101 + 201 / 16) << "no pairs: the even split plus the slack";
}

}  // namespace
}  // namespace polydem
