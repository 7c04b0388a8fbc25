#include "integrators/block_update.hpp"

#include "core/loads.hpp"
#include "integrators/rotation.hpp"

#include <algorithm>

namespace polydem {

namespace {

// Block k's share of the pairs' clip rest (joint_sampling = "clip") added
// to its gathered force and moment.
void add_clip_rest(const BlockUpdate& u, int k) {
  Vec3 f, m;
  u.clip_gather->sum(k, *u.clip_rest, f, m);
  u.blocks.state.contact_force[k] += f;
  u.blocks.state.contact_torque[k] += m;
}

// Blocks i and i + 1 (when below end) gathered, two sums in flight.
void gather_two_blocks(const BlockUpdate& u, int i, int end) {
  auto& st = u.blocks.state;
  if (u.pair_gather) {
    for (int k = i; k < std::min(i + 2, end); ++k)
      u.pair_gather->sum(k, *u.pair_wrench, st.contact_force[k], st.contact_torque[k]);
    return;
  }
  const gather_lanes::GatherArrays a = gather_lane_arrays(u.contacts, st.position, st.contact_force, st.contact_torque);
  if (i + 1 < end)
    u.gather.two(a, i, i + 1);
  else
    u.gather.block(a, i);
  if (u.clip_gather)
    for (int k = i; k < std::min(i + 2, end); ++k) add_clip_rest(u, k);
}

// Free block i's force and moment at the step's time, and the inverse mass
// and principal inertia its update uses. With kLocalDamping (the static
// stage only) the force and the moment are first reduced by Cundall's local
// damping against the velocities at t − dt/2, and the stage's inertia
// (static_stage.hpp) is used; without it the update is the plain one, at no cost.
template <bool kLocalDamping>
[[gnu::always_inline]] inline void block_load(const BlockUpdate& u, int i, Vec3& force, Vec3& torque, double& inv_m,
                                              const Vec3*& inv_I) {
  const auto& st = u.blocks.state;
  const auto& pr = u.blocks.props;
  force = external_force(pr, i, u.step.gravity, u.step.a_ground) + st.contact_force[i];
  torque = st.contact_torque[i];
  const bool loaded = u.loads.on(i) && !u.stage.active;
  if (loaded) {  // the point loads: the sum's last term
    force += u.loads.force[i];
    torque += u.loads.torque[i];
  }
  if constexpr (kLocalDamping) {
    force = locally_damped(force, st.velocity[i], u.stage.local_damping);
    torque = locally_damped(torque, st.angular_velocity[i], u.stage.local_damping);
  }
  inv_m = pr.inv_mass[i];
  inv_I = &pr.inv_principal_inertia[i];
  if constexpr (kLocalDamping) {
    if (!u.stage.scaled_inv_mass.empty()) {  // the static stage's inertia
      inv_m = u.stage.scaled_inv_mass[i];
      inv_I = &u.stage.scaled_inv_inertia[i];
    }
  }
}

// Central differences for one free block (the header), with every load term.
template <bool kLocalDamping>
void advance_block(BlockUpdate& u, int i) {
  auto& st = u.blocks.state;
  const auto& pr = u.blocks.props;
  auto& ledger = u.ledger;
  const double dt = u.clock.dt;
  const double dv_dt = 0.5 * (u.clock.dt_prev + u.clock.dt);  // span of the velocity update
  const Vec3& a_ground = u.step.a_ground;
  Vec3 force, torque;
  double inv_m;
  const Vec3* inv_I_p;
  block_load<kLocalDamping>(u, i, force, torque, inv_m, inv_I_p);
  const bool loaded = u.loads.on(i) && !u.stage.active;
  const Vec3& inv_I = *inv_I_p;
  const Vec3 v_old = st.velocity[i];
  const Vec3 v_new = v_old + (dv_dt * inv_m) * force;
  const Vec3 L_new = st.angular_momentum[i] + dv_dt * torque;
  // ω at the half step: predict the half-step orientation, then evaluate.
  const Mat3& R0 = st.rotation[i];
  const Vec3 w0 = R0 * inv_I.cwiseProduct(R0.transpose() * L_new);
  const Mat3 Rh = (rotation_quaternion(0.5 * dt * w0) * st.orientation[i]).toRotationMatrix();
  const Vec3 w = Rh * inv_I.cwiseProduct(Rh.transpose() * L_new);
  const Vec3 w_old = st.angular_velocity[i];

  ledger.velocity_mid[i] = 0.5 * (v_old + v_new);
  ledger.omega_mid[i] = 0.5 * (w_old + w);
  ledger.position_prev[i] = st.position[i];
  ledger.orientation_prev[i] = st.orientation[i];
  // Gravity's work is the ledger's potential energy: only the ground's counts.
  ledger.load_work[i] += load_work(dt, ground_inertial_force(pr.mass[i], a_ground), ledger.velocity_mid[i]);
  // Under a rising gravity the ledger's potential counts m·g: the rest of
  // the applied weight, m·(g(t) − g), is a load.
  if (u.step.rising)
    ledger.load_work[i] += load_work(dt, pr.mass[i] * (u.step.gravity - u.gravity), ledger.velocity_mid[i]);
  // The point loads' work over the step that ends at the force time, by the
  // trapezoid: ½(F(t) + F(t − dt))·(x(t) − x(t − dt)), and the same for the
  // torque and the turn. It is the leapfrog's own: with the ledger's
  // kinetic energy ½·m·v₋·v₊, ½m·v₋(t)·(v₊(t) − v₋(t − dt)) is exactly
  // that, so a load of any history keeps the balance to round-off (the
  // mid-step dt·F·v(t) runs half a step ahead of the kinetic energy).
  if (loaded) {
    AppliedLoads& l = u.loads;
    if (u.clock.steps > 0)
      ledger.load_work[i] += 0.5 * (l.force[i] + l.force_prev[i]).dot(u.clock.dt_prev * v_old) +
                             0.5 * (l.torque[i] + l.torque_prev[i]).dot(u.clock.dt_prev * st.angular_velocity[i]);
    l.force_prev[i] = l.force[i];
    l.torque_prev[i] = l.torque[i];
  }

  st.velocity[i] = v_new;
  st.angular_momentum[i] = L_new;
  st.angular_velocity[i] = w;
  st.position[i] += dt * v_new;
  st.orientation[i] = (rotation_quaternion(dt * w) * st.orientation[i]).normalized();
  st.rotation[i] = st.orientation[i].toRotationMatrix();
}

block_lanes::BlockArrays block_lane_arrays(BlockUpdate& u) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double) &&
                    sizeof(Mat3) == 9 * sizeof(double),
                "the block arrays are read as plain doubles");
  // The records as doubles (no element is touched: an empty array is fine).
  auto& st = u.blocks.state;
  const auto& pr = u.blocks.props;
  block_lanes::BlockArrays a;
  a.position = reinterpret_cast<double*>(st.position.data());
  a.velocity = reinterpret_cast<double*>(st.velocity.data());
  a.angular_momentum = reinterpret_cast<double*>(st.angular_momentum.data());
  a.angular_velocity = reinterpret_cast<double*>(st.angular_velocity.data());
  a.orientation = reinterpret_cast<double*>(st.orientation.data());
  a.rotation = reinterpret_cast<double*>(st.rotation.data());
  a.contact_force = reinterpret_cast<double*>(st.contact_force.data());
  a.contact_torque = reinterpret_cast<double*>(st.contact_torque.data());
  a.mass = pr.mass.data();
  a.inv_mass = pr.inv_mass.data();
  a.inv_inertia = reinterpret_cast<const double*>(pr.inv_principal_inertia.data());
  a.velocity_mid = reinterpret_cast<double*>(u.ledger.velocity_mid.data());
  a.omega_mid = reinterpret_cast<double*>(u.ledger.omega_mid.data());
  a.position_prev = reinterpret_cast<double*>(u.ledger.position_prev.data());
  a.orientation_prev = reinterpret_cast<double*>(u.ledger.orientation_prev.data());
  a.load_work = u.ledger.load_work.data();
  return a;
}

}  // namespace

void gather_and_advance(BlockUpdate& u, DashpotRest* rest, int begin, int end) {
  const auto& motion = u.blocks.props.motion;
  // The blocks two by two, their forces gathered: the law's, or under the
  // split scheme the rest of the dashpots onto the law's.
  auto gather = [&](int i0) {
    if (!rest) {
      gather_two_blocks(u, i0, end);
      return;
    }
    rest->gather(i0, u.blocks.state);
    if (i0 + 1 < end) rest->gather(i0 + 1, u.blocks.state);
  };
  // The blocks two by two: both gathered, then each updated.
  if (u.stage.local_damping > 0) {
    for (int i0 = begin; i0 < end; i0 += 2) {
      gather(i0);
      for (int i = i0; i < std::min(i0 + 2, end); ++i)
        if (motion[i] == BlockMotion::free) advance_block<true>(u, i);
    }
    return;
  }
  if (u.step.rising) {
    for (int i0 = begin; i0 < end; i0 += 2) {
      gather(i0);
      for (int i = i0; i < std::min(i0 + 2, end); ++i)
        if (motion[i] == BlockMotion::free) advance_block<false>(u, i);
    }
    return;
  }
  const block_lanes::BlockArrays arrays = block_lane_arrays(u);
  block_lanes::StepConstants k;
  for (int c = 0; c < 3; ++c) {
    k.gravity[c] = u.step.gravity[c];
    k.ground_acceleration[c] = u.step.a_ground[c];
  }
  k.dt = u.clock.dt;
  k.dv_dt = 0.5 * (u.clock.dt_prev + u.clock.dt);
  const bool any_loaded = !u.loads.loaded.empty() && !u.stage.active;
  int four[4];
  int waiting = 0;
  for (int i0 = begin; i0 < end; i0 += 2) {
    gather(i0);
    for (int i = i0; i < std::min(i0 + 2, end); ++i) {
      if (motion[i] != BlockMotion::free) continue;
      if (any_loaded && u.loads.loaded[i]) {
        advance_block<false>(u, i);
        continue;
      }
      four[waiting++] = i;
      if (waiting < 4) continue;
      waiting = 0;
      u.advance_four(arrays, k, four);
    }
  }
  if (waiting > 0) {
    for (int w = waiting; w < 4; ++w) four[w] = four[waiting - 1];
    u.advance_four(arrays, k, four);
  }
}

void gather_and_predict(BlockUpdate& u, DashpotRest& rest, int begin, int end) {
  auto& st = u.blocks.state;
  const auto& pr = u.blocks.props;
  const double dv_dt = 0.5 * (u.clock.dt_prev + u.clock.dt);
  for (int i0 = begin; i0 < end; i0 += 2) {
    gather_two_blocks(u, i0, end);
    for (int i = i0; i < std::min(i0 + 2, end); ++i) {
      if (pr.motion[i] == BlockMotion::fixed) {  // never moves (whatever the ground does)
        rest.velocity_next[i] = st.velocity[i];
        rest.omega_next[i] = st.angular_velocity[i];
        continue;
      }
      if (pr.motion[i] == BlockMotion::kinematic) {
        kinematic_velocity_next(u.blocks, u.loads, u.motion, u.clock, u.stage.active, i, rest.velocity_next[i],
                                rest.omega_next[i]);
        continue;
      }
      Vec3 force, torque;
      double inv_m;
      const Vec3* inv_I;
      if (u.stage.local_damping > 0)
        block_load<true>(u, i, force, torque, inv_m, inv_I);
      else
        block_load<false>(u, i, force, torque, inv_m, inv_I);
      rest.velocity_next[i] = st.velocity[i] + (dv_dt * inv_m) * force;
      const Vec3 L = st.angular_momentum[i] + dv_dt * torque;
      const Mat3& R = st.rotation[i];
      rest.omega_next[i] = R * inv_I->cwiseProduct(R.transpose() * L);
    }
  }
}

void gather_all_blocks(const BlockUpdate& u) {
  auto& st = u.blocks.state;
  if (u.pair_gather) {
    for (int i = 0; i < u.blocks.count; ++i)
      u.pair_gather->sum(i, *u.pair_wrench, st.contact_force[i], st.contact_torque[i]);
    return;
  }
  const gather_lanes::GatherArrays a = gather_lane_arrays(u.contacts, st.position, st.contact_force, st.contact_torque);
  for (int i = 0; i < u.blocks.count; ++i) {
    u.gather.block(a, i);
    if (u.clip_gather) add_clip_rest(u, i);
  }
}

}  // namespace polydem
