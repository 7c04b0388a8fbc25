#include "integrators/energy_ledger.hpp"

#include "contact/overlap_joint.hpp"

namespace polydem {

void LedgerKinematics::start(const BlockState& st) {
  velocity_mid = st.velocity;
  omega_mid = st.angular_velocity;
  position_prev = st.position;
  orientation_prev = st.orientation;
  load_work.assign(st.position.size(), 0.0);
}

void LedgerKinematics::save(ByteWriter& w) const {
  w.put(velocity_mid);
  w.put(omega_mid);
  w.put(position_prev);
  w.put(orientation_prev);
  w.put(load_work);
}

void LedgerKinematics::load(ByteReader& r, std::size_t n) {
  r.get_sized(velocity_mid, n, "velocity_mid");
  r.get_sized(omega_mid, n, "omega_mid");
  r.get_sized(position_prev, n, "position_prev");
  r.get_sized(orientation_prev, n, "orientation_prev");
  r.get_sized(load_work, n, "load_work");
}

EnergyLedger energies(const Blocks& blocks, const LedgerKinematics& k, const JointLaws& laws,
                      const ContactSet& contacts, const std::vector<double>& rest_work, const Vec3& gravity) {
  EnergyLedger e;
  const auto& pr = blocks.props;
  const auto& st = blocks.state;
  for (int i : blocks.free_blocks) {
    const double m = pr.mass[i];
    // velocity_mid is the mean of the two half steps; the state holds v₊.
    const Vec3 v_before = 2.0 * k.velocity_mid[i] - st.velocity[i];
    e.kinetic += 0.5 * m * v_before.dot(st.velocity[i]);
    const Vec3 wb0 = st.rotation[i].transpose() * (2.0 * k.omega_mid[i] - st.angular_velocity[i]);
    const Vec3 wb1 = st.rotation[i].transpose() * st.angular_velocity[i];
    e.kinetic += 0.5 * wb0.dot(pr.principal_inertia[i].cwiseProduct(wb1));
    e.gravitational += -m * gravity.dot(k.position_prev[i] - blocks.initial_position[i]);
  }
  if (contacts.pair_joints_in_use()) {
    const PairJointEnergies j = pair_joint_energies(contacts);
    e.strain = j.strain;
    e.slip = j.slip;
    e.damping = j.damping;
  } else {
    e.strain = joint_strain_energy(laws, contacts.sub);
    e.slip = contacts.retired_slip_energy;
    e.damping = contacts.retired_damping_energy;
    for (std::size_t s = 0; s < contacts.sub.size(); ++s) {
      e.slip += contacts.sub.slip_energy[s];
      e.damping += contacts.sub.damping_energy[s];
    }
  }
  for (double w : rest_work) e.damping -= w;
  for (double w : k.load_work) e.load_work += w;
  e.balance = e.kinetic + e.gravitational + e.strain + e.slip + e.damping - e.load_work;
  return e;
}

}  // namespace polydem
