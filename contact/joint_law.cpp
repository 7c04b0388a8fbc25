#include "contact/joint_law.hpp"

#include "contact/joint_law_lanes.hpp"

#include <algorithm>
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

// The rotation matrix of the rotation vector θ (Rodrigues):
// R = I + (sin a / a)·[θ]× + ((1 − cos a)/a²)·[θ]×², a = |θ|. A step turns a
// joint by far less than 1e-3 rad, where the series of the two factors are
// exact to round-off and avoid sin/cos. θ = 0 gives the identity exactly.
inline Mat3 rotation_matrix(const Vec3& t) {
  const double a2 = t.squaredNorm();
  double s, c;
  if (a2 < 1e-6) {  // constants, not divisions: this runs for every pair at every step
    constexpr double k6 = 1.0 / 6.0, k24 = 1.0 / 24.0, k120 = 1.0 / 120.0, k720 = 1.0 / 720.0;
    s = 1.0 - a2 * k6 + (a2 * a2) * k120;
    c = 0.5 - a2 * k24 + (a2 * a2) * k720;
  } else {
    const double a = std::sqrt(a2);
    s = std::sin(a) / a;
    c = (1.0 - std::cos(a)) / a2;
  }
  // [θ]×² = θθᵀ − a²·I.
  Mat3 r = (c * t) * t.transpose();
  r.diagonal().array() += 1.0 - c * a2;
  r(0, 1) -= s * t.z();
  r(0, 2) += s * t.y();
  r(1, 0) += s * t.z();
  r(1, 2) -= s * t.x();
  r(2, 0) -= s * t.y();
  r(2, 1) += s * t.x();
  return r;
}

// The joint's rotation over the last step (see the header): the reference
// block's, with the twist about the normal n the mean of both blocks'.
inline Mat3 joint_spin(const Vec3& w_ref, const Vec3& w_inc, const Vec3& n, double dt) {
  return rotation_matrix(dt * (w_ref + (0.5 * (w_inc - w_ref).dot(n)) * n));
}

// A joint that opens can carry no shear: Coulomb's cap is zero. Whatever
// elastic shear energy it still held is released by slip, so the ledger
// books it as slip dissipation. `pending`: the last step's dashpot power
// still to book (its second half), which an opening joint owes all the same.
inline void open_joint(const JointLaw& law, Subcontacts& sub, std::size_t s, double pending, double dt) {
  const Vec3 fs = sub.shear_force[s];
  if (law.ks > 0 && sub.area[s] > 0) sub.slip_energy[s] += 0.5 * fs.squaredNorm() / (law.ks * sub.area[s]);
  sub.damping_energy[s] += 0.5 * dt * pending;
  sub.damping_force.set_zero(s);
  sub.force[s] = Vec3::Zero();
  sub.normal_force[s] = 0;
  sub.shear_force.set_zero(s);
}

// The law for one subcontact whose geometry and relative velocity at its
// point are known: normal n (unit, from the reference block), overlap u_n,
// relative velocity of the incident block at the point, the joint's
// rotation over the last step.
// `beta`: the dashpots' β applied here (the law's, or its explicit part
// under the split scheme); `dashpot`, when not null, receives which of them
// act (DashpotState).
[[gnu::always_inline]] inline void subcontact_law(const JointLaw& law, Subcontacts& sub, std::size_t s,
                                                  const Vec3& n, double un, const Vec3& vrel, const Mat3& spin,
                                                  double dt, double beta, std::uint8_t* dashpot) {
  if (dashpot) dashpot[s] = 0;
  const double vn = vrel.dot(n);
  const Vec3 vs = vrel - vn * n;
  const double A = sub.area[s];
  const bool bonded = sub.bonded[s] != 0;
  // The last step's dashpot force with this step's velocity: the second
  // half of that step's work (the header's centred velocity).
  const double pending = -sub.damping_force[s].dot(vrel);
  if (un <= 0 && !bonded) {  // open joint: no force, no shear memory
    open_joint(law, sub, s, pending, dt);
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
      open_joint(law, sub, s, pending, dt);
      return;
    }
  }
  const bool still_bonded = sub.bonded[s] != 0;

  // Shear: turn the stored force with the joint, keep it in the current
  // plane (round-off, and the O(dt²) between the two spins' split), then
  // increment.
  Vec3 fs = spin * sub.shear_force[s];
  fs -= fs.dot(n) * n;
  const double fs_old2 = fs.squaredNorm();
  fs -= (law.ks * A * dt) * vs;
  const double cap = (still_bonded ? law.cohesion * A : 0.0) + std::max(fn_el, 0.0) * law.tan_phi;
  bool slipping = false;
  if (fs.squaredNorm() > cap * cap) {  // the square root only when slipping
    const double fs_mag = fs.norm();
    slipping = true;
    // Slip dissipation. With the stored force a = |f_old| (turned), the
    // trial t = |f| and the cap c: shear the cap has fallen below (a > c,
    // the normal force at a lifting edge falling) is let go from m down to c,
    // releasing (m² − c²)/(2·ks·A), where m = min(a, t) is what the step's
    // increment leaves of it; the rest of the trial, t − m, is plastic slip
    // (t − m)/(ks·A) under the force c. When the cap has not fallen (a ≤ c),
    // m = c: the usual c·(t − c)/(ks·A). Both limits are exact: steady
    // sliding books c·Δu, a joint at rest whose cap falls books the strain
    // energy it gives up (open_joint is the cap falling to zero).
    if (law.ks > 0 && A > 0) {
      const double a = std::sqrt(fs_old2);
      const double m = a > cap ? std::min(a, fs_mag) : cap;
      sub.slip_energy[s] += (0.5 * (m - cap) * (m + cap) + cap * (fs_mag - m)) / (law.ks * A);
    }
    fs *= fs_mag > 0 ? cap / fs_mag : 0.0;
    if (still_bonded) sub.bonded[s] = 0;
  }
  sub.shear_force.set(s, fs);

  // Stiffness-proportional damping while closed; u̇_n = −v_n.
  double fn_total = fn_el;
  Vec3 fs_damp = Vec3::Zero();
  if (un > 0) {
    fn_total += beta * law.kn * A * (-vn);
    if (!slipping) fs_damp = -(beta * law.ks * A) * vs;
    if (dashpot) dashpot[s] = static_cast<std::uint8_t>(kNormalDashpot | (slipping ? 0 : kShearDashpot));
  }
  if (sub.bonded[s] == 0 && fn_total < 0) fn_total = 0;  // no tension
  const double fn_damp = fn_total - fn_el;
  // The dashpot's work over the step at the centred velocity: half now with
  // the velocity the force came from, half at the next step (pending).
  const Vec3 f_damp = fn_damp * n + fs_damp;
  sub.damping_energy[s] += 0.5 * dt * (pending - f_damp.dot(vrel));
  sub.damping_force.set(s, f_damp);
  sub.normal_force[s] = fn_total;
  sub.force[s] = fn_total * n + fs + fs_damp;
}

}  // namespace

namespace {

lanes::SubcontactArrays lane_arrays(Subcontacts& sub) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are read as x y z per element");
  lanes::SubcontactArrays a;
  a.ipx = sub.inc_point_local.x.data();
  a.ipy = sub.inc_point_local.y.data();
  a.ipz = sub.inc_point_local.z.data();
  a.offset = sub.ref_offset_local.data();
  a.area = sub.area.data();
  a.bonded = sub.bonded.data();
  a.sfx = sub.shear_force.x.data();
  a.sfy = sub.shear_force.y.data();
  a.sfz = sub.shear_force.z.data();
  a.dfx = sub.damping_force.x.data();
  a.dfy = sub.damping_force.y.data();
  a.dfz = sub.damping_force.z.data();
  a.slip_energy = sub.slip_energy.data();
  a.damping_energy = sub.damping_energy.data();
  a.overlap = sub.overlap.data();
  a.normal_force = sub.normal_force.data();
  // Vec3 is three doubles: the arrays as doubles (no element is touched, so
  // an empty array is fine).
  a.point = reinterpret_cast<double*>(sub.point.data());
  a.force = reinterpret_cast<double*>(sub.force.data());
  return a;
}

// rotation_matrix's series branch (a2 = |θ|² < 1e-6) term by term in plain
// doubles, into R column-major: R(i, j) = R[i + 3j].
inline void rotation_series(double t0, double t1, double t2, double a2, double* R) {
  constexpr double k6 = 1.0 / 6.0, k24 = 1.0 / 24.0, k120 = 1.0 / 120.0, k720 = 1.0 / 720.0;
  const double sn = 1.0 - a2 * k6 + (a2 * a2) * k120;
  const double cs = 0.5 - a2 * k24 + (a2 * a2) * k720;
  const double u0 = cs * t0, u1 = cs * t1, u2 = cs * t2;
  const double diag = 1.0 - cs * a2;
  R[0] = u0 * t0 + diag;
  R[4] = u1 * t1 + diag;
  R[8] = u2 * t2 + diag;
  R[3] = u0 * t1 - sn * t2;  // (0, 1)
  R[6] = u0 * t2 + sn * t1;  // (0, 2)
  R[1] = u1 * t0 + sn * t2;  // (1, 0)
  R[7] = u1 * t2 - sn * t0;  // (1, 2)
  R[2] = u2 * t0 - sn * t1;  // (2, 0)
  R[5] = u2 * t1 + sn * t0;  // (2, 1)
}

// The lanes' PairFrame of the pair (r reference, c incident, `nl` the
// reference face's normal in r's frame), in plain doubles: the same
// operations in the same order as the portable loop's Eigen expressions
// below (R·v is ((a + b) + c) in rows 0 and 1 and a + (b + c) in row 2, a
// dot product (x·x′ + y·y′) + z·z′), without Eigen's SSE2 shuffles between
// the packed and the scalar part of a Vec3, which cost a fifth of a step.
// A joint turning beyond rotation_matrix's series takes rotation_matrix
// itself, with the same θ.
// The pair's common normal in the world, R_ref·nl, in Eigen's association
// (the lanes' and the portable paths' one computation of it).
[[gnu::always_inline]] inline void world_normal(const double* Rr, const Vec3& nl, double* n) {
  const double l0 = nl.x(), l1 = nl.y(), l2 = nl.z();
  n[0] = (Rr[0] * l0 + Rr[3] * l1) + Rr[6] * l2;
  n[1] = (Rr[1] * l0 + Rr[4] * l1) + Rr[7] * l2;
  n[2] = Rr[2] * l0 + (Rr[5] * l1 + Rr[8] * l2);
}

[[gnu::always_inline]] inline void pair_frame(const BlockState& st, int r, int c, const Vec3& nl, double dt,
                                              lanes::PairFrame& f) {
  const double* Rr = st.rotation[r].data();
  const double* xr = st.position[r].data();
  const double* xc = st.position[c].data();
  const double* vr = st.velocity[r].data();
  const double* vc = st.velocity[c].data();
  const double* wr = st.angular_velocity[r].data();
  const double* wc = st.angular_velocity[c].data();
  double nw[3];
  world_normal(Rr, nl, nw);
  const double n0 = nw[0], n1 = nw[1], n2 = nw[2];
  // joint_spin: θ = dt·(w_ref + (½·(w_inc − w_ref)·n)·n)
  const double h = 0.5 * (((wc[0] - wr[0]) * n0 + (wc[1] - wr[1]) * n1) + (wc[2] - wr[2]) * n2);
  const double t0 = dt * (wr[0] + h * n0), t1 = dt * (wr[1] + h * n1), t2 = dt * (wr[2] + h * n2);
  const double a2 = (t0 * t0 + t1 * t1) + t2 * t2;
  if (a2 < 1e-6) {
    rotation_series(t0, t1, t2, a2, f.spin);
  } else {
    const Mat3 spin = rotation_matrix(Vec3(t0, t1, t2));
    std::copy(spin.data(), spin.data() + 9, f.spin);
  }
  f.n[0] = n0;
  f.n[1] = n1;
  f.n[2] = n2;
  f.plane = (n0 * xr[0] + n1 * xr[1]) + n2 * xr[2];
  for (int i = 0; i < 3; ++i) {
    f.xc[i] = xc[i];
    f.dv[i] = vc[i] - vr[i];
    f.wc[i] = wc[i];
    f.wr[i] = wr[i];
    f.xcr[i] = xc[i] - xr[i];
  }
  const double* Rc = st.rotation[c].data();
  for (int i = 0; i < 9; ++i) f.Rc[i] = Rc[i];
}

// The pair loop, each pair under its own law. kLanes: the subcontacts in
// AVX2 lanes (joint_law_lanes.hpp) by `kernel`, lanes::pair_law or
// lanes::pair_law_wide, the same bits.
template <bool kLanes>
[[gnu::always_inline]] inline void pair_forces(const JointLaws& laws, const BlockState& st,
                                               const std::vector<ContactPair>& pairs, Subcontacts& sub, double dt,
                                               std::size_t pair_begin, std::size_t pair_end, const SplitPart& split,
                                               [[maybe_unused]] lanes::PairLawKernel kernel = nullptr) {
  [[maybe_unused]] lanes::SubcontactArrays arrays;
  if constexpr (kLanes) {
    arrays = lane_arrays(sub);
    arrays.dashpot = split.dashpot;
  }
  for (std::size_t q = pair_begin; q < pair_end; ++q) {
    const ContactPair& cp = pairs[q];
    if (cp.count == 0) continue;
    const int r = cp.ref_block;
    const int c = cp.ref_block == cp.a ? cp.b : cp.a;
    const JointLaw& law = laws.between(r, c);
    // Shared by the pair's subcontacts: the common plane and both motions.
    const std::size_t s0 = static_cast<std::size_t>(cp.first);
    if constexpr (kLanes) {
      lanes::PairFrame f;
      pair_frame(st, r, c, sub.ref_normal_local[s0], dt, f);
      const lanes::LawConstants k{law.kn, law.ks, law.tan_phi, law.cohesion, law.tensile_strength,
                                  law.beta * split.explicit_part, dt};
      kernel(f, k, arrays, s0, static_cast<std::size_t>(cp.count));
      continue;
    }
    const Vec3 n = st.rotation[r] * sub.ref_normal_local[s0];
    const Vec3& xr = st.position[r];
    const Vec3& xc = st.position[c];
    const double plane = n.dot(xr);
    const Mat3& Rc = st.rotation[c];
    const Vec3 dv = st.velocity[c] - st.velocity[r];
    const Vec3& wc = st.angular_velocity[c];
    const Vec3& wr = st.angular_velocity[r];
    const Vec3 xcr = xc - xr;
    const Mat3 spin = joint_spin(wr, wc, n, dt);
    for (std::size_t s = s0; s < s0 + static_cast<std::size_t>(cp.count); ++s) {
      const Vec3 arm_c = Rc * sub.inc_point_local[s];  // p − x_c
      const Vec3 p = xc + arm_c;
      const double un = sub.ref_offset_local[s] + plane - n.dot(p);
      const Vec3 vrel = dv + wc.cross(arm_c) - wr.cross(arm_c + xcr);
      sub.point[s] = p;
      sub.overlap[s] = un;
      subcontact_law(law, sub, s, n, un, vrel, spin, dt, law.beta * split.explicit_part, split.dashpot);
    }
  }
}

}  // namespace

void compute_pair_forces(const JointLaws& laws, const BlockState& st, const std::vector<ContactPair>& pairs,
                         Subcontacts& sub, double dt, std::size_t pair_begin, std::size_t pair_end,
                         CodePath path, const SplitPart& split) {
#ifdef POLYDEM_LANES_AVX2
  if (use_lanes(path)) {
    pair_forces<true>(laws, st, pairs, sub, dt, pair_begin, pair_end, split,
                      use_wide_lanes(path) ? &lanes::pair_law_wide : &lanes::pair_law);
    return;
  }
#endif
  pair_forces<false>(laws, st, pairs, sub, dt, pair_begin, pair_end, split);
}

namespace {

// The RestFrame of the pair (r reference, c incident, `nl` the reference
// face's normal in r's frame): the normal as pair_frame's.
void rest_frame(const BlockState& st, const std::vector<Vec3>& velocity_next, const std::vector<Vec3>& omega_next,
                int r, int c, const Vec3& nl, double cn, double cs, lanes::RestFrame& f) {
  world_normal(st.rotation[r].data(), nl, f.n);
  f.Rc = st.rotation[c].data();
  for (int i = 0; i < 3; ++i) {
    f.xcr[i] = st.position[c][i] - st.position[r][i];
    f.dv[i] = velocity_next[c][i] - velocity_next[r][i];
    f.wc[i] = omega_next[c][i];
    f.wr[i] = omega_next[r][i];
  }
  f.cn = cn;
  f.cs = cs;
}

// The rest pass for one pair's subcontacts, one at a time: the lanes'
// operations in their order (arm = Rc·p_local as mat_vec, the relative
// velocity and the dot product as the law's; subcontact j of the pair summed
// into "lane" j mod 4, the lanes then (l0 + l1) + (l2 + l3)).
void pair_rest_portable(const lanes::RestFrame& f, const lanes::RestArrays& a, std::size_t s0, std::size_t count,
                        lanes::PairRest& out) {
  const double* R = f.Rc;
  const double n0 = f.n[0], n1 = f.n[1], n2 = f.n[2];
  double sum[6][4] = {};  // force x y z, moment x y z; per lane
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t s = s0 + j;
    const std::uint8_t state = a.dashpot[s];
    if (state == 0) {
      a.rx[s] = a.ry[s] = a.rz[s] = 0.0;
      continue;
    }
    const double px = a.ipx[s], py = a.ipy[s], pz = a.ipz[s];
    const double ax = (R[0] * px + R[3] * py) + R[6] * pz;
    const double ay = (R[1] * px + R[4] * py) + R[7] * pz;
    const double az = R[2] * px + (R[5] * py + R[8] * pz);
    const double qx = ax + f.xcr[0], qy = ay + f.xcr[1], qz = az + f.xcr[2];
    const double* wc = f.wc;
    const double* wr = f.wr;
    const double vx = (f.dv[0] + (wc[1] * az - wc[2] * ay)) - (wr[1] * qz - wr[2] * qy);
    const double vy = (f.dv[1] + (wc[2] * ax - wc[0] * az)) - (wr[2] * qx - wr[0] * qz);
    const double vz = (f.dv[2] + (wc[0] * ay - wc[1] * ax)) - (wr[0] * qy - wr[1] * qx);
    const double vn = (vx * n0 + vy * n1) + vz * n2;
    const double A = a.area[s];
    double fn = (f.cn * A) * (-vn);
    if (a.bonded[s] == 0) fn = std::max(fn, -a.normal_force[s]);  // never pulls an unbonded joint together
    double fx = fn * n0, fy = fn * n1, fz = fn * n2;
    if (state & kShearDashpot) {
      const double k = f.cs * A;
      fx = fx - k * (vx - vn * n0);
      fy = fy - k * (vy - vn * n1);
      fz = fz - k * (vz - vn * n2);
    }
    a.normal_force[s] = a.normal_force[s] + fn;
    a.rx[s] = fx;
    a.ry[s] = fy;
    a.rz[s] = fz;
    const std::size_t l = j % 4;
    sum[0][l] = sum[0][l] + fx;
    sum[1][l] = sum[1][l] + fy;
    sum[2][l] = sum[2][l] + fz;
    sum[3][l] = sum[3][l] + (ay * fz - az * fy);
    sum[4][l] = sum[4][l] + (az * fx - ax * fz);
    sum[5][l] = sum[5][l] + (ax * fy - ay * fx);
  }
  double total[6];
  for (int c = 0; c < 6; ++c) total[c] = (sum[c][0] + sum[c][1]) + (sum[c][2] + sum[c][3]);
  const double* d = f.xcr;
  for (int c = 0; c < 3; ++c) {
    out.force[c] = total[c];
    out.moment[c] = total[3 + c];
  }
  const double* F = out.force;
  out.moment_ref[0] = -(out.moment[0] + (d[1] * F[2] - d[2] * F[1]));
  out.moment_ref[1] = -(out.moment[1] + (d[2] * F[0] - d[0] * F[2]));
  out.moment_ref[2] = -(out.moment[2] + (d[0] * F[1] - d[1] * F[0]));
}

}  // namespace

void apply_dashpot_rest(const JointLaws& laws, double theta, const BlockState& st,
                        const std::vector<Vec3>& velocity_next, const std::vector<Vec3>& omega_next,
                        const std::vector<ContactPair>& pairs, const std::uint8_t* dashpot, Subcontacts& sub,
                        std::vector<lanes::PairRest>& rest, Vec3Array& rest_force, std::size_t pair_begin,
                        std::size_t pair_end, CodePath path) {
  lanes::RestArrays a;
  a.rx = rest_force.x.data();
  a.ry = rest_force.y.data();
  a.rz = rest_force.z.data();
  a.ipx = sub.inc_point_local.x.data();
  a.ipy = sub.inc_point_local.y.data();
  a.ipz = sub.inc_point_local.z.data();
  a.area = sub.area.data();
  a.bonded = sub.bonded.data();
  a.dashpot = dashpot;
  a.normal_force = sub.normal_force.data();
  lanes::PairRestKernel kernel = &pair_rest_portable;
#ifdef POLYDEM_LANES_AVX2
  if (use_lanes(path)) kernel = use_wide_lanes(path) ? &lanes::pair_rest_wide : &lanes::pair_rest;
#else
  (void)path;
#endif
  for (std::size_t q = pair_begin; q < pair_end; ++q) {
    const ContactPair& cp = pairs[q];
    if (cp.count == 0) {
      rest[q] = lanes::PairRest{};
      continue;
    }
    const int r = cp.ref_block;
    const int c = cp.ref_block == cp.a ? cp.b : cp.a;
    const JointLaw& law = laws.between(r, c);
    const std::size_t s0 = static_cast<std::size_t>(cp.first);
    lanes::RestFrame f;
    rest_frame(st, velocity_next, omega_next, r, c, sub.ref_normal_local[s0], (theta * law.beta) * law.kn,
               (theta * law.beta) * law.ks, f);
    kernel(f, a, s0, static_cast<std::size_t>(cp.count), rest[q]);
  }
}

void settle_damping_work(const BlockState& st, Subcontacts& sub, double dt) {
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const Vec3 f = sub.damping_force[s];
    if (f.isZero(0.0)) continue;
    const int r = sub.ref_block[s];
    const int c = sub.inc_block[s];
    const Vec3 p = st.position[c] + st.rotation[c] * sub.inc_point_local[s];
    const Vec3 vrel = (st.velocity[c] + st.angular_velocity[c].cross(p - st.position[c])) -
                      (st.velocity[r] + st.angular_velocity[r].cross(p - st.position[r]));
    sub.damping_energy[s] += 0.5 * dt * (-f.dot(vrel));
    sub.damping_force.set_zero(s);
  }
}

namespace {

// The normal overlap of subcontact s at the blocks' pose now (its
// body-fixed plane and point).
double overlap_now(const BlockState& st, const Subcontacts& sub, std::size_t s) {
  const int r = sub.ref_block[s];
  const int c = sub.inc_block[s];
  const Vec3 n = st.rotation[r] * sub.ref_normal_local[s];
  const Vec3 p = st.position[c] + st.rotation[c] * sub.inc_point_local[s];
  return sub.ref_offset_local[s] + n.dot(st.position[r]) - n.dot(p);
}

}  // namespace

// Σ ½·kn·A·u_n² over the subcontacts, in subcontact order. The overlaps
// first (in parallel with `threads` > 1 on large sets), into the calling
// thread's scratch (reused: no allocation once warmed up; named by
// reference, since inside the region thread_local would name each thread's
// own); then the sum in order: the same bits on any thread count.
double normal_strain_energy_now(const JointLaws& laws, const BlockState& st, const Subcontacts& sub, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(sub.size());
  thread_local std::vector<double> scratch;
  std::vector<double>& un = scratch;
  un.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static) if (threads > 1 && n >= 2048) num_threads(std::max(threads, 1))
  for (std::ptrdiff_t s = 0; s < n; ++s)
    un[static_cast<std::size_t>(s)] = overlap_now(st, sub, static_cast<std::size_t>(s));
  double e = 0;
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const JointLaw& law = laws.between(sub.ref_block[s], sub.inc_block[s]);
    if (un[s] > 0 || sub.bonded[s]) e += 0.5 * law.kn * sub.area[s] * un[s] * un[s];
  }
  return e;
}

void hold_normal_strain(const JointLaws& laws, const BlockState& st, const ContactSet& old, ContactSet& contacts,
                        int threads) {
  Subcontacts& sc = contacts.sub;
  const Subcontacts& os = old.sub;
  // Pair by pair, in parallel: a pair writes only its own subcontacts.
  const std::ptrdiff_t n_pairs = static_cast<std::ptrdiff_t>(contacts.pairs.size());
#pragma omp parallel for schedule(dynamic, 32) if (threads > 1 && n_pairs >= 256) num_threads(threads)
  for (std::ptrdiff_t q = 0; q < n_pairs; ++q) {
    const ContactPair& cp = contacts.pairs[static_cast<std::size_t>(q)];
    if (cp.count == 0) continue;
    // A pair found for the first time after the first detection held nothing
    // before: found already overlapping (a corner that the clip kept outside
    // the reference face until it was in), it starts at zero force.
    const ContactPair* op = find_pair(old, cp.a, cp.b);
    if (!op && old.detections == 0) continue;
    const double kn = laws.between(cp.a, cp.b).kn;
    const int s0 = cp.first, s1 = cp.first + cp.count;
    bool bonded = false;
    double e_new = 0, u_max = 0;
    for (int s = s0; s < s1; ++s) {
      bonded = bonded || sc.bonded[s] != 0;
      const double u = overlap_now(st, sc, s);
      if (u > 0) {
        e_new += 0.5 * kn * sc.area[s] * u * u;
        u_max = std::max(u_max, u);
      }
    }
    if (bonded || e_new <= 0) continue;
    // Only the compression held before counts: a bond's tension the new,
    // unbonded subcontacts cannot hold must not become compression.
    double e_old = 0;
    for (int o = op ? op->first : 0; op && o < op->first + op->count; ++o) {
      const double u = overlap_now(st, os, o);
      if (u > 0) e_old += 0.5 * kn * os.area[o] * u * u;
    }
    if (e_new <= e_old) continue;
    // f(δ) = Σ ½·kn·A·(u − δ)₊² is convex and falls from e_new at 0 to 0 at
    // u_max: Newton from the left stays left of the root; a bracket and
    // bisection guard it against round-off.
    double delta = u_max;
    if (e_old > 0) {
      double lo = 0, hi = u_max;
      delta = 0;
      for (int it = 0; it < 100; ++it) {
        double f = 0, df = 0;
        for (int s = s0; s < s1; ++s) {
          const double u = overlap_now(st, sc, s) - delta;
          if (u > 0) {
            f += 0.5 * kn * sc.area[s] * u * u;
            df -= kn * sc.area[s] * u;
          }
        }
        if (std::abs(f - e_old) <= 1e-13 * e_new) break;
        (f > e_old ? lo : hi) = delta;
        double next = df < 0 ? delta - (f - e_old) / df : hi;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        delta = next;
      }
    }
    for (int s = s0; s < s1; ++s) {
      sc.ref_offset_local[s] -= delta;
      sc.overlap[s] -= delta;  // the spring's, as the next step's law computes it
      sc.crush[s] = delta;
    }
  }
}

double joint_strain_energy(const JointLaws& laws, const Subcontacts& sub) {
  double e = 0;
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const JointLaw& law = laws.between(sub.ref_block[s], sub.inc_block[s]);
    const double A = sub.area[s];
    if (A <= 0) continue;
    const double un = sub.overlap[s];
    if (un > 0 || sub.bonded[s]) e += 0.5 * law.kn * A * un * un;
    if (law.ks > 0) e += 0.5 * sub.shear_force[s].squaredNorm() / (law.ks * A);
  }
  return e;
}

double shear_strain_energy(const JointLaws& laws, const Subcontacts& sub) {
  double e = 0;
  for (std::size_t s = 0; s < sub.size(); ++s) {
    const double ks = laws.between(sub.ref_block[s], sub.inc_block[s]).ks;
    if (ks > 0 && sub.area[s] > 0) e += 0.5 * sub.shear_force[s].squaredNorm() / (ks * sub.area[s]);
  }
  return e;
}

bool JointLaws::any_bonds() const {
  for (const JointLaw& law : laws)
    if (law.bonds()) return true;
  return false;
}

JointLaws uniform_joint_laws(const JointLaw& law, int blocks) {
  JointLaws out;
  out.laws = {law};
  out.slots = 1;
  out.pair_law = {0};
  out.block_slot.assign(static_cast<std::size_t>(blocks), 0);
  return out;
}

JointLaws make_joint_laws(const Blocks& blocks, const JointSpec& default_joint,
                          const std::vector<JointPairSpec>& pairs) {
  JointLaws out = uniform_joint_laws(make_joint_law(default_joint), blocks.count);
  std::vector<std::pair<int, int>> present;  // group indices of the entries that act
  std::vector<const JointSpec*> specs;
  for (const JointPairSpec& p : pairs) {
    const int a = blocks.find_group(p.group_a), b = blocks.find_group(p.group_b);
    if (a < 0 || b < 0) continue;
    present.emplace_back(a, b);
    specs.push_back(&p.joint);
  }
  if (present.empty()) return out;
  const int groups = static_cast<int>(blocks.group_names.size());
  out.slots = groups + 1;
  out.pair_law.assign(static_cast<std::size_t>(out.slots * out.slots), 0);
  for (std::size_t k = 0; k < present.size(); ++k) {
    out.laws.push_back(make_joint_law(*specs[k]));
    const int sa = present[k].first + 1, sb = present[k].second + 1;
    const int law = static_cast<int>(out.laws.size()) - 1;
    out.pair_law[static_cast<std::size_t>(sa * out.slots + sb)] = law;
    out.pair_law[static_cast<std::size_t>(sb * out.slots + sa)] = law;
  }
  for (int i = 0; i < blocks.count; ++i) out.block_slot[static_cast<std::size_t>(i)] = blocks.props.group[i] + 1;
  return out;
}

JointLaw stiffest_law(const JointLaws& laws) {
  // The laws some pair of groups present among the blocks uses.
  std::vector<char> slot_present(static_cast<std::size_t>(laws.slots), 0);
  for (int sl : laws.block_slot) slot_present[static_cast<std::size_t>(sl)] = 1;
  std::vector<char> acts(laws.laws.size(), 0);
  for (int a = 0; a < laws.slots; ++a)
    for (int b = 0; b < laws.slots; ++b)
      if (slot_present[static_cast<std::size_t>(a)] && slot_present[static_cast<std::size_t>(b)])
        acts[static_cast<std::size_t>(laws.pair_law[static_cast<std::size_t>(a * laws.slots + b)])] = 1;
  JointLaw out;
  bool first = true;
  for (std::size_t k = 0; k < laws.laws.size(); ++k) {
    if (!acts[k]) continue;
    const JointLaw& j = laws.laws[k];
    if (first) {
      out = j;
      first = false;
      continue;
    }
    out.kn = std::max(out.kn, j.kn);
    out.ks = std::max(out.ks, j.ks);
    out.beta = std::max(out.beta, j.beta);
  }
  return out;
}

}  // namespace polydem
