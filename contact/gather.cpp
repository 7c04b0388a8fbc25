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

// In plain doubles, the operations of f += s·F, m += (p − x) × (s·F) one
// component at a time in Vec3's order: the same bits as the Eigen
// expressions it replaced, without their SSE2 shuffles between the packed
// and the scalar part of a Vec3 (9 % less time in the gather and update,
// docs/benchmarks.md).
void gather_block_force(const ContactSet& contacts, int i, const Vec3& x, Vec3& force, Vec3& torque) {
  const int* idx = contacts.gather_sub.data();
  const double* sign = contacts.gather_sign.data();
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are read as x y z per element");
  const double* F = reinterpret_cast<const double*>(contacts.sub.force.data());
  const double* P = reinterpret_cast<const double*>(contacts.sub.point.data());
  const double x0 = x.x(), x1 = x.y(), x2 = x.z();
  double f0 = 0, f1 = 0, f2 = 0, m0 = 0, m1 = 0, m2 = 0;
  for (int k = contacts.gather_offset[i], end = contacts.gather_offset[i + 1]; k < end; ++k) {
    const double* fs = F + 3 * static_cast<std::ptrdiff_t>(idx[k]);
    const double* ps = P + 3 * static_cast<std::ptrdiff_t>(idx[k]);
    const double g = sign[k];
    const double k0 = g * fs[0], k1 = g * fs[1], k2 = g * fs[2];
    f0 += k0;
    f1 += k1;
    f2 += k2;
    const double d0 = ps[0] - x0, d1 = ps[1] - x1, d2 = ps[2] - x2;
    m0 += d1 * k2 - d2 * k1;
    m1 += d2 * k0 - d0 * k2;
    m2 += d0 * k1 - d1 * k0;
  }
  force = Vec3(f0, f1, f2);
  torque = Vec3(m0, m1, m2);
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

}  // namespace polydem
