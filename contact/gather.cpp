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

void gather_block_force(const ContactSet& contacts, int i, const Vec3& x, Vec3& force, Vec3& torque) {
  const auto& off = contacts.gather_offset;
  const auto& idx = contacts.gather_sub;
  const auto& sign = contacts.gather_sign;
  const auto& sub = contacts.sub;
  Vec3 f = Vec3::Zero(), m = Vec3::Zero();
  for (int k = off[i]; k < off[i + 1]; ++k) {
    const int s = idx[k];
    const Vec3 fk = sign[k] * sub.force[s];
    f += fk;
    m += (sub.point[s] - x).cross(fk);
  }
  force = f;
  torque = m;
}

}  // namespace polydem
