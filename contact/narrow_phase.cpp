#include "contact/narrow_phase.hpp"

#include <ccd/ccd.h>

#include <limits>

namespace polydem {

namespace {

// A block as libccd sees it: world vertices inflated by a sphere of radius
// `inflate`, so that MPR reports overlap for blocks closer than the margin.
struct CcdBody {
  const std::vector<Vec3>* vertices;
  Vec3 centre;
  double inflate;
};

void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* body = static_cast<const CcdBody*>(obj);
  const Vec3 d(ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir));
  double best = -std::numeric_limits<double>::infinity();
  Vec3 arg = Vec3::Zero();
  for (const Vec3& v : *body->vertices) {
    const double s = v.dot(d);
    if (s > best) {
      best = s;
      arg = v;
    }
  }
  const double len = d.norm();
  if (len > 0) arg += (body->inflate / len) * d;
  ccdVec3Set(out, arg.x(), arg.y(), arg.z());
}

void ccd_centre(const void* obj, ccd_vec3_t* out) {
  const auto* body = static_cast<const CcdBody*>(obj);
  ccdVec3Set(out, body->centre.x(), body->centre.y(), body->centre.z());
}

}  // namespace

bool narrow_phase(const std::vector<Vec3>& world_a, const Vec3& centre_a, const std::vector<Vec3>& world_b,
                  const Vec3& centre_b, double margin, NarrowPhaseHit& hit) {
  CcdBody ca{&world_a, centre_a, 0.5 * margin};
  CcdBody cb{&world_b, centre_b, 0.5 * margin};
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd_support;
  ccd.support2 = ccd_support;
  ccd.center1 = ccd_centre;
  ccd.center2 = ccd_centre;
  ccd.max_iterations = 200;
  ccd.mpr_tolerance = 1e-6 * margin;
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  if (ccdMPRPenetration(&ca, &cb, &ccd, &depth, &dir, &pos) != 0) return false;
  hit.overlap = depth - margin;
  hit.direction = Vec3(ccdVec3X(&dir), ccdVec3Y(&dir), ccdVec3Z(&dir));
  hit.point = Vec3(ccdVec3X(&pos), ccdVec3Y(&pos), ccdVec3Z(&pos));
  return true;
}

}  // namespace polydem
