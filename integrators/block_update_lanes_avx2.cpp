// The block update in AVX2 lanes (see block_update_lanes.hpp). Compiled with
// -mavx2 on x86-64 only; it includes nothing that instantiates inline code
// shared with other files (no Eigen, no std:: algorithms): only
// core/avx2_lanes.hpp and functions local to this file.
//
// Each stage names the portable code of Simulation::advance_block it
// mirrors, with the portable association.
#include "integrators/block_update_lanes.hpp"

#include "core/avx2_lanes.hpp"

namespace polydem::block_lanes {
namespace {

using namespace avx2;

// Component c of four blocks' records of `width` doubles.
inline V gather(const double* p, int width, int c, const int idx[4]) {
  return _mm256_setr_pd(p[width * idx[0] + c], p[width * idx[1] + c], p[width * idx[2] + c],
                        p[width * idx[3] + c]);
}
inline void scatter(double* p, int width, int c, const int idx[4], V v) {
  alignas(32) double t[4];
  _mm256_store_pd(t, v);
  for (int l = 0; l < 4; ++l) p[width * idx[l] + c] = t[l];
}

struct Vec { V x, y, z; };
struct Quat { V x, y, z, w; };
struct Mat { V m[9]; };  // column-major: m[i + 3j] = (i, j)

inline Vec gather3(const double* p, const int idx[4]) {
  return {gather(p, 3, 0, idx), gather(p, 3, 1, idx), gather(p, 3, 2, idx)};
}
inline void scatter3(double* p, const int idx[4], const Vec& v) {
  scatter(p, 3, 0, idx, v.x);
  scatter(p, 3, 1, idx, v.y);
  scatter(p, 3, 2, idx, v.z);
}
inline Quat gather4(const double* p, const int idx[4]) {
  return {gather(p, 4, 0, idx), gather(p, 4, 1, idx), gather(p, 4, 2, idx), gather(p, 4, 3, idx)};
}
inline void scatter4(double* p, const int idx[4], const Quat& q) {
  scatter(p, 4, 0, idx, q.x);
  scatter(p, 4, 1, idx, q.y);
  scatter(p, 4, 2, idx, q.z);
  scatter(p, 4, 3, idx, q.w);
}

// Rᵀ·v: every row ((a + b) + c).
inline Vec transpose_times(const Mat& r, const Vec& v) {
  return {add(add(mul(r.m[0], v.x), mul(r.m[1], v.y)), mul(r.m[2], v.z)),
          add(add(mul(r.m[3], v.x), mul(r.m[4], v.y)), mul(r.m[5], v.z)),
          add(add(mul(r.m[6], v.x), mul(r.m[7], v.y)), mul(r.m[8], v.z))};
}
// R·v: rows 0 and 1 ((a + b) + c), row 2 a + (b + c).
inline Vec times(const Mat& r, const Vec& v) {
  return {add(add(mul(r.m[0], v.x), mul(r.m[3], v.y)), mul(r.m[6], v.z)),
          add(add(mul(r.m[1], v.x), mul(r.m[4], v.y)), mul(r.m[7], v.z)),
          add(mul(r.m[2], v.x), add(mul(r.m[5], v.y), mul(r.m[8], v.z)))};
}
// ω = R·(I⁻¹ ⊙ (Rᵀ·L)).
inline Vec omega(const Mat& r, const Vec& inv_i, const Vec& l) {
  const Vec a = transpose_times(r, l);
  return times(r, {mul(inv_i.x, a.x), mul(inv_i.y, a.y), mul(inv_i.z, a.z)});
}

// rotation_quaternion's series: c = (1 − a²/8) + a⁴/384, h = (1/2 − a²/48) + a⁴/3840,
// q = (h·θ, c). `small`: lanes with a² < 1e-6.
inline Quat exp_series(const Vec& t, V& small) {
  const V a2 = add(add(mul(t.x, t.x), mul(t.y, t.y)), mul(t.z, t.z));
  small = _mm256_cmp_pd(a2, bc(1e-6), _CMP_LT_OQ);
  const V a4 = mul(a2, a2);
  const V c = add(sub(bc(1.0), div(a2, bc(8.0))), div(a4, bc(384.0)));
  const V h = add(sub(bc(0.5), div(a2, bc(48.0))), div(a4, bc(3840.0)));
  return {mul(h, t.x), mul(h, t.y), mul(h, t.z), c};
}

// a·b, as Eigen's SSE2 quaternion product.
inline Quat product(const Quat& a, const Quat& b) {
  return {sub(add(mul(a.w, b.x), mul(a.y, b.z)), sub(mul(a.z, b.y), mul(a.x, b.w))),
          add(add(mul(a.w, b.y), mul(a.y, b.w)), sub(mul(a.z, b.x), mul(a.x, b.z))),
          add(sub(mul(a.w, b.z), mul(a.y, b.x)), add(mul(a.z, b.w), mul(a.x, b.y))),
          sub(sub(mul(a.w, b.w), mul(a.y, b.y)), add(mul(a.z, b.z), mul(a.x, b.x)))};
}

// q / |q|, |q|² = (x² + z²) + (y² + w²); q itself where |q|² is not positive.
inline Quat normalized(const Quat& q) {
  const V n2 = add(add(mul(q.x, q.x), mul(q.z, q.z)), add(mul(q.y, q.y), mul(q.w, q.w)));
  const V s = _mm256_sqrt_pd(n2);
  const V ok = _mm256_cmp_pd(n2, _mm256_setzero_pd(), _CMP_GT_OQ);
  return {_mm256_blendv_pd(q.x, div(q.x, s), ok), _mm256_blendv_pd(q.y, div(q.y, s), ok),
          _mm256_blendv_pd(q.z, div(q.z, s), ok), _mm256_blendv_pd(q.w, div(q.w, s), ok)};
}

// Eigen's toRotationMatrix.
inline Mat rotation_matrix(const Quat& q) {
  const V two = bc(2.0), one = bc(1.0);
  const V tx = mul(two, q.x), ty = mul(two, q.y), tz = mul(two, q.z);
  const V twx = mul(tx, q.w), twy = mul(ty, q.w), twz = mul(tz, q.w);
  const V txx = mul(tx, q.x), txy = mul(ty, q.x), txz = mul(tz, q.x);
  const V tyy = mul(ty, q.y), tyz = mul(tz, q.y), tzz = mul(tz, q.z);
  Mat r;
  r.m[0] = sub(one, add(tyy, tzz));  // (0, 0)
  r.m[3] = sub(txy, twz);            // (0, 1)
  r.m[6] = add(txz, twy);            // (0, 2)
  r.m[1] = add(txy, twz);            // (1, 0)
  r.m[4] = sub(one, add(txx, tzz));  // (1, 1)
  r.m[7] = sub(tyz, twx);            // (1, 2)
  r.m[2] = sub(txz, twy);            // (2, 0)
  r.m[5] = add(tyz, twx);            // (2, 1)
  r.m[8] = sub(one, add(txx, tyy));  // (2, 2)
  return r;
}

inline V dot(const Vec& a, const Vec& b) { return dot3(a.x, a.y, a.z, b.x, b.y, b.z); }

}  // namespace

bool advance_four(const BlockArrays& a, const StepConstants& k, const int idx[4]) {
  const V dt = bc(k.dt), dv_dt = bc(k.dv_dt), half = bc(0.5);
  const V m = gather(a.mass, 1, 0, idx);
  const V inv_m = gather(a.inv_mass, 1, 0, idx);
  const Vec g{bc(k.gravity[0]), bc(k.gravity[1]), bc(k.gravity[2])};
  const Vec ag{bc(k.ground_acceleration[0]), bc(k.ground_acceleration[1]), bc(k.ground_acceleration[2])};
  // force = (m·g + (−m)·a_g) + F_joint; torque = T_joint.
  const V neg_m = neg(m);
  const Vec fc = gather3(a.contact_force, idx);
  const Vec force{add(add(mul(m, g.x), mul(neg_m, ag.x)), fc.x), add(add(mul(m, g.y), mul(neg_m, ag.y)), fc.y),
                  add(add(mul(m, g.z), mul(neg_m, ag.z)), fc.z)};
  const Vec torque = gather3(a.contact_torque, idx);
  // v_new = v_old + (dv_dt·inv_m)·force; L_new = L + dv_dt·torque.
  const Vec v_old = gather3(a.velocity, idx);
  const V s = mul(dv_dt, inv_m);
  const Vec v_new{add(v_old.x, mul(s, force.x)), add(v_old.y, mul(s, force.y)), add(v_old.z, mul(s, force.z))};
  const Vec l_old = gather3(a.angular_momentum, idx);
  const Vec l_new{add(l_old.x, mul(dv_dt, torque.x)), add(l_old.y, mul(dv_dt, torque.y)),
                  add(l_old.z, mul(dv_dt, torque.z))};
  // ω at the half step: ω0 from R0, the half-step orientation, ω from it.
  Mat r0;
  for (int c = 0; c < 9; ++c) r0.m[c] = gather(a.rotation, 9, c, idx);
  const Vec inv_i = gather3(a.inv_inertia, idx);
  const Vec w0 = omega(r0, inv_i, l_new);
  const V half_dt = bc(0.5 * k.dt);
  V small_h;
  const Quat q_old = gather4(a.orientation, idx);
  const Quat dq_h = exp_series({mul(half_dt, w0.x), mul(half_dt, w0.y), mul(half_dt, w0.z)}, small_h);
  const Mat rh = rotation_matrix(product(dq_h, q_old));
  const Vec w = omega(rh, inv_i, l_new);
  // The step's turn: the series must hold for both turns, or nothing is written.
  V small;
  const Quat dq = exp_series({mul(dt, w.x), mul(dt, w.y), mul(dt, w.z)}, small);
  if (_mm256_movemask_pd(_mm256_and_pd(small_h, small)) != 0xF) return false;
  const Quat q_new = normalized(product(dq, q_old));

  const Vec w_old = gather3(a.angular_velocity, idx);
  const Vec v_mid{mul(half, add(v_old.x, v_new.x)), mul(half, add(v_old.y, v_new.y)),
                  mul(half, add(v_old.z, v_new.z))};
  scatter3(a.velocity_mid, idx, v_mid);
  scatter3(a.omega_mid, idx, {mul(half, add(w_old.x, w.x)), mul(half, add(w_old.y, w.y)), mul(half, add(w_old.z, w.z))});
  const Vec x_old = gather3(a.position, idx);
  scatter3(a.position_prev, idx, x_old);
  scatter4(a.orientation_prev, idx, q_old);
  // load_work += dt·((−m)·a_g · v_mid).
  const V lw = gather(a.load_work, 1, 0, idx);
  const Vec f_ground{mul(neg_m, ag.x), mul(neg_m, ag.y), mul(neg_m, ag.z)};
  scatter(a.load_work, 1, 0, idx, add(lw, mul(dt, dot(f_ground, v_mid))));

  scatter3(a.velocity, idx, v_new);
  scatter3(a.angular_momentum, idx, l_new);
  scatter3(a.angular_velocity, idx, w);
  scatter3(a.position, idx, {add(x_old.x, mul(dt, v_new.x)), add(x_old.y, mul(dt, v_new.y)), add(x_old.z, mul(dt, v_new.z))});
  scatter4(a.orientation, idx, q_new);
  const Mat r_new = rotation_matrix(q_new);
  for (int c = 0; c < 9; ++c) scatter(a.rotation, 9, c, idx, r_new.m[c]);
  return true;
}

}  // namespace polydem::block_lanes
