// The Winkler joint over the overlap of two blocks: face shadows, the
// clipped cells Q_ab and their fan integrals (overlap_integral.hpp).
#include "contact/overlap_integral.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {
namespace {

using Node = OverlapScratch::Node;
using FaceShadow = OverlapScratch::FaceShadow;

// The block's vertices in the frame: plane coordinates (x, y) about the
// origin and height h along n. The frame's axes are taken to the body frame
// once, so each vertex costs three dot products.
void frame_vertices(const PosedBlock& block, const JointFrame& frame, std::vector<double>& x,
                    std::vector<double>& y, std::vector<double>& h) {
  const Mat3& R = block.R;
  const Vec3 u1 = R.transpose() * frame.e1, u2 = R.transpose() * frame.e2, un = R.transpose() * frame.n;
  const Vec3 c = block.x - frame.origin;
  const double c1 = frame.e1.dot(c), c2 = frame.e2.dot(c), cn = frame.n.dot(c);
  const std::vector<Vec3>& v = block.shape->vertices;
  const std::size_t nv = v.size();
  x.resize(nv);
  y.resize(nv);
  h.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    x[i] = u1.dot(v[i]) + c1;
    y[i] = u2.dot(v[i]) + c2;
    h[i] = un.dot(v[i]) + cn;
  }
}

// A face whose normal is within 1e-9 of perpendicular to n counts as a wall:
// it takes no part in the hulls (its slope, 1e9 and beyond, would multiply
// a cell's round-off), and where the region ends against it the rim term
// of the face beside it stands for it (the limit of its cell as it turns
// vertical).
constexpr double kSteep = 1e-9;

// Face f's shadow if its outward normal has a component along n of sign
// `sign` (+1: A's upper hull, −1: B's lower hull); false for a face
// perpendicular to n (component exactly 0) or facing the other way.
bool face_shadow(const Polyhedron& p, const Vec3& u1, const Vec3& u2, const Vec3& un, int f, int sign,
                 const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& h,
                 FaceShadow& s) {
  const Vec3& nf = p.normals[static_cast<std::size_t>(f)];
  const double mn = un.dot(nf);
  if (!(sign > 0 ? mn > kSteep : mn < -kSteep)) return false;
  s.face = f;
  s.m1 = u1.dot(nf);
  s.m2 = u2.dot(nf);
  s.mn = mn;
  s.xmin = s.ymin = s.hmin = std::numeric_limits<double>::infinity();
  s.xmax = s.ymax = s.hmax = -std::numeric_limits<double>::infinity();
  for (int i : p.faces[static_cast<std::size_t>(f)]) {
    s.xmin = std::min(s.xmin, x[i]);
    s.xmax = std::max(s.xmax, x[i]);
    s.ymin = std::min(s.ymin, y[i]);
    s.ymax = std::max(s.ymax, y[i]);
    s.hmin = std::min(s.hmin, h[i]);
    s.hmax = std::max(s.hmax, h[i]);
  }
  return true;
}

// The frame's axes in the block's body frame.
void body_axes(const PosedBlock& block, const JointFrame& frame, Vec3& u1, Vec3& u2, Vec3& un) {
  u1 = block.R.transpose() * frame.e1;
  u2 = block.R.transpose() * frame.e2;
  un = block.R.transpose() * frame.n;
}

// The faces of sign `sign` (face_shadow), with their shadows.
void face_shadows(const PosedBlock& block, const JointFrame& frame, int sign, const std::vector<double>& x,
                  const std::vector<double>& y, const std::vector<double>& h, std::vector<FaceShadow>& out) {
  Vec3 u1, u2, un;
  body_axes(block, frame, u1, u2, un);
  const Polyhedron& p = *block.shape;
  out.clear();
  FaceShadow s;
  for (std::size_t f = 0; f < p.faces.size(); ++f)
    if (face_shadow(p, u1, u2, un, static_cast<int>(f), sign, x, y, h, s)) out.push_back(s);
}

// Per face of B: 1 where it faces −n (its lower hull, face_shadow's sign).
void lower_faces(const PosedBlock& block, const JointFrame& frame, std::vector<char>& lower) {
  const Vec3 un = block.R.transpose() * frame.n;
  const Polyhedron& p = *block.shape;
  lower.resize(p.faces.size());
  for (std::size_t f = 0; f < p.faces.size(); ++f) lower[f] = un.dot(p.normals[f]) < -kSteep ? 1 : 0;
}

// True when the cell of the two shadows can be non-empty: a above b
// somewhere, their boxes overlapping.
bool may_overlap(const FaceShadow& fa, const FaceShadow& fb) {
  if (fa.hmax <= fb.hmin) return false;
  return !(fa.xmax <= fb.xmin || fb.xmax <= fa.xmin || fa.ymax <= fb.ymin || fb.ymax <= fa.ymin);
}

// h clamped to [lo, hi]; a NaN becomes lo.
double clamp_height(double h, double lo, double hi) {
  if (!(h >= lo)) return lo;
  if (!(h <= hi)) return hi;
  return h;
}

// u clamped to [0, 1]; a NaN becomes 0.
double clamp_unit(double u) {
  if (!(u >= 0)) return 0;
  if (!(u <= 1)) return 1;
  return u;
}

// Adds the fan integrals of the convex polygon `poly` (nodes carry t) to `m`.
// The fan's integrals into `m`; returns the cell's ∫t dA and ∫tξ dA.
struct CellLoad {
  double volume = 0;
  Vec2 moment = Vec2::Zero();
};
CellLoad add_fan(const std::vector<Node>& poly, OverlapMoments& m) {
  const std::size_t k = poly.size();
  const double x0 = poly[0].x, y0 = poly[0].y, t0 = poly[0].t;
  double area = 0;
  CellLoad c;
  for (std::size_t i = 1; i + 1 < k; ++i) {
    const double x1 = poly[i].x, y1 = poly[i].y, t1 = poly[i].t;
    const double x2 = poly[i + 1].x, y2 = poly[i + 1].y, t2 = poly[i + 1].t;
    const double a = 0.5 * ((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0));
    const double a12 = a / 12.0;
    const double st = t0 + t1 + t2, sx = x0 + x1 + x2, sy = y0 + y1 + y2;
    area += a;
    c.volume += a * st / 3.0;
    m.overlap_squared += a12 * (t0 * t0 + t1 * t1 + t2 * t2 + st * st);
    m.area_moment.x() += a * sx / 3.0;
    m.area_moment.y() += a * sy / 3.0;
    c.moment.x() += a12 * (t0 * x0 + t1 * x1 + t2 * x2 + st * sx);
    c.moment.y() += a12 * (t0 * y0 + t1 * y1 + t2 * y2 + st * sy);
    m.area_inertia(0, 0) += a12 * (x0 * x0 + x1 * x1 + x2 * x2 + sx * sx);
    const double ixy = a12 * (x0 * y0 + x1 * y1 + x2 * y2 + sx * sy);
    m.area_inertia(0, 1) += ixy;
    m.area_inertia(1, 0) += ixy;
    m.area_inertia(1, 1) += a12 * (y0 * y0 + y1 * y1 + y2 * y2 + sy * sy);
  }
  m.area += area;
  m.volume += c.volume;
  m.volume_moment += c.moment;
  if (area != 0) ++m.cells;
  return c;
}

// Q_ab for face a of A (upper hull) and face b of B (lower hull), integrated
// into `m`.
void add_cell(const Polyhedron& pa, const FaceShadow& sa, const Polyhedron& pb, const FaceShadow& sb,
              OverlapScratch& s, OverlapMoments& m) {
  // t is linear over the cell: its largest value is at most the largest at
  // a's vertices against b's plane, and at b's vertices against a's. Where
  // either is negative the cell is empty, without clipping.
  {
    const std::vector<int>& fa = pa.faces[sa.face];
    const std::vector<int>& fb = pb.faces[sb.face];
    const int a0 = fa[0], b0 = fb[0];
    double top = -std::numeric_limits<double>::infinity();
    for (int i : fa) {
      const double hb = s.hb[b0] - (sb.m1 * (s.xa[i] - s.xb[b0]) + sb.m2 * (s.ya[i] - s.yb[b0])) / sb.mn;
      top = std::max(top, s.ha[i] - hb);
    }
    if (top < 0) return;
    top = -std::numeric_limits<double>::infinity();
    for (int i : fb) {
      const double ha = s.ha[a0] - (sa.m1 * (s.xb[i] - s.xa[a0]) + sa.m2 * (s.yb[i] - s.ya[a0])) / sa.mn;
      top = std::max(top, ha - s.hb[i]);
    }
    if (top < 0) return;
  }
  // proj(a), counter-clockwise seen from +n since a faces +n.
  std::vector<Node>& poly = s.poly;
  std::vector<Node>& next = s.next;
  poly.clear();
  for (int i : pa.faces[sa.face]) poly.push_back(Node{s.xa[i], s.ya[i], s.ha[i], 0.0, 0.0, -1});
  // proj(b): b faces −n, so its loop is clockwise seen from +n; reversed.
  const std::vector<int>& fb = pb.faces[sb.face];
  const std::size_t nb = fb.size();
  s.bx.resize(nb);
  s.by.resize(nb);
  s.bh.resize(nb);
  for (std::size_t k = 0; k < nb; ++k) {
    const int i = fb[nb - 1 - k];
    s.bx[k] = s.xb[i];
    s.by[k] = s.yb[i];
    s.bh[k] = s.hb[i];
  }

  // Sutherland–Hodgman: keep the side d ≥ 0 of each edge of proj(b). A new
  // node is made only between strictly opposite signs, so d0 − d1 ≠ 0.
  for (std::size_t j = 0; j < nb && !poly.empty(); ++j) {
    const std::size_t j1 = j + 1 == nb ? 0 : j + 1;
    const double ox = s.bx[j], oy = s.by[j];
    const double ex = s.bx[j1] - ox, ey = s.by[j1] - oy;
    next.clear();
    const std::size_t k = poly.size();
    for (std::size_t i = 0; i < k; ++i) {
      const Node& p = poly[i];
      const Node& q = poly[i + 1 == k ? 0 : i + 1];
      const double dp = ex * (p.y - oy) - ey * (p.x - ox);
      const double dq = ex * (q.y - oy) - ey * (q.x - ox);
      if (dp >= 0) next.push_back(p);
      if ((dp >= 0) != (dq >= 0)) {
        const double u = dp / (dp - dq);
        next.push_back(Node{p.x + u * (q.x - p.x), p.y + u * (q.y - p.y), p.ha + u * (q.ha - p.ha), 0.0,
                            0.0, static_cast<int>(j)});
      }
    }
    poly.swap(next);
  }
  if (poly.size() < 3) return;

  // B's height at each node: along the edge of proj(b) it was made on, or,
  // for a vertex of a inside proj(b), from b's plane. Both lie in b's height
  // range exactly; the clamp keeps round-off (a steep b) inside it.
  const double x0 = s.bx[0], y0 = s.by[0], h0 = s.bh[0];
  for (Node& p : poly) {
    if (p.b_edge < 0) {
      p.hb = clamp_height(h0 - (sb.m1 * (p.x - x0) + sb.m2 * (p.y - y0)) / sb.mn, sb.hmin, sb.hmax);
    } else {
      const std::size_t j = static_cast<std::size_t>(p.b_edge), j1 = j + 1 == nb ? 0 : j + 1;
      // The node's place along the edge, from the edge's longer coordinate
      // (never zero: an edge of zero length cuts nothing).
      const double ex = s.bx[j1] - s.bx[j], ey = s.by[j1] - s.by[j];
      const double u = std::abs(ex) >= std::abs(ey) ? (p.x - s.bx[j]) / ex : (p.y - s.by[j]) / ey;
      p.hb = s.bh[j] + clamp_unit(u) * (s.bh[j1] - s.bh[j]);
    }
  }

  // Clip by t ≥ 0; the new nodes lie on the zero line (t = 0).
  for (Node& p : poly) p.t = p.ha - p.hb;
  next.clear();
  const std::size_t k = poly.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Node& p = poly[i];
    const Node& q = poly[i + 1 == k ? 0 : i + 1];
    if (p.t >= 0) next.push_back(p);
    if ((p.t >= 0) != (q.t >= 0)) {
      const double u = p.t / (p.t - q.t);
      next.push_back(Node{p.x + u * (q.x - p.x), p.y + u * (q.y - p.y), 0.0, 0.0, 0.0, -1});
    }
  }
  if (next.size() < 3) return;
  for (const Node& p : next) m.max_overlap = std::max(m.max_overlap, p.t);
  const CellLoad c = add_fan(next, m);
  // B's surface over the cell: h_B(ξ) = h0 + g·ξ.
  const Vec2 g(-sb.m1 / sb.mn, -sb.m2 / sb.mn);
  const double hb0 = s.bh[0] - g.x() * s.bx[0] - g.y() * s.by[0];
  m.slope_volume += c.volume * g;
  m.slope_twist += g.y() * c.moment.x() - g.x() * c.moment.y();
  m.height_volume += (hb0 * c.volume + g.dot(c.moment)) * g;

  // The rim: the cell's sides that lie on an edge of b beyond which B's
  // lower hull ends (its neighbour faces up or is perpendicular to n). They
  // move with B, and t need not vanish there: ½∮t²ν ds over them.
  if (pb.neighbours.empty()) return;
  const std::vector<int>& across = pb.neighbours[static_cast<std::size_t>(sb.face)];
  const std::size_t nk = next.size();
  for (std::size_t j = 0; j < nb; ++j) {
    const std::size_t i = (2 * nb - 2 - j) % nb;  // reversed edge j is the face's edge i
    const int g_face = across[i];
    if (g_face < 0 || s.b_lower[static_cast<std::size_t>(g_face)]) continue;
    const std::size_t j1 = j + 1 == nb ? 0 : j + 1;
    const double ox = s.bx[j], oy = s.by[j];
    const double ex = s.bx[j1] - ox, ey = s.by[j1] - oy;
    const double len2 = ex * ex + ey * ey;
    if (!(len2 > 0)) continue;
    const double tol = 1e-9 * len2;
    for (std::size_t e = 0; e < nk; ++e) {
      const Node& p = next[e];
      const Node& q = next[e + 1 == nk ? 0 : e + 1];
      const double dp = ex * (p.y - oy) - ey * (p.x - ox);
      const double dq = ex * (q.y - oy) - ey * (q.x - ox);
      if (!(std::abs(dp) <= tol && std::abs(dq) <= tol)) continue;
      const double dx = q.x - p.x, dy = q.y - p.y;
      const double L = std::hypot(dx, dy);
      if (!(L > 0)) continue;
      const Vec2 nu(dy / L, -dx / L);  // outward: the polygon turns counter-clockwise
      // Simpson's rule, exact for the cubics t²·f with f linear along the side.
      const double tm = 0.5 * (p.t + q.t);
      const double xm = 0.5 * (p.x + q.x), ym = 0.5 * (p.y + q.y);
      const double hp = hb0 + g.x() * p.x + g.y() * p.y, hq = hb0 + g.x() * q.x + g.y() * q.y;
      const double hm = 0.5 * (hp + hq);
      const double w = L / 6.0;
      const double t2 = w * (p.t * p.t + 4 * tm * tm + q.t * q.t);
      const double t2x = w * (p.t * p.t * p.x + 4 * tm * tm * xm + q.t * q.t * q.x);
      const double t2y = w * (p.t * p.t * p.y + 4 * tm * tm * ym + q.t * q.t * q.y);
      const double t2h = w * (p.t * p.t * hp + 4 * tm * tm * hm + q.t * q.t * hq);
      m.rim_force += t2 * nu;
      m.rim_twist += t2x * nu.y() - t2y * nu.x();
      m.rim_height += t2h * nu;
    }
  }
}

}  // namespace

JointFrame make_joint_frame(const Vec3& n, const Vec3& origin) {
  JointFrame f;
  f.origin = origin;
  f.n = n;
  int axis = 0;
  if (std::abs(n.y()) < std::abs(n[axis])) axis = 1;
  if (std::abs(n.z()) < std::abs(n[axis])) axis = 2;
  Vec3 a = Vec3::Zero();
  a[axis] = 1;
  f.e1 = (a - a.dot(n) * n).normalized();
  f.e2 = n.cross(f.e1);
  return f;
}

OverlapMoments overlap_integral(const PosedBlock& a, const PosedBlock& b, const JointFrame& frame,
                                OverlapScratch& s) {
  OverlapMoments m;
  frame_vertices(a, frame, s.xa, s.ya, s.ha);
  frame_vertices(b, frame, s.xb, s.yb, s.hb);
  // Separated along n: t < 0 everywhere, exact zeros.
  const double top_a = *std::max_element(s.ha.begin(), s.ha.end());
  const double bottom_b = *std::min_element(s.hb.begin(), s.hb.end());
  if (top_a <= bottom_b) return m;

  face_shadows(a, frame, +1, s.xa, s.ya, s.ha, s.top_a);
  face_shadows(b, frame, -1, s.xb, s.yb, s.hb, s.bottom_b);
  lower_faces(b, frame, s.b_lower);
  for (const FaceShadow& fa : s.top_a) {
    if (fa.hmax <= bottom_b) continue;
    for (const FaceShadow& fb : s.bottom_b)
      if (may_overlap(fa, fb)) add_cell(*a.shape, fa, *b.shape, fb, s, m);
  }
  return m;
}

OverlapMoments overlap_integral(const PosedBlock& a, const PosedBlock& b, const JointFrame& frame,
                                const FacePair* begin, const FacePair* end, OverlapScratch& s) {
  OverlapMoments m;
  if (begin == end) return m;
  frame_vertices(a, frame, s.xa, s.ya, s.ha);
  frame_vertices(b, frame, s.xb, s.yb, s.hb);
  Vec3 a1, a2, an, b1, b2, bn;
  body_axes(a, frame, a1, a2, an);
  body_axes(b, frame, b1, b2, bn);
  lower_faces(b, frame, s.b_lower);
  FaceShadow fa, fb;
  int face_a = -1;
  bool up = false;
  for (const FacePair* c = begin; c != end; ++c) {
    if (c->a != face_a) {  // the pairs come sorted by A's face: its shadow once
      face_a = c->a;
      up = face_shadow(*a.shape, a1, a2, an, face_a, +1, s.xa, s.ya, s.ha, fa);
    }
    if (!up || !face_shadow(*b.shape, b1, b2, bn, c->b, -1, s.xb, s.yb, s.hb, fb)) continue;
    if (may_overlap(fa, fb)) add_cell(*a.shape, fa, *b.shape, fb, s, m);
  }
  return m;
}

void overlap_face_pairs(const PosedBlock& a, const PosedBlock& b, const Vec3& n, double reach,
                        std::vector<FacePair>& out, OverlapScratch& s) {
  out.clear();
  const JointFrame frame = make_joint_frame(n, 0.5 * (a.x + b.x));
  frame_vertices(a, frame, s.xa, s.ya, s.ha);
  frame_vertices(b, frame, s.xb, s.yb, s.hb);
  // Each face's shadow as a disc about its vertices' mean, and its height
  // range: both unchanged by a turn of the frame about n.
  struct Disc {
    double x, y, r, hmin, hmax;
  };
  auto disc = [](const std::vector<int>& face, const std::vector<double>& x, const std::vector<double>& y,
                 const std::vector<double>& h) {
    Disc d{0, 0, 0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (int i : face) {
      d.x += x[i];
      d.y += y[i];
      d.hmin = std::min(d.hmin, h[i]);
      d.hmax = std::max(d.hmax, h[i]);
    }
    d.x /= static_cast<double>(face.size());
    d.y /= static_cast<double>(face.size());
    for (int i : face) d.r = std::max(d.r, std::hypot(x[i] - d.x, y[i] - d.y));
    return d;
  };
  const Polyhedron& pa = *a.shape;
  const Polyhedron& pb = *b.shape;
  const Vec3 na = a.R.transpose() * n, nb = b.R.transpose() * n;
  // A face may take part if it could face the right way after a turn of
  // the joint by reach/size, far more than between two detections.
  const double turn = 1e-2;
  for (std::size_t fa = 0; fa < pa.faces.size(); ++fa) {
    if (na.dot(pa.normals[fa]) < -turn) continue;
    const Disc da = disc(pa.faces[fa], s.xa, s.ya, s.ha);
    for (std::size_t fb = 0; fb < pb.faces.size(); ++fb) {
      if (nb.dot(pb.normals[fb]) > turn) continue;
      const Disc db = disc(pb.faces[fb], s.xb, s.yb, s.hb);
      if (da.hmax + reach < db.hmin) continue;
      if (std::hypot(da.x - db.x, da.y - db.y) > da.r + db.r + reach) continue;
      out.push_back(FacePair{static_cast<int>(fa), static_cast<int>(fb)});
    }
  }
}

Vec3 plane_point(const JointFrame& frame, const Vec2& xi) {
  return frame.origin + xi.x() * frame.e1 + xi.y() * frame.e2;
}

Vec2 pressure_centroid(const OverlapMoments& m) {
  if (!(m.volume > 0)) return Vec2::Zero();
  return m.volume_moment / m.volume;
}

double polar_moment(const OverlapMoments& m, const Vec2& c) {
  return m.area_inertia.trace() - 2.0 * c.dot(m.area_moment) + c.squaredNorm() * m.area;
}

JointLoad joint_load(const OverlapMoments& m, const JointFrame& frame, double kn, const Vec3& about) {
  JointLoad l;
  const Vec3& n = frame.n;
  const Vec3 slope = m.slope_volume.x() * frame.e1 + m.slope_volume.y() * frame.e2;
  l.force = kn * (m.volume * n - slope);
  // About the origin: ∫t ξ×n (e1×n = −e2, e2×n = e1), −∫t ξ×g = −n·Σ(g₂∫tξ₁ −
  // g₁∫tξ₂), −∫t h_B n×g (n×e1 = e2, n×e2 = −e1); then moved to `about`.
  const Vec3 at_origin = m.volume_moment.y() * frame.e1 - m.volume_moment.x() * frame.e2 - m.slope_twist * n -
                         (m.height_volume.x() * frame.e2 - m.height_volume.y() * frame.e1);
  // The rim: −½kn ∫t² ν ds acting at B's silhouette (ξ + h_B·n): its moment
  // −½kn ∫t² ((ξ × ν)·n n + h_B n × ν) ds, n × ν = ν₁e2 − ν₂e1.
  const Vec3 rim = m.rim_force.x() * frame.e1 + m.rim_force.y() * frame.e2;
  l.force -= 0.5 * kn * rim;
  const Vec3 rim_at_origin =
      m.rim_twist * n + (m.rim_height.x() * frame.e2 - m.rim_height.y() * frame.e1);
  l.moment = kn * at_origin - 0.5 * kn * rim_at_origin + (frame.origin - about).cross(l.force);
  l.energy = 0.5 * kn * m.overlap_squared;
  l.stiffness = kn * m.area;
  return l;
}

}  // namespace polydem
