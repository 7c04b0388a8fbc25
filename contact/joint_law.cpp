#include "contact/joint_law.hpp"

#include <cmath>
#include <numbers>

namespace polydem {

JointLaw make_joint_law(const JointSpec& spec) {
  JointLaw law;
  law.kn = spec.normal_stiffness;
  law.ks = spec.shear_stiffness;
  law.tan_phi = std::tan(spec.friction_angle * std::numbers::pi / 180.0);
  law.cohesion = spec.cohesion;
  law.tensile_strength = spec.tensile_strength;
  law.beta = spec.damping;
  return law;
}

namespace {

// A joint that opens can carry no shear: Coulomb's cap is zero. Whatever
// elastic shear energy it still held is released by slip, so the ledger
// books it as slip dissipation.
inline void open_joint(const JointLaw& law, Subcontacts& sub, std::size_t s) {
  const Vec3& fs = sub.shear_force[s];
  if (law.ks > 0 && sub.area[s] > 0) sub.slip_energy[s] += 0.5 * fs.squaredNorm() / (law.ks * sub.area[s]);
  sub.force[s] = Vec3::Zero();
  sub.normal_force[s] = 0;
  sub.shear_force[s] = Vec3::Zero();
}

// The law for one subcontact whose geometry and relative velocity at its
// point are known: normal n (unit, from the reference block), overlap u_n,
// relative velocity of the incident block at the point.
[[gnu::always_inline]] inline void subcontact_law(const JointLaw& law, Subcontacts& sub, std::size_t s, const Vec3& n, double un,
                           const Vec3& vrel, double dt) {
  const double vn = vrel.dot(n);
  const Vec3 vs = vrel - vn * n;
  const double A = sub.area[s];
  const bool bonded = sub.bonded[s] != 0;
  if (un <= 0 && !bonded) {  // open joint: no force, no shear memory
    open_joint(law, sub, s);
    return;
  }
  double fn_el = law.kn * A * un;
  bool broken = false;
  if (bonded && fn_el < -law.tensile_strength * A) {  // tensile failure
    broken = true;
  }
  if (broken || (un <= 0 && law.tensile_strength == 0)) {
    sub.bonded[s] = 0;
    if (un <= 0) {
      open_joint(law, sub, s);
      return;
    }
  }
  const bool still_bonded = sub.bonded[s] != 0;

  // Shear: rotate the stored force into the current plane, then increment.
  Vec3 fs = sub.shear_force[s];
  fs -= fs.dot(n) * n;
  fs -= (law.ks * A * dt) * vs;
  const double cap = (still_bonded ? law.cohesion * A : 0.0) + std::max(fn_el, 0.0) * law.tan_phi;
  const double fs_mag = fs.norm();
  bool slipping = false;
  if (fs_mag > cap) {
    slipping = true;
    // Plastic slip (fs_mag − cap)/(ks·A) under the force `cap`.
    if (law.ks > 0 && A > 0) sub.slip_energy[s] += cap * (fs_mag - cap) / (law.ks * A);
    fs *= fs_mag > 0 ? cap / fs_mag : 0.0;
    if (still_bonded) sub.bonded[s] = 0;
  }
  sub.shear_force[s] = fs;

  // Stiffness-proportional damping while closed; u̇_n = −v_n.
  double fn_total = fn_el;
  Vec3 fs_damp = Vec3::Zero();
  if (un > 0) {
    fn_total += law.beta * law.kn * A * (-vn);
    if (!slipping) fs_damp = -(law.beta * law.ks * A) * vs;
  }
  if (sub.bonded[s] == 0 && fn_total < 0) fn_total = 0;  // no tension
  const double fn_damp = fn_total - fn_el;
  // Power of the damping forces (≥ 0): they oppose the relative motion.
  sub.damping_energy[s] += dt * (fn_damp * (-vn) - fs_damp.dot(vs));
  sub.normal_force[s] = fn_total;
  sub.force[s] = fn_total * n + fs + fs_damp;
}

}  // namespace

void compute_joint_forces(const JointLaw& law, const BlockState& st, Subcontacts& sub, double dt,
                          std::size_t begin, std::size_t end) {
  for (std::size_t s = begin; s < end; ++s) {
    const int r = sub.ref_block[s];
    const int c = sub.inc_block[s];
    const Vec3 n = st.rotation[r] * sub.ref_normal_local[s];
    const Vec3& xr = st.position[r];
    const Vec3& xc = st.position[c];
    const Vec3 p = xc + st.rotation[c] * sub.inc_point_local[s];
    const double un = sub.ref_offset_local[s] + n.dot(xr) - n.dot(p);
    const Vec3 vrel = (st.velocity[c] + st.angular_velocity[c].cross(p - xc)) -
                      (st.velocity[r] + st.angular_velocity[r].cross(p - xr));
    sub.point[s] = p;
    sub.overlap[s] = un;
    subcontact_law(law, sub, s, n, un, vrel, dt);
  }
}

void compute_pair_forces(const JointLaw& law, const BlockState& st, const std::vector<ContactPair>& pairs,
                         Subcontacts& sub, double dt, std::size_t pair_begin, std::size_t pair_end) {
  for (std::size_t q = pair_begin; q < pair_end; ++q) {
    const ContactPair& cp = pairs[q];
    if (cp.count == 0) continue;
    const int r = cp.ref_block;
    const int c = cp.ref_block == cp.a ? cp.b : cp.a;
    // Shared by the pair's subcontacts: the common plane and both motions.
    const std::size_t s0 = static_cast<std::size_t>(cp.first);
    const Vec3 n = st.rotation[r] * sub.ref_normal_local[s0];
    const Vec3& xr = st.position[r];
    const Vec3& xc = st.position[c];
    const double plane = n.dot(xr);
    const Mat3& Rc = st.rotation[c];
    const Vec3 dv = st.velocity[c] - st.velocity[r];
    const Vec3& wc = st.angular_velocity[c];
    const Vec3& wr = st.angular_velocity[r];
    const Vec3 xcr = xc - xr;
    for (std::size_t s = s0; s < s0 + static_cast<std::size_t>(cp.count); ++s) {
      const Vec3 arm_c = Rc * sub.inc_point_local[s];  // p − x_c
      const Vec3 p = xc + arm_c;
      const double un = sub.ref_offset_local[s] + plane - n.dot(p);
      const Vec3 vrel = dv + wc.cross(arm_c) - wr.cross(arm_c + xcr);
      sub.point[s] = p;
      sub.overlap[s] = un;
      subcontact_law(law, sub, s, n, un, vrel, dt);
    }
  }
}

double joint_strain_energy(const JointLaw& law, const Subcontacts& sub) {
  double e = 0;
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const double A = sub.area[s];
    if (A <= 0) continue;
    const double un = sub.overlap[s];
    if (un > 0 || sub.bonded[s]) e += 0.5 * law.kn * A * un * un;
    if (law.ks > 0) e += 0.5 * sub.shear_force[s].squaredNorm() / (law.ks * A);
  }
  return e;
}

}  // namespace polydem
