#include "integrators/applied_loads.hpp"

#include "integrators/rotation.hpp"

#include <stdexcept>
#include <string>

namespace polydem {

AppliedLoads make_applied_loads(BlockLoads spec, Blocks& blocks) {
  AppliedLoads a;
  a.spec = std::move(spec);
  const int n = blocks.count;
  if (!a.spec.loads.empty()) {
    a.loaded.assign(n, 0);
    a.force.assign(n, Vec3::Zero());
    a.torque.assign(n, Vec3::Zero());
    a.force_prev.assign(n, Vec3::Zero());
    a.torque_prev.assign(n, Vec3::Zero());
    for (const PointLoad& l : a.spec.loads) a.loaded[l.block] = 1;
  }
  if (!a.spec.prescribed.empty()) {
    a.prescription_of.assign(n, -1);
    a.prescribed_history.assign(a.spec.prescribed.size(), AppliedLoads::History{});
    for (std::size_t k = 0; k < a.spec.prescribed.size(); ++k) {
      const Prescription& p = a.spec.prescribed[k];
      if (blocks.props.motion[p.block] != BlockMotion::kinematic)
        throw std::invalid_argument("a prescribed block must be kinematic: block '" + blocks.props.name[p.block] +
                                    "' is not");
      a.prescription_of[p.block] = static_cast<int>(k);
      blocks.state.velocity[p.block] = p.displacement_table.empty() ? p.velocity_at(0.0) : Vec3(Vec3::Zero());
      blocks.state.angular_velocity[p.block] = p.angular_velocity;
    }
  }
  return a;
}

void AppliedLoads::save(ByteWriter& w) const {
  if (!loaded.empty()) {
    w.put(force_prev);
    w.put(torque_prev);
  }
  for (const History& h : prescribed_history) {
    w.put(h.force);
    w.put(h.torque);
  }
}

void AppliedLoads::load(ByteReader& r, std::size_t n) {
  if (!loaded.empty()) {
    r.get_sized(force_prev, n, "load_force_prev");
    r.get_sized(torque_prev, n, "load_torque_prev");
  }
  for (History& h : prescribed_history) {
    r.get(h.force);
    r.get(h.torque);
  }
}

void evaluate_point_loads(AppliedLoads& a, const BlockState& st, double t) {
  for (const PointLoad& l : a.spec.loads) {
    a.force[l.block] = Vec3::Zero();
    a.torque[l.block] = Vec3::Zero();
  }
  for (const PointLoad& l : a.spec.loads) {
    const double f = table_value(l.factor, t).x();
    const Vec3 force = f * l.force;
    Vec3 torque = f * l.moment;
    if (l.at_point) torque += (st.rotation[l.block] * l.arm_local).cross(force);
    a.force[l.block] += force;
    a.torque[l.block] += torque;
  }
}

void kinematic_velocity_next(const Blocks& blocks, const AppliedLoads& loads, const GroundMotion& motion,
                             const StepClock& c, bool static_stage, int i, Vec3& v, Vec3& w) {
  const auto& st = blocks.state;
  const int k = loads.prescription_of.empty() ? -1 : loads.prescription_of[i];
  if (k >= 0) {
    const Prescription& p = loads.spec.prescribed[static_cast<std::size_t>(k)];
    v = Vec3::Zero();
    if (!static_stage) {
      v = !p.displacement_table.empty() ? Vec3((table_value(p.displacement_table, c.time + c.dt) -
                                                table_value(p.displacement_table, c.time)) / c.dt)
                                        : p.velocity_at(c.time + 0.5 * c.dt);
    }
    w = static_stage ? Vec3(Vec3::Zero()) : p.angular_velocity;
    return;
  }
  const bool moving = !static_stage && motion.any_active() && motion.applied_as == GroundMotionApplication::kinematic;
  v = moving ? motion.velocity_vector(c.time + 0.5 * c.dt) : st.velocity[i];
  w = st.angular_velocity[i];
}

namespace {

// A prescribed block (core/loads.hpp): its velocity at t + dt/2 from its
// history, its turn by ω·dt about its centroid; it does the work
// −dt·(F_joint·v + T_joint·ω) on the blocks it pushes. Held still in the
// static stage.
void move_prescribed_block(Blocks& blocks, AppliedLoads& loads, const GroundMotion& motion, const StepClock& c,
                           bool static_stage, LedgerKinematics& ledger, int i, const Prescription& p) {
  auto& st = blocks.state;
  const Vec3 v_old = st.velocity[i], w_old = st.angular_velocity[i];
  const bool by_displacement = !p.displacement_table.empty();
  Vec3 v_new, w_new;
  kinematic_velocity_next(blocks, loads, motion, c, static_stage, i, v_new, w_new);
  ledger.velocity_mid[i] = 0.5 * (v_old + v_new);
  ledger.omega_mid[i] = 0.5 * (w_old + w_new);
  ledger.position_prev[i] = st.position[i];
  ledger.orientation_prev[i] = st.orientation[i];
  // The work it does through its joints over the step that ends now, by
  // the trapezoid (as the point loads: exact against the leapfrog's ledger).
  AppliedLoads::History& h = loads.prescribed_history[static_cast<std::size_t>(loads.prescription_of[i])];
  if (c.steps > 0)
    ledger.load_work[i] -= 0.5 * (st.contact_force[i] + h.force).dot(c.dt_prev * v_old) +
                           0.5 * (st.contact_torque[i] + h.torque).dot(c.dt_prev * w_old);
  h.force = st.contact_force[i];
  h.torque = st.contact_torque[i];
  st.velocity[i] = v_new;
  st.angular_velocity[i] = w_new;
  if (by_displacement && !static_stage)
    st.position[i] = p.start + table_value(p.displacement_table, c.time + c.dt);  // exactly, no drift
  else
    st.position[i] += c.dt * v_new;
  if (!w_new.isZero(0.0)) {
    st.orientation[i] = (rotation_quaternion(c.dt * w_new) * st.orientation[i]).normalized();
    st.rotation[i] = st.orientation[i].toRotationMatrix();
  }
}

}  // namespace

void move_kinematic_blocks(Blocks& blocks, AppliedLoads& loads, const GroundMotion& motion, const StepClock& c,
                           bool static_stage, LedgerKinematics& ledger) {
  if (blocks.kinematic_blocks.empty()) return;
  auto& st = blocks.state;
  for (int i : blocks.kinematic_blocks) {
    const int k = loads.prescription_of.empty() ? -1 : loads.prescription_of[i];
    if (k >= 0) {
      move_prescribed_block(blocks, loads, motion, c, static_stage, ledger, i,
                            loads.spec.prescribed[static_cast<std::size_t>(k)]);
      continue;
    }
    const Vec3 v_old = st.velocity[i];
    Vec3 v_new, w_unused;
    kinematic_velocity_next(blocks, loads, motion, c, static_stage, i, v_new, w_unused);
    ledger.velocity_mid[i] = 0.5 * (v_old + v_new);
    ledger.position_prev[i] = st.position[i];
    // The base does work on the blocks through the joints: −F_joint·v.
    ledger.load_work[i] += load_work(-c.dt, st.contact_force[i], ledger.velocity_mid[i]);
    st.velocity[i] = v_new;
    st.position[i] += c.dt * v_new;
  }
}

}  // namespace polydem
