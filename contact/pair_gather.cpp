#include "contact/pair_gather.hpp"

namespace polydem {

void PairGather::build(const std::vector<ContactPair>& pairs, int n, const std::vector<int>* ref_block) {
  block_offset.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const ContactPair& cp : pairs) {
    ++block_offset[static_cast<std::size_t>(cp.a) + 1];
    ++block_offset[static_cast<std::size_t>(cp.b) + 1];
  }
  for (int i = 0; i < n; ++i) block_offset[i + 1] += block_offset[i];
  block_pair.resize(static_cast<std::size_t>(block_offset[n]));
  std::vector<int> next(block_offset.begin(), block_offset.end() - 1);
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    const ContactPair& cp = pairs[q];
    const int ref = ref_block ? (*ref_block)[q] : cp.ref_block;
    for (const int b : {cp.a, cp.b})
      block_pair[static_cast<std::size_t>(next[b]++)] = 2 * static_cast<int>(q) + (b == ref ? 1 : 0);
  }
}

void PairGather::sum(int i, const std::vector<lanes::PairRest>& wrench, Vec3& force, Vec3& torque) const {
  double f0 = 0, f1 = 0, f2 = 0, m0 = 0, m1 = 0, m2 = 0;
  for (int k = block_offset[i]; k < block_offset[i + 1]; ++k) {
    const int e = block_pair[k];
    const lanes::PairRest& p = wrench[static_cast<std::size_t>(e >> 1)];
    if (e & 1) {  // the reference block: the reaction
      f0 -= p.force[0];
      f1 -= p.force[1];
      f2 -= p.force[2];
      m0 += p.moment_ref[0];
      m1 += p.moment_ref[1];
      m2 += p.moment_ref[2];
    } else {
      f0 += p.force[0];
      f1 += p.force[1];
      f2 += p.force[2];
      m0 += p.moment[0];
      m1 += p.moment[1];
      m2 += p.moment[2];
    }
  }
  force = Vec3(f0, f1, f2);
  torque = Vec3(m0, m1, m2);
}

}  // namespace polydem
