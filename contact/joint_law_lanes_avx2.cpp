// The joint law in AVX2 lanes (see joint_law_lanes.hpp). This file is
// compiled with -mavx2 on x86-64 only; it must include nothing that
// instantiates inline code shared with other files (no Eigen, no std::
// algorithms): only core/avx2_lanes.hpp and functions local to this file.
//
// Each stage below names the portable code of joint_law.cpp it mirrors; the
// order of every addition and multiplication is the portable one (see the
// header for Eigen's association), so the bits are the same.
#include "contact/joint_law_lanes.hpp"

#include "core/avx2_lanes.hpp"

#include <cstring>

namespace polydem::lanes {
namespace {

using namespace avx2;

// std::max(a, 0.0) is (a < 0) ? 0 : a; MAXPD(0, a) is (0 > a) ? 0 : a: the
// same for every a, −0 and NaN included. std::min(a, b) is (b < a) ? b : a,
// which is MINPD(b, a).
inline V max_zero(V a) { return _mm256_max_pd(_mm256_setzero_pd(), a); }
inline V min_std(V a, V b) { return _mm256_min_pd(b, a); }

// m·(x, y, z), m column-major: rows 0 and 1 ((a + b) + c), row 2 a + (b + c).
inline void mat_vec(const double* m, V x, V y, V z, V& ox, V& oy, V& oz) {
  ox = add(add(mul(bc(m[0]), x), mul(bc(m[3]), y)), mul(bc(m[6]), z));
  oy = add(add(mul(bc(m[1]), x), mul(bc(m[4]), y)), mul(bc(m[7]), z));
  oz = add(mul(bc(m[2]), x), add(mul(bc(m[5]), y), mul(bc(m[8]), z)));
}

// The lanes of one group of up to four subcontacts.
struct Group {
  bool full;
  int count;
  __m256i mask;
};

inline Group group(std::size_t left) {
  Group g;
  g.count = left >= 4 ? 4 : static_cast<int>(left);
  g.full = g.count == 4;
  g.mask = _mm256_cmpgt_epi64(_mm256_set1_epi64x(g.count), _mm256_setr_epi64x(0, 1, 2, 3));
  return g;
}
inline V load(const double* p, const Group& g) { return g.full ? _mm256_loadu_pd(p) : _mm256_maskload_pd(p, g.mask); }
inline void store(double* p, V v, const Group& g) {
  if (g.full)
    _mm256_storeu_pd(p, v);
  else
    _mm256_maskstore_pd(p, g.mask, v);
}
// Three lanes' vectors into a Vec3 array (x y z per subcontact). A full
// group as three stores: x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3, each
// gathered from the three vectors turned so that every lane is in place.
inline void store_vec3(double* p, V x, V y, V z, const Group& g) {
  if (g.full) {
    const V xp = _mm256_permute4x64_pd(x, 0x6C);  // x0 x3 x2 x1
    const V yp = _mm256_permute4x64_pd(y, 0xB1);  // y1 y0 y3 y2
    const V zp = _mm256_permute4x64_pd(z, 0xC6);  // z2 z1 z0 z3
    _mm256_storeu_pd(p, _mm256_blend_pd(_mm256_blend_pd(xp, yp, 0x2), zp, 0x4));
    _mm256_storeu_pd(p + 4, _mm256_blend_pd(_mm256_blend_pd(yp, zp, 0x2), xp, 0x4));
    _mm256_storeu_pd(p + 8, _mm256_blend_pd(_mm256_blend_pd(zp, xp, 0x2), yp, 0x4));
    return;
  }
  alignas(32) double tx[4], ty[4], tz[4];
  _mm256_store_pd(tx, x);
  _mm256_store_pd(ty, y);
  _mm256_store_pd(tz, z);
  for (int k = 0; k < g.count; ++k) {
    p[3 * k] = tx[k];
    p[3 * k + 1] = ty[k];
    p[3 * k + 2] = tz[k];
  }
}

// The bonded flags (bytes 0 or 1) of the group's lanes as a lane mask.
inline V load_bonded(const std::uint8_t* p, const Group& g) {
  std::uint32_t bytes = 0;
  if (g.full)
    std::memcpy(&bytes, p, 4);
  else
    for (int k = 0; k < g.count; ++k) bytes |= static_cast<std::uint32_t>(p[k]) << (8 * k);
  const __m256i b = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(static_cast<int>(bytes)));
  return _mm256_castsi256_pd(_mm256_cmpgt_epi64(b, _mm256_setzero_si256()));
}

// A lane mask back to bonded bytes 0 or 1: bit k of the mask to byte k.
inline void store_bonded(std::uint8_t* p, V m, const Group& g) {
  const std::uint32_t bits = static_cast<std::uint32_t>(_mm256_movemask_pd(m));
  const std::uint32_t bytes = (bits * 0x00204081u) & 0x01010101u;
  if (g.full) {
    std::memcpy(p, &bytes, 4);
    return;
  }
  for (int k = 0; k < g.count; ++k) p[k] = static_cast<std::uint8_t>(bytes >> (8 * k));
}

}  // namespace

void pair_law(const PairFrame& f, const LawConstants& law, const SubcontactArrays& a, std::size_t s0,
              std::size_t count) {
  const V zero = _mm256_setzero_pd();
  const V nx = bc(f.n[0]), ny = bc(f.n[1]), nz = bc(f.n[2]);
  const V kn = bc(law.kn), ks = bc(law.ks), dt = bc(law.dt);
  const V half_dt = bc(0.5 * law.dt);  // `0.5 * dt * x` is (0.5·dt)·x
  const V ks_positive = all_lanes(law.ks > 0);
  const V no_tensile_strength = all_lanes(law.tensile_strength == 0);
  for (std::size_t k = 0; k < count; k += 4) {
    const std::size_t s = s0 + k;
    const Group g = group(count - k);

    // Kinematics (pair_forces): arm_c = Rc·inc_point_local; p = x_c + arm_c.
    V ax, ay, az;
    mat_vec(f.Rc, load(a.ipx + s, g), load(a.ipy + s, g), load(a.ipz + s, g), ax, ay, az);
    const V px = add(bc(f.xc[0]), ax), py = add(bc(f.xc[1]), ay), pz = add(bc(f.xc[2]), az);
    // un = ref_offset_local + plane − n·p.
    const V un = sub(add(load(a.offset + s, g), bc(f.plane)), dot3(nx, ny, nz, px, py, pz));
    // vrel = dv + ω_c × arm_c − ω_r × (arm_c + x_cr), left to right.
    const V qx = add(ax, bc(f.xcr[0])), qy = add(ay, bc(f.xcr[1])), qz = add(az, bc(f.xcr[2]));
    const V wcx = bc(f.wc[0]), wcy = bc(f.wc[1]), wcz = bc(f.wc[2]);
    const V wrx = bc(f.wr[0]), wry = bc(f.wr[1]), wrz = bc(f.wr[2]);
    const V vx = sub(add(bc(f.dv[0]), sub(mul(wcy, az), mul(wcz, ay))), sub(mul(wry, qz), mul(wrz, qy)));
    const V vy = sub(add(bc(f.dv[1]), sub(mul(wcz, ax), mul(wcx, az))), sub(mul(wrz, qx), mul(wrx, qz)));
    const V vz = sub(add(bc(f.dv[2]), sub(mul(wcx, ay), mul(wcy, ax))), sub(mul(wrx, qy), mul(wry, qx)));
    store_vec3(a.point + 3 * s, px, py, pz, g);
    store(a.overlap + s, un, g);

    // subcontact_law.
    const V vn = dot3(vx, vy, vz, nx, ny, nz);
    const V vsx = sub(vx, mul(vn, nx)), vsy = sub(vy, mul(vn, ny)), vsz = sub(vz, mul(vn, nz));
    const V A = load(a.area + s, g);
    const V bonded = load_bonded(a.bonded + s, g);
    const V dfx = load(a.dfx + s, g), dfy = load(a.dfy + s, g), dfz = load(a.dfz + s, g);
    const V pending = neg(dot3(dfx, dfy, dfz, vx, vy, vz));
    const V fn_el = mul(mul(kn, A), un);
    const V un_closed_not = le(un, zero);  // un <= 0
    const V broken = both(bonded, lt(fn_el, mul(bc(-law.tensile_strength), A)));
    const V loses_bond = either(broken, both(un_closed_not, no_tensile_strength));
    const V still_bonded = but_not(bonded, loses_bond);
    // open_joint: un <= 0 and not bonded, or the bond just lost with un <= 0.
    const V open = both(un_closed_not, either(_mm256_xor_pd(bonded, all_lanes(true)), loses_bond));

    const V sfx = load(a.sfx + s, g), sfy = load(a.sfy + s, g), sfz = load(a.sfz + s, g);
    const V slip0 = load(a.slip_energy + s, g);
    const V damp0 = load(a.damping_energy + s, g);
    const V ksA = mul(ks, A);
    const V energy_counts = both(ks_positive, gt(A, zero));  // law.ks > 0 && A > 0
    // open_joint's ledger: 0.5·|F_s|²/(ks·A) of slip, (0.5·dt)·pending of damping.
    // Divisions and square roots are the slow instructions: only for a
    // group with an open or a slipping lane.
    const int lane_bits = (1 << g.count) - 1;
    const int open_lanes = _mm256_movemask_pd(open) & lane_bits;
    V slip_open = slip0;
    if (open_lanes)
      slip_open = pick(energy_counts, add(slip0, div(mul(bc(0.5), dot3(sfx, sfy, sfz, sfx, sfy, sfz)), ksA)), slip0);
    const V damp_open = add(damp0, mul(half_dt, pending));

    // Shear: fs = Q·F_s, fs −= (fs·n)·n, fs −= ((ks·A)·dt)·vs.
    V fx, fy, fz;
    mat_vec(f.spin, sfx, sfy, sfz, fx, fy, fz);
    const V fdn = dot3(fx, fy, fz, nx, ny, nz);
    fx = sub(fx, mul(fdn, nx));
    fy = sub(fy, mul(fdn, ny));
    fz = sub(fz, mul(fdn, nz));
    const V fs_old2 = dot3(fx, fy, fz, fx, fy, fz);
    const V kdt = mul(ksA, dt);
    fx = sub(fx, mul(kdt, vsx));
    fy = sub(fy, mul(kdt, vsy));
    fz = sub(fz, mul(kdt, vsz));
    const V cap = add(pick(still_bonded, mul(bc(law.cohesion), A), zero), mul(max_zero(fn_el), bc(law.tan_phi)));
    const V f2 = dot3(fx, fy, fz, fx, fy, fz);
    const V slipping = gt(f2, mul(cap, cap));
    V slip_closed = slip0;
    if (_mm256_movemask_pd(slipping) & lane_bits) {
      const V fs_mag = _mm256_sqrt_pd(f2);
      const V a_old = _mm256_sqrt_pd(fs_old2);
      const V m = pick(gt(a_old, cap), min_std(a_old, fs_mag), cap);
      const V slip_inc = div(add(mul(mul(bc(0.5), sub(m, cap)), add(m, cap)), mul(cap, sub(fs_mag, m))), ksA);
      slip_closed = pick(both(slipping, energy_counts), add(slip0, slip_inc), slip0);
      const V factor = pick(gt(fs_mag, zero), div(cap, fs_mag), zero);
      fx = pick(slipping, mul(fx, factor), fx);
      fy = pick(slipping, mul(fy, factor), fy);
      fz = pick(slipping, mul(fz, factor), fz);
    }
    const V bonded_after = but_not(still_bonded, slipping);

    // Damping while closed: fn += ((β·kn)·A)·(−vn); fs_damp = −((β·ks)·A)·vs unless slipping.
    const V un_positive = gt(un, zero);
    V fn_total = pick(un_positive, add(fn_el, mul(mul(bc(law.beta * law.kn), A), neg(vn))), fn_el);
    const V shear_damped = but_not(un_positive, slipping);
    const V cs = neg(mul(bc(law.beta * law.ks), A));
    const V fdsx = pick(shear_damped, mul(cs, vsx), zero);
    const V fdsy = pick(shear_damped, mul(cs, vsy), zero);
    const V fdsz = pick(shear_damped, mul(cs, vsz), zero);
    fn_total = pick(but_not(lt(fn_total, zero), bonded_after), zero, fn_total);  // no tension unbonded
    const V fn_damp = sub(fn_total, fn_el);
    const V fdampx = add(mul(fn_damp, nx), fdsx);
    const V fdampy = add(mul(fn_damp, ny), fdsy);
    const V fdampz = add(mul(fn_damp, nz), fdsz);
    const V damp_closed = add(damp0, mul(half_dt, sub(pending, dot3(fdampx, fdampy, fdampz, vx, vy, vz))));
    const V forcex = add(add(mul(fn_total, nx), fx), fdsx);
    const V forcey = add(add(mul(fn_total, ny), fy), fdsy);
    const V forcez = add(add(mul(fn_total, nz), fz), fdsz);

    // The open lanes take open_joint's values.
    store(a.slip_energy + s, pick(open, slip_open, slip_closed), g);
    store(a.damping_energy + s, pick(open, damp_open, damp_closed), g);
    store(a.dfx + s, pick(open, zero, fdampx), g);
    store(a.dfy + s, pick(open, zero, fdampy), g);
    store(a.dfz + s, pick(open, zero, fdampz), g);
    store(a.normal_force + s, pick(open, zero, fn_total), g);
    store(a.sfx + s, pick(open, zero, fx), g);
    store(a.sfy + s, pick(open, zero, fy), g);
    store(a.sfz + s, pick(open, zero, fz), g);
    store_vec3(a.force + 3 * s, pick(open, zero, forcex), pick(open, zero, forcey), pick(open, zero, forcez), g);
    store_bonded(a.bonded + s, pick(open, zero, bonded_after), g);
  }
}

}  // namespace polydem::lanes
