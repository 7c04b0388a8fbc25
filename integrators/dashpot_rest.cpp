#include "integrators/dashpot_rest.hpp"

#include "integrators/critical_time_step.hpp"
#include "integrators/split_damping.hpp"

namespace polydem {

void DashpotRest::set_step(double dt, double beta, double safety_factor, int blocks) {
  fraction = 0;
  const std::size_t n = static_cast<std::size_t>(blocks);
  work.resize(n, 0.0);
  pending.resize(n, 0.0);
  if (!(beta > 0)) return;  // nothing to split: the explicit step, one pass
  const double omega = highest_frequency_for_step(dt, beta, safety_factor, DampingScheme::split);
  fraction = split_damping(0.5 * beta * omega).fraction;
  velocity_next.resize(n, Vec3::Zero());
  omega_next.resize(n, Vec3::Zero());
  force.resize(n, Vec3::Zero());
  torque.resize(n, Vec3::Zero());
}

void DashpotRest::size_for(const ContactSet& contacts, int n) {
  dashpot_state.resize(contacts.sub.size());
  force_sub.resize(contacts.sub.size());
  pair_rest.resize(contacts.pairs.size());
  block_offset.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const ContactPair& cp : contacts.pairs) {
    ++block_offset[static_cast<std::size_t>(cp.a) + 1];
    ++block_offset[static_cast<std::size_t>(cp.b) + 1];
  }
  for (int i = 0; i < n; ++i) block_offset[i + 1] += block_offset[i];
  block_pair.resize(static_cast<std::size_t>(block_offset[n]));
  std::vector<int> next(block_offset.begin(), block_offset.end() - 1);
  for (std::size_t q = 0; q < contacts.pairs.size(); ++q) {
    const ContactPair& cp = contacts.pairs[q];
    for (const int b : {cp.a, cp.b})
      block_pair[static_cast<std::size_t>(next[b]++)] = 2 * static_cast<int>(q) + (b == cp.ref_block ? 1 : 0);
  }
}

void DashpotRest::gather(int i, BlockState& st) {
  double f0 = 0, f1 = 0, f2 = 0, m0 = 0, m1 = 0, m2 = 0;
  for (int k = block_offset[i]; k < block_offset[i + 1]; ++k) {
    const int e = block_pair[k];
    const lanes::PairRest& p = pair_rest[static_cast<std::size_t>(e >> 1)];
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
  force[i] = Vec3(f0, f1, f2);
  torque[i] = Vec3(m0, m1, m2);
  st.contact_force[i] += force[i];
  st.contact_torque[i] += torque[i];
}

void DashpotRest::book_work(int i, const BlockState& st, const LedgerKinematics& ledger, double dt) {
  const double half = 0.5 * dt;
  const Vec3& v = st.velocity[i];
  const Vec3& w = st.angular_velocity[i];
  const Vec3 v_before = 2.0 * ledger.velocity_mid[i] - v, w_before = 2.0 * ledger.omega_mid[i] - w;
  work[i] += pending[i] + half * (force[i].dot(v_before) + torque[i].dot(w_before));
  pending[i] = half * (force[i].dot(v) + torque[i].dot(w));
}

}  // namespace polydem
