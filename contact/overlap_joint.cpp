// The overlap joint model per pair (overlap_joint.hpp): the Winkler layer's
// integrals, the joint's shear and twist springs with their friction
// ellipse, the dashpots, and the pair's wrench on both blocks.
#include "contact/overlap_joint.hpp"

#include <algorithm>
#include <cmath>

namespace polydem {

void PairJoints::resize(std::size_t n) {
  ref_block.resize(n, 0);
  normal_local.resize(n, Vec3::UnitZ());
  offset_local.resize(n, 0.0);
  shear.resize(n, Vec3::Zero());
  twist.resize(n, 0.0);
  slip_energy.resize(n, 0.0);
  damping_energy.resize(n, 0.0);
  damping.resize(n, lanes::PairRest{});
  wrench.resize(n, lanes::PairRest{});
  normal_force.resize(n, 0.0);
  overlap.resize(n, 0.0);
  area.resize(n, 0.0);
  polar.resize(n, 0.0);
  strain_energy.resize(n, 0.0);
  sliding.resize(n, 0);
}

namespace {

// A wrench array as nine doubles per pair.
void put_wrenches(ByteWriter& w, const std::vector<lanes::PairRest>& v) {
  std::vector<double> flat;
  flat.reserve(9 * v.size());
  for (const lanes::PairRest& p : v) {
    flat.insert(flat.end(), p.force, p.force + 3);
    flat.insert(flat.end(), p.moment, p.moment + 3);
    flat.insert(flat.end(), p.moment_ref, p.moment_ref + 3);
  }
  w.put(flat);
}

void get_wrenches(ByteReader& r, std::vector<lanes::PairRest>& v, std::size_t n, const char* name) {
  std::vector<double> flat;
  r.get_sized(flat, 9 * n, name);
  v.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    std::copy(&flat[9 * q], &flat[9 * q] + 3, v[q].force);
    std::copy(&flat[9 * q + 3], &flat[9 * q + 3] + 3, v[q].moment);
    std::copy(&flat[9 * q + 6], &flat[9 * q + 6] + 3, v[q].moment_ref);
  }
}

}  // namespace

void PairJoints::save(ByteWriter& w) const {
  w.put(ref_block);
  w.put(normal_local);
  w.put(offset_local);
  w.put(shear);
  w.put(twist);
  w.put(slip_energy);
  w.put(damping_energy);
  put_wrenches(w, damping);
  put_wrenches(w, wrench);
  w.put(normal_force);
  w.put(overlap);
  w.put(area);
  w.put(polar);
  w.put(strain_energy);
  w.put(sliding);
}

void PairJoints::load(ByteReader& r, std::size_t n) {
  r.get_sized(ref_block, n, "pair_joints.ref_block");
  r.get_sized(normal_local, n, "pair_joints.normal_local");
  r.get_sized(offset_local, n, "pair_joints.offset_local");
  r.get_sized(shear, n, "pair_joints.shear");
  r.get_sized(twist, n, "pair_joints.twist");
  r.get_sized(slip_energy, n, "pair_joints.slip_energy");
  r.get_sized(damping_energy, n, "pair_joints.damping_energy");
  get_wrenches(r, damping, n, "pair_joints.damping");
  get_wrenches(r, wrench, n, "pair_joints.wrench");
  r.get_sized(normal_force, n, "pair_joints.normal_force");
  r.get_sized(overlap, n, "pair_joints.overlap");
  r.get_sized(area, n, "pair_joints.area");
  r.get_sized(polar, n, "pair_joints.polar");
  r.get_sized(strain_energy, n, "pair_joints.strain_energy");
  r.get_sized(sliding, n, "pair_joints.sliding");
}

namespace {

// The mean distance of a region's points from p over √(J_p/A): 0.943 for a
// disc, 0.938 for a square (overlap_joint.hpp).
constexpr double kTwistArm = 0.94;

Vec3 to_vec(const double (&a)[3]) { return Vec3(a[0], a[1], a[2]); }

void set(double (&a)[3], const Vec3& v) {
  a[0] = v.x();
  a[1] = v.y();
  a[2] = v.z();
}

// The power of a pair's wrench (force on the incident block c, moments about
// each block's centroid) at the blocks' velocities, W.
double wrench_power(const lanes::PairRest& w, const BlockState& st, int r, int c) {
  return to_vec(w.force).dot(st.velocity[c] - st.velocity[r]) + to_vec(w.moment).dot(st.angular_velocity[c]) +
         to_vec(w.moment_ref).dot(st.angular_velocity[r]);
}

// The rotation by the vector θ.
Mat3 turn(const Vec3& theta) {
  const double a = theta.norm();
  if (!(a > 0)) return Mat3::Identity();
  return Eigen::AngleAxisd(a, theta / a).toRotationMatrix();
}

// Adds the force f acting on c through the world point x to the pair's
// wrench (and its reaction on r, through the same point).
void add_force(lanes::PairRest& w, const Vec3& f, const Vec3& x, const Vec3& xc, const Vec3& xr) {
  set(w.force, to_vec(w.force) + f);
  set(w.moment, to_vec(w.moment) + (x - xc).cross(f));
  set(w.moment_ref, to_vec(w.moment_ref) - (x - xr).cross(f));
}

// Adds the couple m on c (and −m on r).
void add_couple(lanes::PairRest& w, const Vec3& m) {
  set(w.moment, to_vec(w.moment) + m);
  set(w.moment_ref, to_vec(w.moment_ref) - m);
}

// The elastic energy of a joint's shear layer holding the shear force f and
// the twisting moment t over a region of area A and polar moment J:
// |f|²/(2·ks·A) + t²/(2·ks·J), a term dropped where its stiffness is zero.
double shear_layer_energy(const Vec3& f, double t, double ks, double area, double polar) {
  const double ka = ks * area, kj = ks * polar;
  return (ka > 0 ? f.squaredNorm() / (2.0 * ka) : 0.0) + (kj > 0 ? t * t / (2.0 * kj) : 0.0);
}

}  // namespace

void overlap_joint_forces(const JointLaws& laws, const std::vector<Polyhedron>& shapes, const BlockState& st,
                          const std::vector<ContactPair>& pairs, Subcontacts& sub, PairJoints& j, double dt,
                          std::size_t begin, std::size_t end, OverlapScratch& scratch) {
  for (std::size_t q = begin; q < end; ++q) {
    const ContactPair& cp = pairs[q];
    // The sampled points: where they are and how far the joint is open there.
    const auto s0 = static_cast<std::size_t>(cp.first);
    {
      const int pr = cp.ref_block, pc = pr == cp.a ? cp.b : cp.a;
      const Vec3 pn = st.rotation[pr] * cp.normal_local;
      const double plane = cp.offset_local + pn.dot(st.position[pr]);
      for (std::size_t s = s0; s < s0 + static_cast<std::size_t>(cp.count); ++s) {
        const Vec3 x = st.rotation[pc] * sub.inc_point_local[s] + st.position[pc];
        sub.point[s] = x;
        sub.overlap[s] = plane - pn.dot(x);  // their force and normal force stay the zeros they were built with
      }
    }

    // The joint's own plane, carried in its reference block.
    const int r = j.ref_block[q];
    const int c = r == cp.a ? cp.b : cp.a;
    const JointLaw& law = laws.between(r, c);
    const Vec3& xr = st.position[r];
    const Vec3& xc = st.position[c];
    const Vec3 n = st.rotation[r] * j.normal_local[q];
    const double plane = j.offset_local[q] + n.dot(xr);

    // The second half of the last step's dashpot work, at the velocities now.
    j.damping_energy[q] -= 0.5 * dt * wrench_power(j.damping[q], st, r, c);
    j.damping[q] = lanes::PairRest{};
    j.wrench[q] = lanes::PairRest{};

    // The layer's integrals, in a frame on the joint's plane near the pair.
    const Vec3 mid = 0.5 * (xr + xc);
    const JointFrame frame = make_joint_frame(n, mid - (n.dot(mid) - plane) * n);
    const PosedBlock A{&shapes[static_cast<std::size_t>(r)], st.rotation[r], xr};
    const PosedBlock B{&shapes[static_cast<std::size_t>(c)], st.rotation[c], xc};
    const FacePair* cells = j.cells.data();
    const OverlapMoments m =
        overlap_integral(A, B, frame, cells + j.cell_first[q], cells + j.cell_first[q + 1], scratch);
    j.overlap[q] = m.max_overlap;
    const double area_before = j.area[q];
    j.area[q] = m.area;
    j.normal_force[q] = 0;
    j.sliding[q] = 0;
    if (!(m.volume > 0 && m.area > 0)) {  // apart: nothing carried, nothing stored
      // The cap fell to zero with the overlap: the stored shear and twist
      // slip off, friction's work their elastic energy (joint_law.hpp).
      j.slip_energy[q] += shear_layer_energy(j.shear[q], j.twist[q], law.ks, area_before, j.polar[q]);
      j.shear[q] = Vec3::Zero();
      j.twist[q] = 0;
      j.polar[q] = 0;
      j.strain_energy[q] = 0;
      continue;
    }

    const Vec2 pc = pressure_centroid(m);
    const Vec2 ac = m.area_moment / m.area;
    const Vec3 p = plane_point(frame, pc);    // the pressure centroid
    const Vec3 xa = plane_point(frame, ac);   // Ω's centroid
    const Vec3 dw = st.angular_velocity[c] - st.angular_velocity[r];
    auto relative_velocity = [&](const Vec3& x) -> Vec3 {
      return (st.velocity[c] + st.angular_velocity[c].cross(x - xc)) -
             (st.velocity[r] + st.angular_velocity[r].cross(x - xr));
    };
    const double area = m.area;
    const double polar = std::max(polar_moment(m, pc), 0.0);
    const double spin = n.dot(dw);

    // Normal: the elastic layer, and its dashpot (force at Ω's centroid and
    // the couple of the linear part of the normal velocity).
    const double n_elastic = law.kn * m.volume;
    double n_viscous = -law.beta * law.kn * area * n.dot(relative_velocity(xa));
    const Vec3 tilt = n.cross(dw);  // ∇v_n in the plane
    const Vec2 g(frame.e1.dot(tilt), frame.e2.dot(tilt));
    const Mat2 Jc = m.area_inertia - area * ac * ac.transpose();
    const Vec2 mq = -law.beta * law.kn * (Jc * g);
    Vec3 rocking = mq.y() * frame.e1 - mq.x() * frame.e2;
    if (n_elastic + n_viscous < 0) {  // the dashpot may not pull the pair together
      const double k = n_elastic / -n_viscous;
      n_viscous *= k;
      rocking *= k;
    }

    // Shear and twist: turned with the joint, onto the plane, scaled down
    // with the area where the region shrank (the sheared layer that left
    // the contact takes its stress: the elastic displacement stays), and
    // incremented. The layer leaves where its overlap, and so its pressure
    // and its friction, has fallen to zero: its stress slips off, and the
    // strain energy it held is friction's work. (Where the region grows the
    // new layer comes in unstressed and the force is kept: one uniform
    // shear over a larger area holds less energy, which the ledger's
    // numerical line shows.)
    const Vec3 theta = dt * (st.angular_velocity[r] + (0.5 * spin) * n);
    Vec3 fs = turn(theta) * j.shear[q];
    fs -= n.dot(fs) * n;
    const double polar_before = j.polar[q];
    double tw = j.twist[q];
    // What the shrinking parts held (a part that grew keeps its term, so
    // only the shrinking ones' release is booked).
    const bool shrank = area < area_before || polar < polar_before;
    const double before =
        shrank ? shear_layer_energy(fs, tw, law.ks, std::max(area, area_before), std::max(polar, polar_before)) : 0.0;
    if (area < area_before) fs *= area / area_before;
    if (polar < polar_before) tw *= polar / polar_before;
    // The elastic energy the joint holds before the step's increments.
    const double held = shear_layer_energy(fs, tw, law.ks, area, polar);
    if (shrank) j.slip_energy[q] += before - held;
    const Vec3 v = relative_velocity(p);
    const Vec3 vs = v - n.dot(v) * n;
    const double ks_area = law.ks * area, ks_polar = law.ks * polar;
    fs -= (ks_area * dt) * vs;
    tw -= ks_polar * dt * spin;

    // Friction: the ellipse (|F|/F_max)² + (T/T_max)² ≤ 1.
    const double n_friction = law.friction_on_total ? n_elastic + n_viscous : n_elastic;
    const double f_max = std::max(law.cohesion * area + law.tan_phi * n_friction, 0.0);
    const double t_max = kTwistArm * std::sqrt(polar / area) * f_max;
    auto ellipse = [&](const Vec3& f, double t) {
      return (f_max > 0 ? f.squaredNorm() / (f_max * f_max) : (f.squaredNorm() > 0 ? 1e300 : 0.0)) +
             (t_max > 0 ? t * t / (t_max * t_max) : (t != 0 ? 1e300 : 0.0));
    };
    const double e = ellipse(fs, tw);
    // With friction_on_total the whole shear and twist, springs and
    // dashpots, is what friction bounds: beyond it the joint slips and the
    // dashpots are off; the springs keep their trial up to the limit
    // (joint_law.hpp).
    const bool slipping =
        e > 1 || (law.friction_on_total && ellipse(fs - (law.beta * ks_area) * vs, tw - law.beta * ks_polar * spin) > 1);
    if (e > 1) {
      // Friction's work as the subcontacts' (joint_law.hpp): the slip from
      // the trial (scale 1) back to the limit (scale s) under a friction
      // force that falls from the scale the slip starts at, min(1,
      // max(held's, s)), to s.
      const double s = 1.0 / std::sqrt(e);
      const double trial = shear_layer_energy(fs, tw, law.ks, area, polar);
      const double start = trial > 0 ? std::min(1.0, std::max(std::sqrt(held / trial), s)) : s;
      j.slip_energy[q] += (1.0 - s) * (start + s) * trial;
      fs *= s;
      tw *= s;
    }
    j.shear[q] = fs;
    j.twist[q] = tw;
    j.polar[q] = polar;
    j.sliding[q] = slipping ? 1 : 0;

    // The dashpots' wrench: normal always, shear and twist while sticking.
    lanes::PairRest& d = j.damping[q];
    add_force(d, n_viscous * n, xa, xc, xr);
    add_couple(d, rocking);
    if (!slipping) {
      add_force(d, (-law.beta * ks_area) * vs, p, xc, xr);
      add_couple(d, (-law.beta * ks_polar * spin) * n);
    }
    lanes::PairRest& w = j.wrench[q];
    w = d;
    const JointLoad layer = joint_load(m, frame, law.kn, frame.origin);  // conservative: its work is −dW
    add_force(w, layer.force, frame.origin, xc, xr);
    add_couple(w, layer.moment);
    add_force(w, fs, p, xc, xr);
    add_couple(w, tw * n);
    j.normal_force[q] = n_elastic + n_viscous;
    j.strain_energy[q] = 0.5 * law.kn * m.overlap_squared + shear_layer_energy(fs, tw, law.ks, area, polar);
    // The first half of this dashpot work, at the velocities it came from.
    j.damping_energy[q] -= 0.5 * dt * wrench_power(d, st, r, c);
  }
}

namespace {

// ∫t² over the joint between blocks r and c on the plane (normal·x = offset
// in r's frame), every face pair considered: the layer's strain energy over
// ½kn.
double layer_overlap_squared(const std::vector<Polyhedron>& shapes, const BlockState& st, int r, int c,
                             const Vec3& normal_local, double offset_local, OverlapScratch& scratch) {
  const Vec3 n = st.rotation[r] * normal_local;
  const double plane = offset_local + n.dot(st.position[r]);
  const Vec3 mid = 0.5 * (st.position[r] + st.position[c]);
  const JointFrame frame = make_joint_frame(n, mid - (n.dot(mid) - plane) * n);
  const PosedBlock A{&shapes[static_cast<std::size_t>(r)], st.rotation[r], st.position[r]};
  const PosedBlock B{&shapes[static_cast<std::size_t>(c)], st.rotation[c], st.position[c]};
  return overlap_integral(A, B, frame, scratch).overlap_squared;
}

}  // namespace

int rechoose_joint_planes(const std::vector<Polyhedron>& shapes, const BlockState& st,
                          const std::vector<ContactPair>& pairs, PairJoints& j, OverlapScratch& scratch) {
  int changed = 0;
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    const ContactPair& cp = pairs[q];
    if (j.ref_block[q] == cp.ref_block && j.normal_local[q] == cp.normal_local &&
        j.offset_local[q] == cp.offset_local)
      continue;
    const int r = j.ref_block[q];
    if (layer_overlap_squared(shapes, st, r, r == cp.a ? cp.b : cp.a, j.normal_local[q], j.offset_local[q],
                              scratch) > 0)
      continue;  // closed on its plane: kept
    const int rd = cp.ref_block;
    if (layer_overlap_squared(shapes, st, rd, rd == cp.a ? cp.b : cp.a, cp.normal_local, cp.offset_local,
                              scratch) > 0)
      continue;  // the detection's plane would load it: no force may appear at a detection
    j.ref_block[q] = cp.ref_block;
    j.normal_local[q] = cp.normal_local;
    j.offset_local[q] = cp.offset_local;
    ++changed;
  }
  return changed;
}

void find_joint_cells(const std::vector<Polyhedron>& shapes, const BlockState& st,
                      const std::vector<ContactPair>& pairs, const Subcontacts& sub, double reach, PairJoints& j,
                      OverlapScratch& scratch) {
  j.cell_first.assign(pairs.size() + 1, 0);
  j.cells.clear();
  std::vector<FacePair>& found = scratch.face_pairs;
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    const ContactPair& cp = pairs[q];
    const int r = j.ref_block[q];
    const int c = r == cp.a ? cp.b : cp.a;
    const PosedBlock A{&shapes[static_cast<std::size_t>(r)], st.rotation[r], st.position[r]};
    const PosedBlock B{&shapes[static_cast<std::size_t>(c)], st.rotation[c], st.position[c]};
    const Vec3 n = st.rotation[r] * j.normal_local[q];
    overlap_face_pairs(A, B, n, reach, found, scratch);
    j.cells.insert(j.cells.end(), found.begin(), found.end());
    j.cell_first[q + 1] = static_cast<int>(j.cells.size());
  }
}

void settle_pair_damping(const BlockState& st, const std::vector<ContactPair>& pairs, PairJoints& j, double dt) {
  for (std::size_t q = 0; q < j.size(); ++q) {
    const ContactPair& cp = pairs[q];
    const int r = j.ref_block[q];
    const int c = r == cp.a ? cp.b : cp.a;
    j.damping_energy[q] -= 0.5 * dt * wrench_power(j.damping[q], st, r, c);
    j.damping[q] = lanes::PairRest{};
  }
}

void carry_pair_joints(const ContactSet& previous, ContactSet& current) {
  const PairJoints& old = previous.joints;
  PairJoints& now = current.joints;
  now = PairJoints{};
  now.resize(current.pairs.size());
  current.retired_slip_energy = previous.retired_slip_energy;
  current.retired_damping_energy = previous.retired_damping_energy;
  std::vector<char> taken(old.size(), 0);
  for (std::size_t q = 0; q < current.pairs.size(); ++q) {
    const ContactPair& cp = current.pairs[q];
    const ContactPair* op = old.size() == previous.pairs.size() ? find_pair(previous, cp.a, cp.b) : nullptr;
    if (!op) {  // a new joint: the plane the detection chose
      now.ref_block[q] = cp.ref_block;
      now.normal_local[q] = cp.normal_local;
      now.offset_local[q] = cp.offset_local;
      continue;
    }
    const auto o = static_cast<std::size_t>(op - previous.pairs.data());
    taken[o] = 1;
    now.ref_block[q] = old.ref_block[o];
    now.normal_local[q] = old.normal_local[o];
    now.offset_local[q] = old.offset_local[o];
    now.shear[q] = old.shear[o];
    now.twist[q] = old.twist[o];
    now.slip_energy[q] = old.slip_energy[o];
    now.damping_energy[q] = old.damping_energy[o];
    now.strain_energy[q] = old.strain_energy[o];
    now.area[q] = old.area[o];
    now.polar[q] = old.polar[o];
  }
  for (std::size_t o = 0; o < old.size(); ++o) {
    if (taken[o]) continue;
    current.retired_slip_energy += old.slip_energy[o];
    current.retired_damping_energy += old.damping_energy[o];
  }
}

PairJointEnergies pair_joint_energies(const ContactSet& contacts) {
  PairJointEnergies e;
  e.slip = contacts.retired_slip_energy;
  e.damping = contacts.retired_damping_energy;
  const PairJoints& j = contacts.joints;
  for (std::size_t q = 0; q < j.size(); ++q) {
    e.strain += j.strain_energy[q];
    e.slip += j.slip_energy[q];
    e.damping += j.damping_energy[q];
  }
  return e;
}

}  // namespace polydem
