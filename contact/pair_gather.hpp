// Gather by pair: each block's sum of the wrenches of its joints taken whole.
//
// Where a joint's result is one wrench per pair (the split damping scheme's
// rest of the dashpots, integrators/dashpot_rest.hpp; the overlap joint
// model, contact/overlap_joint.hpp) rather than one force per subcontact,
// each block sums its pairs' wrenches over a CSR list (block_offset[i] ..
// block_offset[i+1] of block_pair), in pair order, fixed at each detection:
// the same bits for any number of threads, as the subcontact gather
// (gather.hpp).
#pragma once

#include "contact/joint_law_kernels.hpp"
#include "contact/subcontacts.hpp"

#include <vector>

namespace polydem {

struct PairGather {
  std::vector<int> block_offset;  // blocks + 1
  std::vector<int> block_pair;    // 2·pair, + 1 where the block is the pair's reference block

  // The lists of `blocks` blocks for `pairs`, each pair's reference block
  // its own or, when given, ref_block[pair].
  void build(const std::vector<ContactPair>& pairs, int blocks, const std::vector<int>* ref_block = nullptr);
  // Block i's sum of `wrench` (per pair: force on the incident block, its
  // moment about that block's centroid, the reaction's moment about the
  // reference block's): the force on block i and its moment about block i's
  // centroid.
  void sum(int i, const std::vector<lanes::PairRest>& wrench, Vec3& force, Vec3& torque) const;
};

}  // namespace polydem
