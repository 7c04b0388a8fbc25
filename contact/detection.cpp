#include "contact/detection.hpp"

#include "contact/contact_patch.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace polydem {

struct ContactDetector::Impl {
  std::vector<std::shared_ptr<fcl::Boxd>> boxes;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::vector<int> object_block;  // user data
  fcl::DynamicAABBTreeCollisionManagerd manager;
  bool registered = false;
  std::vector<std::pair<int, int>> candidates;
  std::vector<Patch> patches;
  std::vector<char> found;
  std::vector<PatchScratch> scratch;
  std::vector<Vec3> detected_position;
  std::vector<Quat> detected_orientation;
  ContactSet previous;
  std::vector<int> count;
  std::vector<char> old_used;
};

namespace {

struct BroadPhaseData {
  const Blocks* blocks;
  std::vector<std::pair<int, int>>* pairs;
};

bool on_overlap(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* d = static_cast<BroadPhaseData*>(data);
  const int i = *static_cast<const int*>(o1->getUserData());
  const int j = *static_cast<const int*>(o2->getUserData());
  const auto& motion = d->blocks->props.motion;
  if (motion[i] != BlockMotion::free && motion[j] != BlockMotion::free) return false;
  d->pairs->emplace_back(std::min(i, j), std::max(i, j));
  return false;  // keep going
}

void set_box(const Blocks& b, int i, double grow, fcl::Boxd& box, fcl::CollisionObjectd& obj) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  const auto& v = b.props.local_shape[i].vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec3 w = world_vertex(b, i, static_cast<int>(k));
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  box.side = (hi - lo) + Vec3::Constant(2 * grow);
  box.computeLocalAABB();
  obj.setTranslation(0.5 * (lo + hi));
  obj.computeAABB();
}

std::uint64_t subcontact_key(int ref_side, int ref_face, int inc_face, std::uint32_t feature) {
  return (static_cast<std::uint64_t>(ref_side & 1) << 63) |
         (static_cast<std::uint64_t>(ref_face & 0x7FFF) << 48) |
         (static_cast<std::uint64_t>(inc_face & 0xFFFF) << 32) | feature;
}

}  // namespace

ContactDetector::ContactDetector(const Blocks& blocks, double margin) : impl_(std::make_unique<Impl>()), margin_(margin) {
  auto& im = *impl_;
  const int n = blocks.count;
  im.object_block.resize(n);
  for (int i = 0; i < n; ++i) {
    im.object_block[i] = i;
    im.boxes.push_back(std::make_shared<fcl::Boxd>(1.0, 1.0, 1.0));
    im.objects.push_back(std::make_unique<fcl::CollisionObjectd>(im.boxes.back()));
    im.objects.back()->setUserData(&im.object_block[i]);
  }
  im.scratch.resize(std::max(1, omp_get_max_threads()));
  im.detected_position = blocks.state.position;
  im.detected_orientation = blocks.state.orientation;
}

ContactDetector::~ContactDetector() = default;

bool ContactDetector::needs_detection(const Blocks& b) const {
  const auto& im = *impl_;
  double moved = 0;
  const int n = b.count;
#pragma omp parallel for reduction(max : moved) schedule(static) if (n >= 2048)
  for (int i = 0; i < n; ++i) {
    if (b.props.motion[i] == BlockMotion::fixed) continue;
    const Quat dq = b.state.orientation[i] * im.detected_orientation[i].conjugate();
    // |vec(dq)| = sin(angle/2); 2·|vec| bounds the angle well for small turns.
    const double turn = 2.0 * dq.vec().norm() * b.props.radius[i];
    moved = std::max(moved, (b.state.position[i] - im.detected_position[i]).norm() + turn);
  }
  return moved > 0.5 * margin_;
}

void ContactDetector::detect(const Blocks& b, ContactSet& contacts, bool bond_new) {
  auto& im = *impl_;
  const int n = b.count;

  // Broad phase.
  for (int i = 0; i < n; ++i)
    if (!im.registered || b.props.motion[i] != BlockMotion::fixed)
      set_box(b, i, 0.5 * margin_, *im.boxes[i], *im.objects[i]);
  if (!im.registered) {
    std::vector<fcl::CollisionObjectd*> objs;
    for (auto& o : im.objects) objs.push_back(o.get());
    im.manager.registerObjects(objs);
    im.manager.setup();
    im.registered = true;
  } else {
    im.manager.update();
  }
  im.candidates.clear();
  BroadPhaseData data{&b, &im.candidates};
  im.manager.collide(&data, on_overlap);
  std::sort(im.candidates.begin(), im.candidates.end());
  im.candidates.erase(std::unique(im.candidates.begin(), im.candidates.end()), im.candidates.end());

  // The previous contacts become the history to carry over.
  std::swap(im.previous, contacts);
  const ContactSet& old = im.previous;
  auto find_old_pair = [&](int a, int c) -> const ContactPair* {
    auto it = std::lower_bound(old.pairs.begin(), old.pairs.end(), std::make_pair(a, c),
                               [](const ContactPair& p, const std::pair<int, int>& k) {
                                 return std::make_pair(p.a, p.b) < k;
                               });
    return (it != old.pairs.end() && it->a == a && it->b == c) ? &*it : nullptr;
  };

  // Narrow phase and patches, in parallel, one slot per candidate.
  const int nc = static_cast<int>(im.candidates.size());
  im.patches.resize(nc);
  im.found.assign(nc, 0);
#pragma omp parallel for schedule(dynamic, 16) if (nc >= 64)
  for (int k = 0; k < nc; ++k) {
    const auto [i, j] = im.candidates[k];
    const PosedBlock pa{&b.props.local_shape[i], b.state.rotation[i], b.state.position[i], b.props.size[i]};
    const PosedBlock pb{&b.props.local_shape[j], b.state.rotation[j], b.state.position[j], b.props.size[j]};
    int prev_side = -1, prev_face = -1;
    if (const ContactPair* op = find_old_pair(i, j)) {
      prev_side = op->ref_block == i ? 0 : 1;
      prev_face = op->ref_face;
    }
    im.found[k] = find_patch(pa, pb, margin_, prev_side, prev_face, im.patches[k], im.scratch[omp_get_thread_num()]);
  }

  // Assemble in candidate order (sorted by block pair): deterministic.
  contacts.pairs.clear();
  std::size_t total = 0;
  for (int k = 0; k < nc; ++k)
    if (im.found[k]) total += im.patches[k].points.size();
  Subcontacts& sc = contacts.sub;
  sc.resize(total);
  contacts.retired_slip_energy = old.retired_slip_energy;
  contacts.retired_damping_energy = old.retired_damping_energy;
  contacts.detections = old.detections + 1;
  std::vector<char>& old_used = im.old_used;  // reused across detections
  old_used.assign(old.sub.size(), 0);
  std::size_t s = 0;
  for (int k = 0; k < nc; ++k) {
    if (!im.found[k]) continue;
    const auto [i, j] = im.candidates[k];
    const Patch& patch = im.patches[k];
    ContactPair cp;
    cp.a = i;
    cp.b = j;
    cp.ref_block = patch.ref_side == 0 ? i : j;
    const int inc = patch.ref_side == 0 ? j : i;
    cp.ref_face = patch.ref_face;
    cp.inc_face = patch.inc_face;
    cp.first = static_cast<int>(s);
    cp.count = static_cast<int>(patch.points.size());
    cp.patch_area = patch.area;
    const ContactPair* op = find_old_pair(i, j);
    const Mat3& Rr = b.state.rotation[cp.ref_block];
    const Mat3& Ri = b.state.rotation[inc];
    const Vec3 n_local = Rr.transpose() * patch.normal;
    const double off_local = patch.offset - patch.normal.dot(b.state.position[cp.ref_block]);
    for (const PatchPoint& pt : patch.points) {
      sc.pair[s] = static_cast<int>(contacts.pairs.size());
      sc.ref_block[s] = cp.ref_block;
      sc.inc_block[s] = inc;
      sc.key[s] = subcontact_key(patch.ref_side, patch.ref_face, patch.inc_face, pt.feature);
      sc.ref_normal_local[s] = n_local;
      sc.ref_offset_local[s] = off_local;
      sc.inc_point_local[s] = Ri.transpose() * (pt.point - b.state.position[inc]);
      sc.area[s] = pt.area;
      sc.shear_force[s] = Vec3::Zero();
      sc.bonded[s] = bond_new ? 1 : 0;
      sc.slip_energy[s] = 0;
      sc.damping_energy[s] = 0;
      sc.force[s] = Vec3::Zero();
      sc.point[s] = pt.point;
      sc.overlap[s] = -pt.separation;
      sc.normal_force[s] = 0;
      if (op) {
        for (int o = op->first; o < op->first + op->count; ++o) {
          if (old.sub.key[o] != sc.key[s] || old_used[o]) continue;
          old_used[o] = 1;
          sc.shear_force[s] = old.sub.shear_force[o];
          sc.bonded[s] = old.sub.bonded[o];
          sc.slip_energy[s] = old.sub.slip_energy[o];
          sc.damping_energy[s] = old.sub.damping_energy[o];
          break;
        }
      }
      ++s;
    }
    contacts.pairs.push_back(cp);
  }
  for (std::size_t o = 0; o < old.sub.size(); ++o) {
    if (old_used[o]) continue;
    contacts.retired_slip_energy += old.sub.slip_energy[o];
    contacts.retired_damping_energy += old.sub.damping_energy[o];
  }

  // Gather lists: per block, its subcontacts in subcontact order.
  auto& cnt = im.count;
  cnt.assign(n + 1, 0);
  for (std::size_t q = 0; q < total; ++q) {
    ++cnt[sc.inc_block[q] + 1];
    ++cnt[sc.ref_block[q] + 1];
  }
  contacts.gather_offset.resize(n + 1);
  contacts.gather_offset[0] = 0;
  for (int i = 0; i < n; ++i) contacts.gather_offset[i + 1] = contacts.gather_offset[i] + cnt[i + 1];
  contacts.gather_sub.resize(2 * total);
  contacts.gather_sign.resize(2 * total);
  std::copy(contacts.gather_offset.begin(), contacts.gather_offset.end() - 1, cnt.begin());
  for (std::size_t q = 0; q < total; ++q) {
    int& pi = cnt[sc.inc_block[q]];
    contacts.gather_sub[pi] = static_cast<int>(q);
    contacts.gather_sign[pi++] = 1.0;
    int& pr = cnt[sc.ref_block[q]];
    contacts.gather_sub[pr] = static_cast<int>(q);
    contacts.gather_sign[pr++] = -1.0;
  }

  im.detected_position = b.state.position;
  im.detected_orientation = b.state.orientation;
}

void ContactDetector::save(ByteWriter& w) const {
  w.put(impl_->detected_position);
  w.put(impl_->detected_orientation);
}

void ContactDetector::load(ByteReader& r) {
  const std::size_t n = impl_->object_block.size();
  r.get_sized(impl_->detected_position, n, "detector.detected_position");
  r.get_sized(impl_->detected_orientation, n, "detector.detected_orientation");
}

}  // namespace polydem
