#include "contact/clip_joint.hpp"

#include "contact/joint_law.hpp"
#include "contact/moving_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace polydem {

namespace {

// The unit normal of the reference face's side plane `side` (out of the
// face), from the world vertices, as the clip computes it.
Vec3 side_normal(const std::vector<Vec3>& ref_w, const std::vector<int>& rface, int side, const Vec3& n) {
  const auto k = static_cast<std::size_t>(side);
  const Vec3 m = (ref_w[static_cast<std::size_t>(rface[(k + 1) % rface.size()])] -
                  ref_w[static_cast<std::size_t>(rface[k])])
                     .cross(n);
  const double len = m.norm();
  return len > 0 ? Vec3(m / len) : Vec3(Vec3::Zero());
}

}  // namespace

ClipLoad clip_normal_load(const PosedBlock& ref, int ref_face, const PosedBlock& inc, int inc_face, const Vec3& n,
                          double c, double kn, double face_area_min, ClipScratch& s) {
  const Polyhedron& rp = *ref.shape;
  const Polyhedron& ip = *inc.shape;
  const auto& rface = rp.faces[static_cast<std::size_t>(ref_face)];
  const auto& iface = ip.faces[static_cast<std::size_t>(inc_face)];
  if (s.ref_w.size() < rp.vertices.size()) s.ref_w.resize(rp.vertices.size());
  if (s.inc_w.size() < ip.vertices.size()) s.inc_w.resize(ip.vertices.size());
  for (int v : rface) s.ref_w[static_cast<std::size_t>(v)] = ref.R * rp.vertices[static_cast<std::size_t>(v)] + ref.x;
  for (int v : iface) s.inc_w[static_cast<std::size_t>(v)] = inc.R * ip.vertices[static_cast<std::size_t>(v)] + inc.x;
  PatchScratch& ps = s.patch;
  clip_incident_face(s.ref_w, rface, n, s.inc_w, iface, ps);
  merge_coincident_vertices(ps);
  ClipLoad load;
  const std::size_t np = ps.poly.size();
  s.area.assign(np, 0.0);
  s.u.resize(np);
  s.on_plane.resize(np);
  for (std::size_t j = 0; j < np; ++j) {
    s.u[j] = c - n.dot(ps.poly[j]);
    s.on_plane[j] = ps.poly[j] + s.u[j] * n;
  }
  if (np < 3) return load;
  const double total = corner_areas(s.on_plane.data(), np, n, kClipNoArea * face_area_min, s.area.data());
  if (total <= kClipNoArea * face_area_min) {
    std::fill(s.area.begin(), s.area.end(), 0.0);
    return load;
  }
  load.area = total;
  double signed_area = 0;
  for (std::size_t j = 1; j + 1 < np; ++j)
    signed_area += (s.on_plane[j] - s.on_plane[0]).cross(s.on_plane[j + 1] - s.on_plane[0]).dot(n);
  const double orientation = signed_area > 0 ? 1.0 : -1.0;
  const Vec3 m_inc = inc.R * ip.normals[static_cast<std::size_t>(inc_face)];
  const double mn = m_inc.dot(n);
  Vec3 F = Vec3::Zero(), M = Vec3::Zero();  // the rest, on the incident block about its centroid
  Vec3 F_springs = Vec3::Zero(), M_springs = Vec3::Zero();
  for (std::size_t j = 0; j < np; ++j) {
    const double u = s.u[j];
    if (!(u > 0)) continue;
    const double A = s.area[j];
    load.energy += 0.5 * kn * A * u * u;
    const Vec3 arm = ps.poly[j] - inc.x;
    const Vec3 f_n = (kn * A * u) * n;
    F_springs += f_n;
    M_springs += arm.cross(f_n);
    const PointDefinition& def = ps.poly_def[j];
    Vec3 f = Vec3::Zero();
    if (def.kind == PointKind::incident_edge) {
      // The crossing slides along e as the side plane s cuts it:
      // δu = −(n − ((n·e)/(s·e))·s)·δx of the edge's material point.
      const Vec3 e = s.inc_w[static_cast<std::size_t>(def.v1)] - s.inc_w[static_cast<std::size_t>(def.v0)];
      const Vec3 sn = side_normal(s.ref_w, rface, def.side, n);
      const double se = sn.dot(e);
      if (se != 0) f = (-kn * A * u * n.dot(e) / se) * sn;
    } else if (def.kind == PointKind::reference_corner) {
      // The incident face's plane moving under a fixed ray along n:
      // δu = −(m·δx)/(m·n).
      if (std::abs(mn) > 1e-9) f = (kn * A * u) * (m_inc / mn - n);
    }
    F += f;
    M += arm.cross(f);
  }
  // The areas' part. E = (E/|P|)·|P| with the shares θ_i/2π: the polygon's
  // area moves with each incident edge's line (C1 = E/|P| a unit of area),
  // and the corners' angles with the lines' turns (C2 = ½·kn·|P|/2π a unit
  // of angle and of u²).
  if (load.energy > 0) {
    const double C1 = load.energy / total;
    const double C2 = 0.5 * kn * total / (2.0 * std::numbers::pi);
    for (std::size_t j = 0; j < np; ++j) {
      const PatchScratch::EdgeLine& line = ps.poly_edge[j];
      if (line.side >= 0) continue;  // a side plane of the reference face: fixed in the reference block
      const std::size_t k = (j + 1) % np;
      const Vec3 d = s.on_plane[k] - s.on_plane[j];
      const Vec3 Lnu = orientation * d.cross(n);  // length × outward normal
      const Vec3 mid = 0.5 * (ps.poly[j] + ps.poly[k]);
      F -= C1 * Lnu;
      M -= C1 * (mid - inc.x).cross(Lnu);
      const double uj = std::max(s.u[j], 0.0), uk = std::max(s.u[k], 0.0);
      const double w = uj * uj - uk * uk;
      if (w == 0) continue;
      const Vec3 e = s.inc_w[static_cast<std::size_t>(line.v1)] - s.inc_w[static_cast<std::size_t>(line.v0)];
      const Vec3 p = e - e.dot(n) * n;
      const double p2 = p.squaredNorm();
      if (p2 > 0) M -= (C2 * w * orientation / p2) * e.cross(n.cross(p));
    }
  }
  load.rest_force = F;
  load.rest_moment = M;
  load.force = F + F_springs;
  load.moment = M + M_springs;
  return load;
}

namespace {

// Whether a detection at the blocks' poses now would keep the pair's
// common plane (ref_face of ref) and incident face (inc_face of inc):
// build_patch's choices with the pair's as the previous ones. `depth`
// gets the face test's overlap along the plane (minus its separation).
bool faces_still_chosen(const PosedBlock& ref, const PosedBlock& inc, bool ref_is_a, int ref_face, int inc_face,
                        double margin, PatchScratch& s, double& depth) {
  const PosedBlock& a = ref_is_a ? ref : inc;
  const PosedBlock& b = ref_is_a ? inc : ref;
  world_vertices(a, s.world_a);
  world_vertices(b, s.world_b);
  double sep_a = 0, sep_b = 0;
  const int side = ref_is_a ? 0 : 1;
  const CommonPlane plane = choose_common_plane(a, b, s.world_a, s.world_b, margin, side, ref_face, sep_a, sep_b);
  depth = -plane.separation;
  if (plane.ref_side != side || plane.ref_face != ref_face || plane.separation > margin) return false;
  const Vec3 n = ref.R * ref.shape->normals[static_cast<std::size_t>(ref_face)];
  return choose_incident_face(inc, n, inc_face) == inc_face;
}

// clip_pairs' work for pair q.
void clip_pair(const std::vector<Polyhedron>& shapes, const BlockState& st, const JointLaws& laws,
               const std::vector<ContactPair>& pairs, double margin, Subcontacts& sub,
               std::vector<lanes::PairRest>& rest, std::vector<std::uint8_t>& stale, std::vector<double>& shear_dropped,
               std::size_t q, ClipScratch& s, const std::vector<std::vector<double>>* face_areas, bool check_faces) {
  auto area_of = [&](int block, const Polyhedron& p, int face) {
    return face_areas ? (*face_areas)[static_cast<std::size_t>(block)][static_cast<std::size_t>(face)]
                      : face_area(p, face);
  };
  const ContactPair& cp = pairs[q];
  lanes::PairRest& w = rest[q];
  w = lanes::PairRest{};
  stale[q] = 0;
  shear_dropped[q] = 0;
  if (cp.count == 0 || cp.ref_face < 0) return;
  const int r = cp.ref_block;
  const int i = cp.ref_block == cp.a ? cp.b : cp.a;
  const auto s0 = static_cast<std::size_t>(cp.first);
  const Polyhedron& rp = shapes[static_cast<std::size_t>(r)];
  const Polyhedron& ip = shapes[static_cast<std::size_t>(i)];
  const PosedBlock ref{&rp, st.rotation[r], st.position[r]};
  const PosedBlock inc{&ip, st.rotation[i], st.position[i]};
  const Vec3 n = st.rotation[r] * sub.ref_normal_local[s0];
  const double c = sub.ref_offset_local[s0] + n.dot(st.position[r]);
  const double c_geometric = cp.offset_local + n.dot(st.position[r]);
  const double face_area_min = std::min(area_of(r, rp, cp.ref_face), area_of(i, ip, cp.inc_face));
  const double kn = laws.between(r, i).kn;
  // The faces a detection would choose at this pose (the common plane, the
  // incident face, each kept within its tolerance, and the pair within the
  // margin): another choice, and the pair is re-sampled.
  double depth = 0;
  if (check_faces && !faces_still_chosen(ref, inc, r == cp.a, cp.ref_face, cp.inc_face, margin, s.patch, depth)) {
    stale[q] = 1;
    move_points(st, pairs, sub, q, q + 1);
    return;
  }
  const ClipLoad load = clip_normal_load(ref, cp.ref_face, inc, cp.inc_face, n, c, kn, face_area_min, s);
  // A face test that finds the blocks overlapping by more than the
  // polygon's deepest vertex, by a quarter of the margin, is how a
  // detection tells an edge-to-edge contact (build_patch, with MPR's depth
  // for the polygon's): the pair is re-sampled for the detection to judge.
  if (check_faces) {
    double deepest = -std::numeric_limits<double>::infinity();
    for (const Vec3& x : s.patch.poly) deepest = std::max(deepest, c_geometric - n.dot(x));
    if (depth > deepest + 0.25 * margin + 1e-12) {
      stale[q] = 1;
      move_points(st, pairs, sub, q, q + 1);
      return;
    }
  }
  // Each subcontact takes the vertex nearest to where it was put at the
  // last step (it has moved since by a step's sliding), unambiguously:
  // nearer than a quarter of that vertex's distance to any other, and no
  // vertex taken twice. Every vertex that turns the boundary by more than
  // kClipCornerAngle must be taken; one turning less (a corner of two
  // nearly aligned faces, whose vertices come and go as the stones
  // vibrate) may be left without a subcontact, its spring's load then in
  // the pair's wrench (no shear spring, no dashpot: it has at most
  // kClipCornerAngle/2π of the area). Otherwise the pair is re-sampled.
  const PatchScratch& ps = s.patch;
  const std::size_t np = ps.poly.size();
  const auto count = static_cast<std::size_t>(cp.count);
  if (s.taken.size() < np) s.taken.resize(np);
  if (s.vertex_of.size() < count) s.vertex_of.resize(count);
  // A pair without area carries nothing (no springs to match) until it
  // has some.
  bool none = load.area == 0;
  for (std::size_t t = 0; t < count && none; ++t) none = sub.area[s0 + t] == 0;
  if (none) return;
  bool same = load.area > 0;
  std::fill(s.taken.begin(), s.taken.begin() + static_cast<std::ptrdiff_t>(np), 0);
  for (std::size_t t = 0; t < count && same; ++t) {
    const Vec3 last = st.rotation[i] * sub.inc_point_local[s0 + t] + st.position[i];
    std::size_t nearest = np;
    double d2 = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < np; ++j) {
      const double e2 = (ps.poly[j] - last).squaredNorm();
      if (e2 < d2) d2 = e2, nearest = j;
    }
    double apart2 = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < np; ++j)
      if (j != nearest) apart2 = std::min(apart2, (ps.poly[j] - ps.poly[nearest]).squaredNorm());
    same = nearest < np && !s.taken[nearest] && d2 <= 0.0625 * apart2 &&
           n.dot(ps.poly[nearest]) - c_geometric <= margin;
    if (same) s.taken[nearest] = 1, s.vertex_of[t] = nearest;
  }
  for (std::size_t j = 0; j < np && same; ++j)
    same = s.taken[j] || n.dot(ps.poly[j]) - c_geometric > margin ||
           s.area[j] < kClipCornerAngle / (2.0 * std::numbers::pi) * load.area;
  if (!same) {
    stale[q] = 1;
    move_points(st, pairs, sub, q, q + 1);
    return;
  }
  // Each spring keeps its elastic shear displacement F/(ks·A) as its area
  // changes: its shear force goes with its area, and the shear energy
  // F²/(2·ks·A) with it (the part of the joint that left the contact takes
  // its strain with it; a part that came in brings the same). That change
  // is no force's work: it is booked with the detections' (dropped shear).
  const Mat3 RiT = st.rotation[i].transpose();
  const double ks = laws.between(r, i).ks;
  double dropped = 0;
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t k = s0 + t;
    sub.inc_point_local.set(k, RiT * (ps.poly[s.vertex_of[t]] - st.position[i]));
    const double a_old = sub.area[k], a_new = s.area[s.vertex_of[t]];
    sub.area[k] = a_new;
    if (a_new == a_old || !(a_old > 0) || !(ks > 0)) continue;
    const Vec3 f = sub.shear_force[k];
    const double ratio = a_new / a_old;
    dropped += f.squaredNorm() / (2.0 * ks * a_old) * (1.0 - ratio);
    sub.shear_force.set(k, ratio * f);
  }
  shear_dropped[q] = dropped;
  Vec3 force = load.rest_force, moment = load.rest_moment;
  for (std::size_t j = 0; j < np; ++j) {
    if (s.taken[j] || !(s.u[j] > 0)) continue;
    const Vec3 f = (kn * s.area[j] * s.u[j]) * n;
    force += f;
    moment += (ps.poly[j] - st.position[i]).cross(f);
  }
  const Vec3 xcr = st.position[i] - st.position[r];
  const Vec3 moment_ref = -(moment + xcr.cross(force));
  for (int d = 0; d < 3; ++d) {
    w.force[d] = force[d];
    w.moment[d] = moment[d];
    w.moment_ref[d] = moment_ref[d];
  }
}

}  // namespace

void clip_pairs(const std::vector<Polyhedron>& shapes, const BlockState& st, const JointLaws& laws,
                const std::vector<ContactPair>& pairs, double margin, Subcontacts& sub,
                std::vector<lanes::PairRest>& rest, std::vector<std::uint8_t>& stale,
                std::vector<double>& shear_dropped, std::size_t begin, std::size_t end, ClipScratch& s,
                const std::vector<std::vector<double>>* face_areas) {
  for (std::size_t q = begin; q < end; ++q)
    clip_pair(shapes, st, laws, pairs, margin, sub, rest, stale, shear_dropped, q, s, face_areas, true);
}

void clip_listed_pairs(const std::vector<Polyhedron>& shapes, const BlockState& st, const JointLaws& laws,
                       const std::vector<ContactPair>& pairs, double margin, Subcontacts& sub,
                       std::vector<lanes::PairRest>& rest, std::vector<std::uint8_t>& stale,
                       std::vector<double>& shear_dropped, const int* list, std::size_t count, ClipScratch& s,
                       const std::vector<std::vector<double>>* face_areas, bool check_faces) {
  for (std::size_t k = 0; k < count; ++k)
    clip_pair(shapes, st, laws, pairs, margin, sub, rest, stale, shear_dropped, static_cast<std::size_t>(list[k]), s,
              face_areas, check_faces);
}

std::vector<std::vector<double>> face_areas_of(const std::vector<Polyhedron>& shapes) {
  std::vector<std::vector<double>> out(shapes.size());
  for (std::size_t b = 0; b < shapes.size(); ++b)
    for (std::size_t f = 0; f < shapes[b].faces.size(); ++f)
      out[b].push_back(face_area(shapes[b], static_cast<int>(f)));
  return out;
}

}  // namespace polydem
