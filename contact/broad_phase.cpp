#include "contact/broad_phase.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <limits>

namespace polydem {

struct BroadPhase::Impl {
  std::vector<std::shared_ptr<fcl::Boxd>> boxes;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::vector<int> object_block;  // user data
  fcl::DynamicAABBTreeCollisionManagerd manager;
  bool registered = false;
};

namespace {

struct OverlapData {
  const Blocks* blocks;
  std::vector<std::pair<int, int>>* pairs;
};

bool on_overlap(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* d = static_cast<OverlapData*>(data);
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

}  // namespace

BroadPhase::BroadPhase(int blocks) : impl_(std::make_unique<Impl>()) {
  auto& im = *impl_;
  im.object_block.resize(blocks);
  for (int i = 0; i < blocks; ++i) {
    im.object_block[i] = i;
    im.boxes.push_back(std::make_shared<fcl::Boxd>(1.0, 1.0, 1.0));
    im.objects.push_back(std::make_unique<fcl::CollisionObjectd>(im.boxes.back()));
    im.objects.back()->setUserData(&im.object_block[i]);
  }
}

BroadPhase::~BroadPhase() = default;

void BroadPhase::find_pairs(const Blocks& b, double grow, std::vector<std::pair<int, int>>& pairs) {
  auto& im = *impl_;
  const int n = b.count;
  for (int i = 0; i < n; ++i)
    if (!im.registered || b.props.motion[i] != BlockMotion::fixed) set_box(b, i, grow, *im.boxes[i], *im.objects[i]);
  if (!im.registered) {
    std::vector<fcl::CollisionObjectd*> objs;
    for (auto& o : im.objects) objs.push_back(o.get());
    im.manager.registerObjects(objs);
    im.manager.setup();
    im.registered = true;
  } else {
    im.manager.update();
  }
  pairs.clear();
  OverlapData data{&b, &pairs};
  im.manager.collide(&data, on_overlap);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

}  // namespace polydem
