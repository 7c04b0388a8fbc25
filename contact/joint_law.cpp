#include "contact/joint_law.hpp"

#include "contact/joint_law_kernels.hpp"

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
  law.friction_on_total = spec.friction_normal == FrictionNormal::total;
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

// The pair's common normal in the world, R_ref·nl, in Eigen's association
// (R·v is ((a + b) + c) in rows 0 and 1 and a + (b + c) in row 2).
[[gnu::always_inline]] inline void world_normal(const double* Rr, const Vec3& nl, double* n) {
  const double l0 = nl.x(), l1 = nl.y(), l2 = nl.z();
  n[0] = (Rr[0] * l0 + Rr[3] * l1) + Rr[6] * l2;
  n[1] = (Rr[1] * l0 + Rr[4] * l1) + Rr[7] * l2;
  n[2] = Rr[2] * l0 + (Rr[5] * l1 + Rr[8] * l2);
}

// The kernels' PairFrame of the pair (r reference, c incident, `nl` the
// reference face's normal in r's frame), in plain doubles with Eigen's
// association (a dot product (x·x′ + y·y′) + z·z′), without Eigen's SSE2
// shuffles between the packed and the scalar part of a Vec3. A joint
// turning beyond rotation_matrix's series takes rotation_matrix itself,
// with the same θ.
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

// The kernels of `path` on this machine (core/code_path.hpp).
lanes::JointLawKernels joint_law_kernels(CodePath path) {
#ifdef POLYDEM_LANES_AVX2
  if (use_wide_lanes(path)) return {&lanes::pair_law_avx512, &lanes::pair_rest_avx512};
  if (use_lanes(path)) return {&lanes::pair_law_avx2, &lanes::pair_rest_avx2};
#endif
  return {&lanes::pair_law_portable, &lanes::pair_rest_portable};
}

}  // namespace

void compute_pair_forces(const JointLaws& laws, const BlockState& st, const std::vector<ContactPair>& pairs,
                         Subcontacts& sub, double dt, std::size_t pair_begin, std::size_t pair_end,
                         CodePath path, const SplitPart& split) {
  const lanes::PairLawKernel kernel = joint_law_kernels(path).law;
  lanes::SubcontactArrays arrays = lane_arrays(sub);
  arrays.dashpot = split.dashpot;
  for (std::size_t q = pair_begin; q < pair_end; ++q) {
    const ContactPair& cp = pairs[q];
    if (cp.count == 0) continue;
    const int r = cp.ref_block;
    const int c = cp.ref_block == cp.a ? cp.b : cp.a;
    const JointLaw& law = laws.between(r, c);
    // Shared by the pair's subcontacts: the common plane and both motions.
    const std::size_t s0 = static_cast<std::size_t>(cp.first);
    lanes::PairFrame f;
    pair_frame(st, r, c, sub.ref_normal_local[s0], dt, f);
    JointLaw applied = law;
    applied.beta = law.beta * split.explicit_part;
    kernel(f, applied, dt, arrays, s0, static_cast<std::size_t>(cp.count));
  }
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
  const lanes::PairRestKernel kernel = joint_law_kernels(path).rest;
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
  settle_damping_work(st, sub, dt, 0, static_cast<int>(sub.size()));
}

void settle_damping_work(const BlockState& st, Subcontacts& sub, double dt, int first, int last) {
  for (int s = first; s < last; ++s) {
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

// ½·kn·A·u² of subcontact s at overlap u: closed, or open and bonded.
double normal_strain(const JointLaws& laws, const Subcontacts& sub, std::size_t s, double u) {
  const JointLaw& law = laws.between(sub.ref_block[s], sub.inc_block[s]);
  return u > 0 || sub.bonded[s] ? 0.5 * law.kn * sub.area[s] * u * u : 0.0;
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
  for (std::size_t s = 0; s < sub.size(); ++s) e += normal_strain(laws, sub, s, un[s]);
  return e;
}

double normal_strain_energy_now(const JointLaws& laws, const BlockState& st, const Subcontacts& sub, int first,
                                int last) {
  double e = 0;
  for (int s = first; s < last; ++s) {
    const auto k = static_cast<std::size_t>(s);
    e += normal_strain(laws, sub, k, overlap_now(st, sub, k));
  }
  return e;
}

void hold_normal_strain(const JointLaws& laws, const BlockState& st, const ContactSet& old, ContactSet& contacts,
                        int threads, const std::vector<int>* sampled) {
  Subcontacts& sc = contacts.sub;
  const Subcontacts& os = old.sub;
  // Pair by pair, in parallel: a pair writes only its own subcontacts.
  const std::ptrdiff_t n_pairs = static_cast<std::ptrdiff_t>(sampled ? sampled->size() : contacts.pairs.size());
#pragma omp parallel for schedule(dynamic, 32) if (threads > 1 && n_pairs >= 256) num_threads(threads)
  for (std::ptrdiff_t m = 0; m < n_pairs; ++m) {
    const std::size_t q = sampled ? static_cast<std::size_t>((*sampled)[static_cast<std::size_t>(m)])
                                  : static_cast<std::size_t>(m);
    const ContactPair& cp = contacts.pairs[q];
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
  return shear_strain_energy(laws, sub, 0, static_cast<int>(sub.size()));
}

double shear_strain_energy(const JointLaws& laws, const Subcontacts& sub, int first, int last) {
  double e = 0;
  for (int s = first; s < last; ++s) {
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

std::vector<int> acting_laws(const JointLaws& laws, const std::vector<char>& among) {
  std::vector<int> in_slot(static_cast<std::size_t>(laws.slots), 0);
  for (std::size_t i = 0; i < laws.block_slot.size(); ++i)
    if (among.empty() || among[i]) ++in_slot[static_cast<std::size_t>(laws.block_slot[i])];
  std::vector<char> acts(laws.laws.size(), 0);
  for (int a = 0; a < laws.slots; ++a)
    for (int b = a; b < laws.slots; ++b) {
      const int na = in_slot[static_cast<std::size_t>(a)], nb = in_slot[static_cast<std::size_t>(b)];
      if (a == b ? na >= 2 : na >= 1 && nb >= 1)
        acts[static_cast<std::size_t>(laws.pair_law[static_cast<std::size_t>(a * laws.slots + b)])] = 1;
    }
  std::vector<int> out;
  for (std::size_t k = 0; k < acts.size(); ++k)
    if (acts[k]) out.push_back(static_cast<int>(k));
  if (out.empty()) out.push_back(0);
  return out;
}

JointLaw stiffest_law(const JointLaws& laws) {
  JointLaw out;
  bool first = true;
  for (const int k : acting_laws(laws)) {
    const JointLaw& j = laws.laws[static_cast<std::size_t>(k)];
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
