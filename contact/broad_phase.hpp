// Broad phase: which pairs of blocks are close enough to look at.
//
// FCL's dynamic AABB tree over the blocks' world boxes, each box grown by
// `grow` (half the contact margin) on every side, so that two blocks whose
// boxes overlap may be within the margin of each other. The boxes are exact
// (the world vertices' extent) and refitted at each call; fixed blocks are
// boxed once. Pairs of blocks that cannot move (fixed, kinematic) are never
// reported: nothing can change between them.
//
// The pairs come back as (lower index, higher index), sorted and without
// duplicates, whatever order the tree visits them in: detection downstream
// depends on that order, and a tree rebuilt after a restart finds the same
// pairs in the same order.
#pragma once

#include "core/blocks.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace polydem {

class BroadPhase {
 public:
  explicit BroadPhase(int blocks);
  ~BroadPhase();
  BroadPhase(const BroadPhase&) = delete;
  BroadPhase& operator=(const BroadPhase&) = delete;

  // Refits the boxes to the current state and writes the candidate pairs
  // (i < j, sorted, unique) into `pairs` (cleared first).
  void find_pairs(const Blocks& blocks, double grow, std::vector<std::pair<int, int>>& pairs);

 private:
  struct Impl;  // FCL stays inside broad_phase.cpp
  std::unique_ptr<Impl> impl_;
};

}  // namespace polydem
