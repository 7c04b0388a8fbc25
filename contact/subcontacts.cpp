#include "contact/subcontacts.hpp"

#include <algorithm>

namespace polydem {

void Subcontacts::clear() { resize(0); }

void Subcontacts::resize(std::size_t n) {
  pair.resize(n);
  ref_block.resize(n);
  inc_block.resize(n);
  key.resize(n);
  ref_normal_local.resize(n);
  ref_offset_local.resize(n);
  inc_point_local.resize(n);
  area.resize(n);
  shear_force.resize(n);
  bonded.resize(n);
  force.resize(n);
  point.resize(n);
  overlap.resize(n);
  normal_force.resize(n);
  slip_energy.resize(n);
  damping_energy.resize(n);
  damping_force.resize(n);
}

void ContactSet::save(ByteWriter& w) const {
  w.put(static_cast<std::uint64_t>(pairs.size()));
  for (const ContactPair& p : pairs) {
    w.put(p.a);
    w.put(p.b);
    w.put(p.ref_block);
    w.put(p.ref_face);
    w.put(p.inc_face);
    w.put(p.first);
    w.put(p.count);
    w.put(p.patch_area);
  }
  w.put(sub.pair);
  w.put(sub.ref_block);
  w.put(sub.inc_block);
  w.put(sub.key);
  w.put(sub.ref_normal_local);
  w.put(sub.ref_offset_local);
  w.put(sub.inc_point_local);
  w.put(sub.area);
  w.put(sub.shear_force);
  w.put(sub.bonded);
  w.put(sub.force);
  w.put(sub.point);
  w.put(sub.overlap);
  w.put(sub.normal_force);
  w.put(sub.slip_energy);
  w.put(sub.damping_energy);
  w.put(sub.damping_force);
  w.put(gather_offset);
  w.put(gather_sub);
  w.put(gather_sign);
  w.put(retired_slip_energy);
  w.put(retired_damping_energy);
  w.put(detections);
}

void ContactSet::load(ByteReader& r, int blocks) {
  std::uint64_t np = 0;
  r.get(np);
  if (np > r.remaining() / 36) throw StateFormatError("contact pairs: count beyond the data");
  pairs.resize(static_cast<std::size_t>(np));
  for (ContactPair& p : pairs) {
    r.get(p.a);
    r.get(p.b);
    r.get(p.ref_block);
    r.get(p.ref_face);
    r.get(p.inc_face);
    r.get(p.first);
    r.get(p.count);
    r.get(p.patch_area);
  }
  r.get(sub.pair);
  const std::size_t n = sub.pair.size();
  r.get_sized(sub.ref_block, n, "subcontacts.ref_block");
  r.get_sized(sub.inc_block, n, "subcontacts.inc_block");
  r.get_sized(sub.key, n, "subcontacts.key");
  r.get_sized(sub.ref_normal_local, n, "subcontacts.ref_normal_local");
  r.get_sized(sub.ref_offset_local, n, "subcontacts.ref_offset_local");
  r.get_sized(sub.inc_point_local, n, "subcontacts.inc_point_local");
  r.get_sized(sub.area, n, "subcontacts.area");
  r.get_sized(sub.shear_force, n, "subcontacts.shear_force");
  r.get_sized(sub.bonded, n, "subcontacts.bonded");
  r.get_sized(sub.force, n, "subcontacts.force");
  r.get_sized(sub.point, n, "subcontacts.point");
  r.get_sized(sub.overlap, n, "subcontacts.overlap");
  r.get_sized(sub.normal_force, n, "subcontacts.normal_force");
  r.get_sized(sub.slip_energy, n, "subcontacts.slip_energy");
  r.get_sized(sub.damping_energy, n, "subcontacts.damping_energy");
  r.get_sized(sub.damping_force, n, "subcontacts.damping_force");
  r.get_sized(gather_offset, static_cast<std::size_t>(blocks) + 1, "contacts.gather_offset");
  r.get_sized(gather_sub, 2 * n, "contacts.gather_sub");
  r.get_sized(gather_sign, 2 * n, "contacts.gather_sign");
  r.get(retired_slip_energy);
  r.get(retired_damping_energy);
  r.get(detections);

  // Indices in range: a checkpoint that passed its checksum but was written
  // for another scene must not index out of bounds.
  auto block_ok = [&](int b) { return b >= 0 && b < blocks; };
  for (const ContactPair& p : pairs)
    if (!block_ok(p.a) || !block_ok(p.b) || !block_ok(p.ref_block) || p.first < 0 || p.count < 0 ||
        static_cast<std::size_t>(p.first) + static_cast<std::size_t>(p.count) > n)
      throw StateFormatError("contact pair out of range");
  for (std::size_t s = 0; s < n; ++s)
    if (sub.pair[s] < 0 || static_cast<std::size_t>(sub.pair[s]) >= pairs.size() || !block_ok(sub.ref_block[s]) ||
        !block_ok(sub.inc_block[s]))
      throw StateFormatError("subcontact out of range");
  if (gather_offset.front() != 0 || static_cast<std::size_t>(gather_offset.back()) != 2 * n)
    throw StateFormatError("gather lists out of range");
  for (int i = 0; i < blocks; ++i)
    if (gather_offset[i] > gather_offset[i + 1]) throw StateFormatError("gather lists out of order");
  for (int q : gather_sub)
    if (q < 0 || static_cast<std::size_t>(q) >= n) throw StateFormatError("gather list out of range");
}

const ContactPair* find_pair(const ContactSet& set, int a, int b) {
  auto it = std::lower_bound(set.pairs.begin(), set.pairs.end(), std::make_pair(a, b),
                             [](const ContactPair& p, const std::pair<int, int>& k) {
                               return std::make_pair(p.a, p.b) < k;
                             });
  return (it != set.pairs.end() && it->a == a && it->b == b) ? &*it : nullptr;
}

std::uint64_t subcontact_key(int ref_side, int ref_face, int inc_face, std::uint32_t feature) {
  return (static_cast<std::uint64_t>(ref_side & 1) << 63) |
         (static_cast<std::uint64_t>(ref_face & 0x7FFF) << 48) |
         (static_cast<std::uint64_t>(inc_face & 0xFFFF) << 32) | feature;
}

void build_subcontacts(const Blocks& b, const std::vector<std::pair<int, int>>& candidates,
                       const std::vector<Patch>& patches, const std::vector<char>& found, bool bond_new,
                       ContactSet& contacts) {
  const std::size_t nc = candidates.size();
  contacts.pairs.clear();
  std::size_t total = 0;
  for (std::size_t k = 0; k < nc; ++k)
    if (found[k]) total += patches[k].points.size();
  Subcontacts& sc = contacts.sub;
  sc.resize(total);
  std::size_t s = 0;
  for (std::size_t k = 0; k < nc; ++k) {
    if (!found[k]) continue;
    const auto [i, j] = candidates[k];
    const Patch& patch = patches[k];
    ContactPair cp;
    cp.a = i;
    cp.b = j;
    cp.ref_block = patch.ref_side == 0 ? i : j;
    const int inc = patch.ref_side == 0 ? j : i;
    cp.ref_face = patch.ref_face;
    cp.inc_face = patch.inc_face;
    cp.first = static_cast<int>(s);
    cp.count = static_cast<int>(patch.points.size());
    cp.patch_area = patch.area;
    const Mat3& Rr = b.state.rotation[cp.ref_block];
    const Mat3& Ri = b.state.rotation[inc];
    const Vec3 n_local = Rr.transpose() * patch.normal;
    const double off_local = patch.offset - patch.normal.dot(b.state.position[cp.ref_block]);
    for (const PatchPoint& pt : patch.points) {
      sc.pair[s] = static_cast<int>(contacts.pairs.size());
      sc.ref_block[s] = cp.ref_block;
      sc.inc_block[s] = inc;
      sc.key[s] = subcontact_key(patch.ref_side, patch.ref_face, patch.inc_face, pt.feature);
      sc.ref_normal_local[s] = n_local;
      sc.ref_offset_local[s] = off_local;
      sc.inc_point_local[s] = Ri.transpose() * (pt.point - b.state.position[inc]);
      sc.area[s] = pt.area;
      sc.shear_force[s] = Vec3::Zero();
      sc.bonded[s] = bond_new ? 1 : 0;
      sc.slip_energy[s] = 0;
      sc.damping_energy[s] = 0;
      sc.damping_force[s] = Vec3::Zero();
      sc.force[s] = Vec3::Zero();
      sc.point[s] = pt.point;
      sc.overlap[s] = -pt.separation;
      sc.normal_force[s] = 0;
      ++s;
    }
    contacts.pairs.push_back(cp);
  }
}

void carry_history(const ContactSet& old, ContactSet& contacts, std::vector<char>& old_used) {
  Subcontacts& sc = contacts.sub;
  old_used.assign(old.sub.size(), 0);
  for (const ContactPair& cp : contacts.pairs) {
    const ContactPair* op = find_pair(old, cp.a, cp.b);
    if (!op) continue;
    for (int s = cp.first; s < cp.first + cp.count; ++s) {
      for (int o = op->first; o < op->first + op->count; ++o) {
        if (old.sub.key[o] != sc.key[s] || old_used[o]) continue;
        old_used[o] = 1;
        // The shear history is the elastic shear displacement F_s/(ks·A): carry
        // it, so the force scales with the new tributary area. Carrying the
        // force onto a much smaller area (a patch clipped to a sliver) would
        // store F_s²/(2·ks·A) of strain energy from nowhere, which the next
        // step books as slip (the spire's collapse: 0.6 MJ at once).
        const double a_old = old.sub.area[o];
        sc.shear_force[s] = a_old > 0 ? Vec3(old.sub.shear_force[o] * (sc.area[s] / a_old)) : Vec3::Zero();
        sc.bonded[s] = old.sub.bonded[o];
        sc.slip_energy[s] = old.sub.slip_energy[o];
        sc.damping_energy[s] = old.sub.damping_energy[o];
        break;
      }
    }
  }
  contacts.retired_slip_energy = old.retired_slip_energy;
  contacts.retired_damping_energy = old.retired_damping_energy;
  for (std::size_t o = 0; o < old.sub.size(); ++o) {
    if (old_used[o]) continue;
    contacts.retired_slip_energy += old.sub.slip_energy[o];
    contacts.retired_damping_energy += old.sub.damping_energy[o];
  }
}

}  // namespace polydem
