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
  pairs.build(contacts.pairs, n);
}

void DashpotRest::gather(int i, BlockState& st) {
  pairs.sum(i, pair_rest, force[i], torque[i]);
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
