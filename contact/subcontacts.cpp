#include "contact/subcontacts.hpp"

#include "contact/joint_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {

void Subcontacts::clear() { resize(0); }

void Subcontacts::resize(std::size_t n) {
  pair.resize(n);
  ref_block.resize(n);
  inc_block.resize(n);
  key.resize(n);
  ref_normal_local.resize(n);
  ref_offset_local.resize(n);
  inc_point_local.resize(n);
  area.resize(n);
  crush.resize(n);
  shear_force.resize(n);
  bonded.resize(n);
  force.resize(n);
  point.resize(n);
  overlap.resize(n);
  normal_force.resize(n);
  slip_energy.resize(n);
  damping_energy.resize(n);
  damping_force.resize(n);
  moving.resize(n);
}

void ContactSet::save(ByteWriter& w) const {
  w.put(static_cast<std::uint64_t>(pairs.size()));
  for (const ContactPair& p : pairs) {
    w.put(p.a);
    w.put(p.b);
    w.put(p.ref_block);
    w.put(p.ref_face);
    w.put(p.inc_face);
    w.put(p.first);
    w.put(p.count);
    w.put(p.patch_area);
    w.put(p.normal_local);
    w.put(p.offset_local);
  }
  w.put(sub.pair);
  w.put(sub.ref_block);
  w.put(sub.inc_block);
  w.put(sub.key);
  w.put(sub.ref_normal_local);
  w.put(sub.ref_offset_local);
  w.put(sub.inc_point_local);
  w.put(sub.area);
  w.put(sub.crush);
  w.put(sub.shear_force);
  w.put(sub.bonded);
  w.put(sub.force);
  w.put(sub.point);
  w.put(sub.overlap);
  w.put(sub.normal_force);
  w.put(sub.slip_energy);
  w.put(sub.damping_energy);
  w.put(sub.damping_force);
  w.put(static_cast<std::uint8_t>(sub.moving.on ? 1 : 0));
  if (sub.moving.on)
    MovingPoints::for_each_array(sub.moving, sub.moving, [&w](const auto& v, const auto&, const char*) { w.put(v); });
  w.put(gather_offset);
  w.put(gather_sub);
  w.put(gather_sign);
  w.put(retired_slip_energy);
  w.put(retired_damping_energy);
  w.put(dropped_shear_energy);
  w.put(resampled_normal_energy);
  w.put(detections);
  w.put(static_cast<std::uint64_t>(joints.size()));
  if (joints.size() > 0) joints.save(w);
}

void ContactSet::load(ByteReader& r, int blocks) {
  std::uint64_t np = 0;
  r.get(np);
  if (np > r.remaining() / 36) throw StateFormatError("contact pairs: count beyond the data");
  pairs.resize(static_cast<std::size_t>(np));
  for (ContactPair& p : pairs) {
    r.get(p.a);
    r.get(p.b);
    r.get(p.ref_block);
    r.get(p.ref_face);
    r.get(p.inc_face);
    r.get(p.first);
    r.get(p.count);
    r.get(p.patch_area);
    r.get(p.normal_local);
    r.get(p.offset_local);
  }
  r.get(sub.pair);
  const std::size_t n = sub.pair.size();
  r.get_sized(sub.ref_block, n, "subcontacts.ref_block");
  r.get_sized(sub.inc_block, n, "subcontacts.inc_block");
  r.get_sized(sub.key, n, "subcontacts.key");
  r.get_sized(sub.ref_normal_local, n, "subcontacts.ref_normal_local");
  r.get_sized(sub.ref_offset_local, n, "subcontacts.ref_offset_local");
  r.get_sized(sub.inc_point_local, n, "subcontacts.inc_point_local");
  r.get_sized(sub.area, n, "subcontacts.area");
  r.get_sized(sub.crush, n, "subcontacts.crush");
  r.get_sized(sub.shear_force, n, "subcontacts.shear_force");
  r.get_sized(sub.bonded, n, "subcontacts.bonded");
  r.get_sized(sub.force, n, "subcontacts.force");
  r.get_sized(sub.point, n, "subcontacts.point");
  r.get_sized(sub.overlap, n, "subcontacts.overlap");
  r.get_sized(sub.normal_force, n, "subcontacts.normal_force");
  r.get_sized(sub.slip_energy, n, "subcontacts.slip_energy");
  r.get_sized(sub.damping_energy, n, "subcontacts.damping_energy");
  r.get_sized(sub.damping_force, n, "subcontacts.damping_force");
  std::uint8_t moving = 0;
  r.get(moving);
  sub.moving.on = moving != 0;
  sub.moving.resize(0);
  if (sub.moving.on) {
    MovingPoints::for_each_array(sub.moving, sub.moving, [&](auto& v, auto&, const char* name) {
      r.get_sized(v, n, (std::string("subcontacts.moving.") + name).c_str());
    });
    for (std::uint8_t k : sub.moving.kind)
      if (k > static_cast<std::uint8_t>(PointKind::fixed)) throw StateFormatError("subcontact point kind out of range");
  }
  r.get_sized(gather_offset, static_cast<std::size_t>(blocks) + 1, "contacts.gather_offset");
  r.get_sized(gather_sub, 2 * n, "contacts.gather_sub");
  r.get_sized(gather_sign, 2 * n, "contacts.gather_sign");
  r.get(retired_slip_energy);
  r.get(retired_damping_energy);
  r.get(dropped_shear_energy);
  r.get(resampled_normal_energy);
  r.get(detections);
  std::uint64_t nj = 0;
  r.get(nj);
  if (nj != 0 && nj != np)
    throw StateFormatError("the joints of " + std::to_string(nj) + " pairs, " + std::to_string(np) + " pairs");
  joints = PairJoints{};
  if (nj > 0) joints.load(r, np);

  // Indices in range: a checkpoint that passed its checksum but was written
  // for another scene must not index out of bounds.
  auto block_ok = [&](int b) { return b >= 0 && b < blocks; };
  for (const ContactPair& p : pairs)
    if (!block_ok(p.a) || !block_ok(p.b) || !block_ok(p.ref_block) || p.first < 0 || p.count < 0 ||
        static_cast<std::size_t>(p.first) + static_cast<std::size_t>(p.count) > n)
      throw StateFormatError("contact pair out of range");
  for (std::size_t s = 0; s < n; ++s)
    if (sub.pair[s] < 0 || static_cast<std::size_t>(sub.pair[s]) >= pairs.size() || !block_ok(sub.ref_block[s]) ||
        !block_ok(sub.inc_block[s]))
      throw StateFormatError("subcontact out of range");
  if (gather_offset.front() != 0 || static_cast<std::size_t>(gather_offset.back()) != 2 * n)
    throw StateFormatError("gather lists out of range");
  for (int i = 0; i < blocks; ++i)
    if (gather_offset[i] > gather_offset[i + 1]) throw StateFormatError("gather lists out of order");
  for (int q : gather_sub)
    if (q < 0 || static_cast<std::size_t>(q) >= n) throw StateFormatError("gather list out of range");
}

const ContactPair* find_pair(const ContactSet& set, int a, int b) {
  auto it = std::lower_bound(set.pairs.begin(), set.pairs.end(), std::make_pair(a, b),
                             [](const ContactPair& p, const std::pair<int, int>& k) {
                               return std::make_pair(p.a, p.b) < k;
                             });
  return (it != set.pairs.end() && it->a == a && it->b == b) ? &*it : nullptr;
}

std::uint64_t subcontact_key(int ref_side, int ref_face, int inc_face, std::uint32_t feature) {
  return (static_cast<std::uint64_t>(ref_side & 1) << 63) |
         (static_cast<std::uint64_t>(ref_face & 0x7FFF) << 48) |
         (static_cast<std::uint64_t>(inc_face & 0xFFFF) << 32) | feature;
}

namespace {

// Pairs [o1, o2) of `from` appended whole to `to` as its pairs from
// `index` on, their subcontacts from `first` on (to.sub already sized):
// one contiguous copy per array.
template <class T>
void copy_range(const std::vector<T>& from, std::size_t begin, std::size_t end, std::vector<T>& to, std::size_t at) {
  std::copy(from.begin() + static_cast<std::ptrdiff_t>(begin), from.begin() + static_cast<std::ptrdiff_t>(end),
            to.begin() + static_cast<std::ptrdiff_t>(at));
}

void copy_range(const Vec3Array& from, std::size_t begin, std::size_t end, Vec3Array& to, std::size_t at) {
  copy_range(from.x, begin, end, to.x, at);
  copy_range(from.y, begin, end, to.y, at);
  copy_range(from.z, begin, end, to.z, at);
}

void copy_pairs(const ContactSet& from, int o1, int o2, int index, int first, ContactSet& to) {
  const Subcontacts& os = from.sub;
  Subcontacts& sc = to.sub;
  const auto begin = static_cast<std::size_t>(from.pairs[static_cast<std::size_t>(o1)].first);
  const ContactPair& last = from.pairs[static_cast<std::size_t>(o2 - 1)];
  const auto end = static_cast<std::size_t>(last.first + last.count);
  const auto at = static_cast<std::size_t>(first);
  copy_range(os.ref_block, begin, end, sc.ref_block, at);
  copy_range(os.inc_block, begin, end, sc.inc_block, at);
  copy_range(os.key, begin, end, sc.key, at);
  copy_range(os.ref_normal_local, begin, end, sc.ref_normal_local, at);
  copy_range(os.ref_offset_local, begin, end, sc.ref_offset_local, at);
  copy_range(os.inc_point_local, begin, end, sc.inc_point_local, at);
  copy_range(os.area, begin, end, sc.area, at);
  copy_range(os.crush, begin, end, sc.crush, at);
  copy_range(os.shear_force, begin, end, sc.shear_force, at);
  copy_range(os.bonded, begin, end, sc.bonded, at);
  copy_range(os.force, begin, end, sc.force, at);
  copy_range(os.point, begin, end, sc.point, at);
  copy_range(os.overlap, begin, end, sc.overlap, at);
  copy_range(os.normal_force, begin, end, sc.normal_force, at);
  copy_range(os.slip_energy, begin, end, sc.slip_energy, at);
  copy_range(os.damping_energy, begin, end, sc.damping_energy, at);
  copy_range(os.damping_force, begin, end, sc.damping_force, at);
  if (sc.moving.on && os.moving.on)
    MovingPoints::for_each_array(sc.moving, os.moving, [&](auto& to_array, const auto& from_array, const char*) {
      copy_range(from_array, begin, end, to_array, at);
    });
  const int shift = first - static_cast<int>(begin);
  for (int o = o1; o < o2; ++o) {
    ContactPair cp = from.pairs[static_cast<std::size_t>(o)];
    const int q = index + (o - o1);
    for (int s = cp.first; s < cp.first + cp.count; ++s) sc.pair[static_cast<std::size_t>(s + shift)] = q;
    cp.first += shift;
    to.pairs.push_back(cp);
  }
}

}  // namespace

void sample_pair(const Blocks& b, int i, int j, const Patch& patch, bool bond_new, int index, int first,
                 ContactPair& cp, Subcontacts& sc) {
  cp.a = i;
  cp.b = j;
  cp.ref_block = patch.ref_side == 0 ? i : j;
  const int inc = patch.ref_side == 0 ? j : i;
  cp.ref_face = patch.ref_face;
  cp.inc_face = patch.inc_face;
  cp.first = first;
  cp.count = static_cast<int>(patch.points.size());
  cp.patch_area = patch.area;
  const Mat3& Rr = b.state.rotation[cp.ref_block];
  const Mat3& Ri = b.state.rotation[inc];
  const Vec3 n_local = Rr.transpose() * patch.normal;
  const double off_local = patch.offset - patch.normal.dot(b.state.position[cp.ref_block]);
  cp.normal_local = n_local;
  cp.offset_local = off_local;
  std::size_t s = static_cast<std::size_t>(first);
  for (const PatchPoint& pt : patch.points) {
    sc.pair[s] = index;
    sc.ref_block[s] = cp.ref_block;
    sc.inc_block[s] = inc;
    sc.key[s] = subcontact_key(patch.ref_side, patch.ref_face, patch.inc_face, pt.feature);
    sc.ref_normal_local[s] = n_local;
    sc.ref_offset_local[s] = off_local;
    sc.inc_point_local.set(s, Ri.transpose() * (pt.point - b.state.position[inc]));
    sc.area[s] = pt.area;
    sc.crush[s] = 0;
    sc.shear_force.set_zero(s);
    sc.bonded[s] = bond_new ? 1 : 0;
    sc.slip_energy[s] = 0;
    sc.damping_energy[s] = 0;
    sc.damping_force.set_zero(s);
    sc.force[s] = Vec3::Zero();
    sc.point[s] = pt.point;
    sc.overlap[s] = -pt.separation;
    sc.normal_force[s] = 0;
    if (sc.moving.on)
      define_moving_point(b.props.local_shape[static_cast<std::size_t>(cp.ref_block)], patch.ref_face,
                          b.props.local_shape[static_cast<std::size_t>(inc)], patch.inc_face, pt,
                          Rr.transpose() * (pt.point - b.state.position[cp.ref_block]), sc.inc_point_local[s], sc.moving,
                          s);
    ++s;
  }
}

void append_pairs(const ContactSet& from, int first_pair, int last_pair, ContactSet& to) {
  if (first_pair >= last_pair) return;
  const int first = static_cast<int>(to.sub.size());
  const ContactPair& lo = from.pairs[static_cast<std::size_t>(first_pair)];
  const ContactPair& hi = from.pairs[static_cast<std::size_t>(last_pair - 1)];
  to.sub.resize(static_cast<std::size_t>(first + (hi.first + hi.count - lo.first)));
  copy_pairs(from, first_pair, last_pair, static_cast<int>(to.pairs.size()), first, to);
}

void build_subcontacts(const Blocks& b, const std::vector<std::pair<int, int>>& candidates,
                       const std::vector<Patch>& patches, const std::vector<char>& found, bool bond_new,
                       ContactSet& contacts, const ContactSet* previous, const std::vector<int>* kept_from) {
  const std::size_t nc = candidates.size();
  auto kept = [&](std::size_t k) { return kept_from && (*kept_from)[k] >= 0; };
  contacts.pairs.clear();
  std::size_t total = 0;
  for (std::size_t k = 0; k < nc; ++k) {
    if (kept(k))
      total += static_cast<std::size_t>(previous->pairs[static_cast<std::size_t>((*kept_from)[k])].count);
    else if (found[k])
      total += patches[k].points.size();
  }
  Subcontacts& sc = contacts.sub;
  sc.resize(total);
  std::size_t s = 0;
  for (std::size_t k = 0; k < nc; ++k) {
    if (kept(k)) {  // a run of pairs that follow each other in `previous` too, copied at once
      const int o1 = (*kept_from)[k];
      std::size_t k2 = k + 1;
      while (k2 < nc && kept(k2) && (*kept_from)[k2] == o1 + static_cast<int>(k2 - k)) ++k2;
      const int o2 = o1 + static_cast<int>(k2 - k);
      const std::size_t n0 = contacts.pairs.size();
      copy_pairs(*previous, o1, o2, static_cast<int>(n0), static_cast<int>(s), contacts);
      for (std::size_t q = n0; q < contacts.pairs.size(); ++q) s += static_cast<std::size_t>(contacts.pairs[q].count);
      k = k2 - 1;
      continue;
    }
    if (!found[k]) continue;
    const auto [i, j] = candidates[k];
    ContactPair cp;
    sample_pair(b, i, j, patches[k], bond_new, static_cast<int>(contacts.pairs.size()), static_cast<int>(s), cp,
                sc);
    s += static_cast<std::size_t>(cp.count);
    contacts.pairs.push_back(cp);
  }
}


// Carrying history by position.
//
// The joint between two blocks is a surface, and what it remembers (how far
// it has been sheared elastically, whether its bond still holds) belongs to
// places on that surface. The subcontacts are only where a detection
// happened to sample it: the vertices of the clipped polygon. Their
// topology changes for reasons that have nothing to do with the joint's
// state: a cube twisted by a hundredth of a radian on an equal cube turns
// its four corner subcontacts into eight crossings, four near the corners
// and four near the middles of the edges; a block sliding over an edge
// turns two corners into two crossings; the reference face may change
// sides. Matching by clip feature lost the whole shear history at each such
// change, and its strain energy vanished from the ledger.
//
// So the previous subcontacts are read as samples of a field. Their incident
// points are fixed in their block, so evaluated at the current pose they are
// where those material points of the joint are now; projected on the joint
// plane they span the previous patch. The elastic shear stress F/A is
// interpolated linearly over it (a fan about the centroid, the centroid
// taking the mean: exact for a uniform shear and for a twist, whose field is
// linear), and a new subcontact takes the stress at its point times its own
// area, i.e. the elastic shear displacement F/(ks·A) carries. Taking the
// nearest previous subcontact's instead (tried first) left the crossings in
// the middle of a twisted cube's edges, half a metre from any corner, with
// no shear, and the cube sprang back about a twisted position.
// A point outside the previous patch (the patch grew, or slid) takes the
// value of the nearest edge within the pair's reach: how far any point of
// one block has moved relative to the other since the last detection,
// from the blocks' own motion. The patch's edge, traced by the reference
// face's sides over the incident face, has not moved farther. Farther out,
// the point was not in contact then: it is contact area that is new,
// without history. (A reach set by anything else, the contact margin, the
// patch's size or the detection travel, a threshold the pair that
// triggered the detection has just crossed, hands shear to area that had
// none or takes it from area that had it.)
//
// Strain energy must not appear from the resampling: a pair whose new shear
// energy exceeds its previous one has its new forces scaled down to it.
// Whatever is not handed on — a patch that shrank, a coarser sampling of the
// same field, a force turned out of a new plane, a pair that is gone — is
// the difference of the shear strain energies before and after, booked as
// dropped.
namespace {

// Signed area (×2) of the triangle (a, b, c) seen along n.
inline double signed_area(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  return (b - a).cross(c - a).dot(n);
}

// The previous patch of one pair: its points [first, first + count) in the
// scratch arrays, their centroid and mean stress.
struct PreviousPatch {
  int first = 0, count = 0;
  Vec3 centroid = Vec3::Zero(), mean_stress = Vec3::Zero();
  double tolerance = 0;
};

// The stress interpolated at q; false if q is farther than the tolerance
// from the patch (in the plane normal to n).
bool interpolate_stress(const PreviousPatch& pp, const CarryScratch& sc, const Vec3& q, const Vec3& n,
                        double tiny_area, Vec3& stress) {
  const Vec3* p = sc.old_point.data() + pp.first;
  const Vec3* t = sc.old_stress.data() + pp.first;
  const int m = pp.count;
  if (m >= 3) {  // inside one of the fan's triangles (c, p_j, p_j+1)?
    const Vec3& c = pp.centroid;
    for (int j = 0; j < m; ++j) {
      const int k = (j + 1) % m;
      const double whole = signed_area(c, p[j], p[k], n);
      if (std::abs(whole) <= tiny_area) continue;
      const double wj = signed_area(c, q, p[k], n) / whole;
      const double wk = signed_area(c, p[j], q, n) / whole;
      const double wc = 1.0 - wj - wk;
      constexpr double kOnEdge = -1e-12;
      if (wj >= kOnEdge && wk >= kOnEdge && wc >= kOnEdge) {
        stress = wc * pp.mean_stress + wj * t[j] + wk * t[k];
        return true;
      }
    }
  }
  // Outside (or a patch of one or two points): the nearest point of the
  // boundary, interpolated along its edge.
  double best = std::numeric_limits<double>::infinity();
  const int edges = m >= 3 ? m : m - 1;
  if (m == 1) {
    Vec3 d = q - p[0];
    d -= d.dot(n) * n;
    best = d.squaredNorm();
    stress = t[0];
  }
  for (int j = 0; j < edges; ++j) {
    const int k = (j + 1) % m;
    Vec3 e = p[k] - p[j];
    e -= e.dot(n) * n;
    Vec3 w = q - p[j];
    w -= w.dot(n) * n;
    const double len2 = e.squaredNorm();
    const double u = len2 > 0 ? std::clamp(w.dot(e) / len2, 0.0, 1.0) : 0.0;
    const double d2 = (w - u * e).squaredNorm();
    if (d2 < best) {
      best = d2;
      stress = (1.0 - u) * t[j] + u * t[k];
    }
  }
  return best <= pp.tolerance * pp.tolerance;
}

// How far any point of block a can have moved relative to any point of
// block b since the previous detection: |d_a − d_b| + turned_a + turned_b
// (each block's points move by its translation plus at most the chord of
// its rotation at its bounding radius), raised by a relative 1e-9 so that a
// point on the edge of a patch whose blocks made just this move is not lost
// to round-off.
double pair_reach(const CarryScratch& sc, int a, int b) {
  if (sc.moved.empty()) return 0.0;
  return (1.0 + 1e-9) * ((sc.moved[a] - sc.moved[b]).norm() + sc.turned[a] + sc.turned[b]);
}

}  // namespace

void carry_history(const Blocks& blocks, const ContactSet& old, ContactSet& contacts, const JointLaws& laws,
                   CarryScratch& scratch, int threads) {
  Subcontacts& sc = contacts.sub;
  const Subcontacts& os = old.sub;
  const BlockState& st = blocks.state;
  const std::size_t n_old = os.size();
  scratch.old_point.resize(n_old);
  scratch.old_stress.resize(n_old);
  // Pair by pair, most pairs are not sampled: only the pairs sampled read
  // their previous points, each its own.
  const bool by_pair = scratch.by_pair;
  const std::size_t n_carry = by_pair ? scratch.sampled.size() : contacts.pairs.size();
  const bool parallel = threads > 1 && n_carry >= 256;
  auto old_sample = [&](std::size_t o) {
    const int c = os.inc_block[o];
    scratch.old_point[o] = st.position[c] + st.rotation[c] * os.inc_point_local[o];
    scratch.old_stress[o] = os.area[o] > 0 ? Vec3(os.shear_force[o] / os.area[o]) : Vec3(Vec3::Zero());
  };
  if (!by_pair) {
#pragma omp parallel for schedule(static) if (parallel) num_threads(threads)
    for (std::size_t o = 0; o < n_old; ++o) old_sample(o);
  }
  scratch.dissipation_taken.assign(n_old, 0);

  // Pair by pair, in parallel: a pair writes only its own subcontacts and
  // reads only its previous pair's (the one pair (a, b) before), whose
  // dissipation flags no other pair touches.
  const std::ptrdiff_t n_pairs = static_cast<std::ptrdiff_t>(n_carry);
#pragma omp parallel for schedule(dynamic, 32) if (parallel) num_threads(threads)
  for (std::ptrdiff_t m = 0; m < n_pairs; ++m) {
    const std::ptrdiff_t q = by_pair ? scratch.sampled[static_cast<std::size_t>(m)] : m;
    const ContactPair& cp = contacts.pairs[static_cast<std::size_t>(q)];
    const ContactPair* op = find_pair(old, cp.a, cp.b);
    if (!op || op->count == 0 || cp.count == 0) continue;
    if (by_pair)  // the previous points of this pair only
      for (int o = op->first; o < op->first + op->count; ++o) old_sample(static_cast<std::size_t>(o));
    PreviousPatch pp;
    pp.first = op->first;
    pp.count = op->count;
    for (int o = op->first; o < op->first + op->count; ++o) {
      pp.centroid += scratch.old_point[o];
      pp.mean_stress += scratch.old_stress[o];
    }
    pp.centroid /= static_cast<double>(op->count);
    pp.mean_stress /= static_cast<double>(op->count);
    double radius2 = 0;
    for (int o = op->first; o < op->first + op->count; ++o)
      radius2 = std::max(radius2, (scratch.old_point[o] - pp.centroid).squaredNorm());
    // The reach, and at least a billionth of the patch's size or of its
    // lever arm on the incident block (a patch of one point): a point of
    // the previous patch found again where it was (the blocks not moved)
    // lies on it to round-off, not beyond it.
    const int c0 = os.inc_block[op->first];
    const double lever = (scratch.old_point[op->first] - st.position[c0]).norm();
    pp.tolerance = std::max(by_pair ? (1.0 + 1e-9) * scratch.reach[static_cast<std::size_t>(q)]
                                    : pair_reach(scratch, cp.a, cp.b),
                            1e-9 * std::max(std::sqrt(radius2), lever));
    const double tiny_area = 1e-12 * radius2;
    const Vec3 n = st.rotation[cp.ref_block] * sc.ref_normal_local[cp.first];
    // The previous forces were on the previous incident block; if the
    // reference face changed sides, the new incident block feels the reaction.
    const double side = os.inc_block[op->first] == sc.inc_block[cp.first] ? 1.0 : -1.0;
    double e_old = 0, e_new = 0;
    for (int o = op->first; o < op->first + op->count; ++o)
      if (os.area[o] > 0) e_old += os.shear_force[o].squaredNorm() / os.area[o];
    for (int s = cp.first; s < cp.first + cp.count; ++s) {
      Vec3 stress = Vec3::Zero();
      if (!interpolate_stress(pp, scratch, sc.point[s], n, tiny_area, stress)) continue;
      Vec3 f = (side * sc.area[s]) * stress;
      f -= f.dot(n) * n;
      sc.shear_force.set(s, f);
      if (sc.area[s] > 0) e_new += f.squaredNorm() / sc.area[s];
      // Bond and dissipation: the nearest previous subcontact's.
      double best = std::numeric_limits<double>::infinity();
      int src = -1;
      for (int o = op->first; o < op->first + op->count; ++o) {
        Vec3 d = sc.point[s] - scratch.old_point[o];
        d -= d.dot(n) * n;
        if (d.squaredNorm() < best) {
          best = d.squaredNorm();
          src = o;
        }
      }
      sc.bonded[s] = os.bonded[src];
      if (!scratch.dissipation_taken[src]) {
        scratch.dissipation_taken[src] = 1;
        sc.slip_energy[s] = os.slip_energy[src];
        sc.damping_energy[s] = os.damping_energy[src];
      }
    }
    if (e_new > e_old) {  // the resampling must not make strain energy
      const double scale = std::sqrt(e_old / e_new);
      for (int s = cp.first; s < cp.first + cp.count; ++s) sc.shear_force.set(s, sc.shear_force[s] * scale);
    }
  }

  // The ledger: dissipation no one took retires; shear energy not handed on
  // is dropped.
  contacts.retired_slip_energy = old.retired_slip_energy;
  contacts.retired_damping_energy = old.retired_damping_energy;
  const bool some_kept = by_pair && !scratch.old_kept.empty();
  for (std::size_t o = 0; o < n_old; ++o) {
    if (scratch.dissipation_taken[o]) continue;
    if (some_kept && scratch.old_kept[static_cast<std::size_t>(os.pair[o])]) continue;  // copied whole
    contacts.retired_slip_energy += os.slip_energy[o];
    contacts.retired_damping_energy += os.damping_energy[o];
  }
  if (!by_pair) {
    contacts.dropped_shear_energy =
        old.dropped_shear_energy + (shear_strain_energy(laws, os) - shear_strain_energy(laws, sc));
  } else {  // the same difference over the pairs sampled and the pairs gone (the rest cancel)
    double dropped = 0;
    scratch.old_taken.assign(old.pairs.size(), 0);
    for (int q : scratch.sampled) {
      const ContactPair& cp = contacts.pairs[static_cast<std::size_t>(q)];
      if (const ContactPair* op = find_pair(old, cp.a, cp.b)) {
        scratch.old_taken[static_cast<std::size_t>(op - old.pairs.data())] = 1;
        dropped += shear_strain_energy(laws, os, op->first, op->first + op->count);
      }
      dropped -= shear_strain_energy(laws, sc, cp.first, cp.first + cp.count);
    }
    for (std::size_t o = 0; o < old.pairs.size(); ++o)  // pairs gone
      if (!scratch.old_taken[o] && !(some_kept && scratch.old_kept[o]))
        dropped += shear_strain_energy(laws, os, old.pairs[o].first, old.pairs[o].first + old.pairs[o].count);
    contacts.dropped_shear_energy = old.dropped_shear_energy + dropped;
  }
  contacts.resampled_normal_energy = old.resampled_normal_energy;
}

}  // namespace polydem
