#include "contact/gather.hpp"

#include <algorithm>

namespace polydem {

void build_gather_lists(int n, ContactSet& contacts, std::vector<int>& cnt) {
  const Subcontacts& sc = contacts.sub;
  const std::size_t total = sc.size();
  cnt.assign(n + 1, 0);
  for (std::size_t q = 0; q < total; ++q) {
    ++cnt[sc.inc_block[q] + 1];
    ++cnt[sc.ref_block[q] + 1];
  }
  contacts.gather_offset.resize(n + 1);
  contacts.gather_offset[0] = 0;
  for (int i = 0; i < n; ++i) contacts.gather_offset[i + 1] = contacts.gather_offset[i] + cnt[i + 1];
  contacts.gather_sub.resize(2 * total);
  contacts.gather_sign.resize(2 * total);
  std::copy(contacts.gather_offset.begin(), contacts.gather_offset.end() - 1, cnt.begin());
  for (std::size_t q = 0; q < total; ++q) {
    int& pi = cnt[sc.inc_block[q]];
    contacts.gather_sub[pi] = static_cast<int>(q);
    contacts.gather_sign[pi++] = 1.0;
    int& pr = cnt[sc.ref_block[q]];
    contacts.gather_sub[pr] = static_cast<int>(q);
    contacts.gather_sign[pr++] = -1.0;
  }
}

gather_lanes::GatherArrays gather_lane_arrays(const ContactSet& contacts, const std::vector<Vec3>& centroid,
                                              std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are read as x y z per element");
  gather_lanes::GatherArrays a;
  a.offset = contacts.gather_offset.data();
  a.entry = contacts.gather_sub.data();
  a.sign = contacts.gather_sign.data();
  a.force = reinterpret_cast<const double*>(contacts.sub.force.data());
  a.point = reinterpret_cast<const double*>(contacts.sub.point.data());
  a.centroid = reinterpret_cast<const double*>(centroid.data());
  a.contact_force = reinterpret_cast<double*>(force.data());
  a.contact_torque = reinterpret_cast<double*>(torque.data());
  return a;
}

gather_lanes::GatherKernels gather_kernels(CodePath path) {
#ifdef POLYDEM_LANES_AVX2
  if (use_lanes(path)) return {&gather_lanes::gather_block_avx2, &gather_lanes::gather_two_avx2};
#endif
  return {&gather_lanes::gather_block_portable, &gather_lanes::gather_two_portable};
}

}  // namespace polydem
