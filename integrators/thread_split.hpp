// How the step's threads share the work: each thread one contiguous range
// of the pairs (the joint law) and one of the blocks (the gather and the
// update), so that a thread moves the blocks whose joint forces it has
// just computed. The pairs are in block order (ContactPair::a, the
// detection's candidate order), so thread t's blocks start at the first
// block of its pairs; only the joints across a split then cross between
// the cores (a cache line takes tens of nanoseconds one way). That start is kept within n/(8·nt) blocks
// of the even split, so that a scene whose pairs crowd onto a few blocks
// (a row of stones on one ground block, the ground first) still shares its
// blocks out; clamping a non-decreasing sequence into non-decreasing
// windows keeps the ranges in order, so every block is in exactly one.
#pragma once

#include "contact/subcontacts.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace polydem {

// Thread t's share of n items among nt threads: one contiguous range each.
template <class I>
std::pair<I, I> thread_range(I n, I nt, I t) {
  const I chunk = (n + nt - 1) / nt;
  const I begin = std::min(n, t * chunk);
  return {begin, std::min(n, begin + chunk)};
}

// Where thread t's blocks start among `blocks` (t = 0: 0, t = nt: blocks),
// its pairs being thread_range(pairs.size(), nt, t).
inline int block_split(const std::vector<ContactPair>& pairs, int blocks, int nt, int t) {
  if (t <= 0) return 0;
  if (t >= nt) return blocks;
  const std::size_t np = pairs.size();
  const std::size_t first = thread_range(np, static_cast<std::size_t>(nt), static_cast<std::size_t>(t)).first;
  const int at = first < np ? pairs[first].a : blocks;
  const int even = thread_range(blocks, nt, t).first;
  const int slack = blocks / (8 * nt);
  return std::clamp(at, std::max(0, even - slack), std::min(blocks, even + slack));
}

}  // namespace polydem
