#include "contact/moving_points.hpp"

#include "contact/subcontacts.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

namespace polydem {

void MovingPoints::resize(std::size_t n) {
  const std::size_t k = on ? n : 0;
  for_each_array(*this, *this, [k](auto& v, auto&, const char*) { v.resize(k); });
}

namespace {

// The side plane of the reference face's edge `side` (body frame): unit
// normal out of the face and offset.
void side_plane(const Polyhedron& p, int face, int side, Vec3& normal, double& offset) {
  const auto& f = p.faces[static_cast<std::size_t>(face)];
  const auto k = static_cast<std::size_t>(side);
  const Vec3& v0 = p.vertices[static_cast<std::size_t>(f[k])];
  const Vec3& v1 = p.vertices[static_cast<std::size_t>(f[(k + 1) % f.size()])];
  normal = (v1 - v0).cross(p.normals[static_cast<std::size_t>(face)]).normalized();
  offset = normal.dot(v0);
}

// The two side planes of `face` nearest to body-frame point y (by its
// signed distance from each, largest first).
void nearest_sides(const Polyhedron& p, int face, const Vec3& y, Vec3& h1, double& o1, Vec3& h2, double& o2) {
  const auto& f = p.faces[static_cast<std::size_t>(face)];
  double d1 = -1e300, d2 = -1e300;
  for (std::size_t k = 0; k < f.size(); ++k) {
    Vec3 m;
    double c = 0;
    side_plane(p, face, static_cast<int>(k), m, c);
    const double dist = m.dot(y) - c;
    if (dist > d1) {
      d2 = d1, h2 = h1, o2 = o1;
      d1 = dist, h1 = m, o1 = c;
    } else if (dist > d2) {
      d2 = dist, h2 = m, o2 = c;
    }
  }
}

}  // namespace

void define_moving_point(const Polyhedron& rp, int ref_face, const Polyhedron& ip, int inc_face,
                         const PatchPoint& pt, const Vec3& point_ref, const Vec3& point_inc, MovingPoints& mp,
                         std::size_t s) {
  mp.kind[s] = static_cast<std::uint8_t>(pt.def.kind);
  mp.a[s] = mp.b[s] = mp.m[s] = mp.r0[s] = mp.r1[s] = mp.h1[s] = mp.h2[s] = Vec3::Zero();
  mp.c[s] = mp.o1[s] = mp.o2[s] = 0;
  if (pt.def.kind == PointKind::incident_vertex) {
    mp.a[s] = ip.vertices[static_cast<std::size_t>(pt.def.v0)];
    mp.b[s] = ip.normals[static_cast<std::size_t>(inc_face)];
    nearest_sides(rp, ref_face, point_ref, mp.h1[s], mp.o1[s], mp.h2[s], mp.o2[s]);
  } else if (pt.def.kind == PointKind::incident_edge) {
    mp.a[s] = ip.vertices[static_cast<std::size_t>(pt.def.v0)];
    mp.b[s] = ip.vertices[static_cast<std::size_t>(pt.def.v1)];
    side_plane(rp, ref_face, pt.def.side, mp.m[s], mp.c[s]);
    const auto& f = rp.faces[static_cast<std::size_t>(ref_face)];
    const auto k = static_cast<std::size_t>(pt.def.side);
    mp.r0[s] = rp.vertices[static_cast<std::size_t>(f[k])];
    mp.r1[s] = rp.vertices[static_cast<std::size_t>(f[(k + 1) % f.size()])];
  } else if (pt.def.kind == PointKind::reference_corner) {
    // The meeting line of the two side planes, on the reference plane.
    Vec3 m1, m2;
    double c1 = 0, c2 = 0;
    side_plane(rp, ref_face, pt.def.side, m1, c1);
    side_plane(rp, ref_face, pt.def.side2, m2, c2);
    const Vec3& n = rp.normals[static_cast<std::size_t>(ref_face)];
    Eigen::Matrix3d A;
    A.row(0) = m1.transpose();
    A.row(1) = m2.transpose();
    A.row(2) = n.transpose();
    const Vec3 rhs(c1, c2, rp.offsets[static_cast<std::size_t>(ref_face)]);
    mp.a[s] = A.colPivHouseholderQr().solve(rhs);
    mp.m[s] = ip.normals[static_cast<std::size_t>(inc_face)];
    mp.c[s] = ip.offsets[static_cast<std::size_t>(inc_face)];
    nearest_sides(ip, inc_face, point_inc, mp.h1[s], mp.o1[s], mp.h2[s], mp.o2[s]);
  }
}

namespace {

// One pair (see move_points).
void move_pair(const BlockState& st, const ContactPair& cp, Subcontacts& sub) {
  const std::size_t s0 = static_cast<std::size_t>(cp.first), count = static_cast<std::size_t>(cp.count);
  const int r = cp.ref_block;
  const int i = cp.ref_block == cp.a ? cp.b : cp.a;
  const MovingPoints& mp = sub.moving;
  if (cp.ref_face < 0) return;  // an edge-to-edge crossing: fixed
  // The reference block's frame seen from the incident block's:
  // y_inc = M·y_ref + d.
  const Mat3 M = st.rotation[i].transpose() * st.rotation[r];
  const Vec3 d = st.rotation[i].transpose() * (st.position[r] - st.position[i]);
  const Vec3 n = M * sub.ref_normal_local[s0];  // the common plane's normal, incident frame
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t s = s0 + k;
    Vec3 p = sub.inc_point_local[s];
    const auto kind = static_cast<PointKind>(mp.kind[s]);
    if (kind == PointKind::incident_vertex) {
      // Past a side of the reference face (it has slid off its edge since
      // the detection): held on that side, moved along the incident face,
      // where the crossings the next detection finds will be.
      p = mp.a[s];
      const Vec3& g = mp.b[s];
      for (int side = 0; side < 2; ++side) {
        const Vec3& h = side == 0 ? mp.h1[s] : mp.h2[s];
        const Vec3 w = M * h;  // the side plane w·y = o + w·d, incident frame
        const double past = w.dot(p - d) - (side == 0 ? mp.o1[s] : mp.o2[s]);
        if (past <= 0) continue;
        const Vec3 dir = w - w.dot(g) * g;  // along the incident face
        const double along = w.dot(dir);
        if (along > 1e-6) p -= (past / along) * dir;
      }
    } else if (kind == PointKind::incident_edge) {
      // In the incident frame the side plane is w·y = c + w·d, w = M·m.
      const Vec3 w = M * mp.m[s];
      const Vec3& a = mp.a[s];
      const Vec3 e = mp.b[s] - a;
      const double den = w.dot(e);
      // An edge within a thousandth of a radian of its side plane (an edge
      // lying in the plane of the face below) has no crossing to speak of:
      // its point stays where the detection put it, fixed in the block.
      if (den * den > 1e-6 * e.squaredNorm()) {
        double t = std::clamp((mp.c[s] + w.dot(d - a)) / den, 0.0, 1.0);
        p = a + t * e;
        // Where along the reference edge r0 + u·er it lies: u·|er|² =
        // (p − d)·M·er − r0·er. Past an end, on the common plane, the
        // edge's point nearest to that end.
        const Vec3 er_ref = mp.r1[s] - mp.r0[s];
        const double er2 = er_ref.squaredNorm();
        const Vec3 er = M * er_ref;
        const double u_er2 = (p - d).dot(er) - mp.r0[s].dot(er_ref);
        if (u_er2 < 0 || u_er2 > er2) {
          const Vec3 end = M * mp.r0[s] + d + std::clamp(u_er2 / er2, 0.0, 1.0) * er;
          const Vec3 ep = e - e.dot(n) * n, to_end = end - a;
          t = std::clamp((to_end - to_end.dot(n) * n).dot(ep) / ep.squaredNorm(), 0.0, 1.0);
          p = a + t * e;
        }
      }
    } else if (kind == PointKind::reference_corner) {
      const Vec3 x = M * mp.a[s] + d;
      const double den = mp.m[s].dot(n);
      if (std::abs(den) > 1e-9) p = x + ((mp.c[s] - mp.m[s].dot(x)) / den) * n;
      // Past a side of the incident face: held on it, within the face.
      for (int side = 0; side < 2; ++side) {
        const Vec3& h = side == 0 ? mp.h1[s] : mp.h2[s];
        const double past = h.dot(p) - (side == 0 ? mp.o1[s] : mp.o2[s]);
        if (past > 0) p -= past * h;
      }
    }
    sub.inc_point_local.set(s, p);
  }
}

}  // namespace

void move_points(const BlockState& st, const std::vector<ContactPair>& pairs, Subcontacts& sub, std::size_t begin,
                 std::size_t end) {
  for (std::size_t q = begin; q < end; ++q) {
    const ContactPair& cp = pairs[q];
    if (cp.count > 0) move_pair(st, cp, sub);
  }
}

}  // namespace polydem
