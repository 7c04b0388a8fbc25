#include "contact/narrow_phase.hpp"

#include <ccd/ccd.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace polydem {

namespace {

// A block as libccd sees it: world vertices inflated by a sphere of radius
// `inflate`, so that MPR reports overlap for blocks closer than the margin.
// The n vertices are kept as x, y and z arrays: MPR asks each block for its
// support point some tens of times, and the dot products of a direction
// with every vertex then run as one loop over contiguous doubles (the same
// (x·dx + y·dy) + z·dz as Vec3::dot, so the same bits and the same vertex).
struct CcdBody {
  std::size_t n;
  const double* x;
  const double* y;
  const double* z;
  Vec3 centre;
  double inflate;
};

// Scratch for the x, y, z arrays of both blocks and the dot products, one
// per thread (detection runs the narrow phase on several): no allocation
// once the largest block has been seen.
struct SupportScratch {
  std::vector<double> xyz_a, xyz_b, dots;
};
thread_local SupportScratch scratch;

void split_xyz(const std::vector<Vec3>& v, std::vector<double>& out) {
  const std::size_t n = v.size();
  out.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = v[i].x();
    out[n + i] = v[i].y();
    out[2 * n + i] = v[i].z();
  }
}

void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* body = static_cast<const CcdBody*>(obj);
  const Vec3 d(ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir));
  const std::size_t n = body->n;
  double* dots = scratch.dots.data();
  const double* x = body->x;
  const double* y = body->y;
  const double* z = body->z;
  const double dx = d.x(), dy = d.y(), dz = d.z();
  for (std::size_t i = 0; i < n; ++i) dots[i] = (x[i] * dx + y[i] * dy) + z[i] * dz;
  // The first vertex of the largest product, as the scan over Vec3 found it.
  double best = -std::numeric_limits<double>::infinity();
  std::size_t arg = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (dots[i] > best) {
      best = dots[i];
      arg = i;
    }
  }
  Vec3 p = arg < n ? Vec3(x[arg], y[arg], z[arg]) : Vec3(Vec3::Zero());
  const double len = d.norm();
  if (len > 0) p += (body->inflate / len) * d;
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

void ccd_centre(const void* obj, ccd_vec3_t* out) {
  const auto* body = static_cast<const CcdBody*>(obj);
  ccdVec3Set(out, body->centre.x(), body->centre.y(), body->centre.z());
}

}  // namespace

bool narrow_phase(const std::vector<Vec3>& world_a, const Vec3& centre_a, const std::vector<Vec3>& world_b,
                  const Vec3& centre_b, double margin, NarrowPhaseHit& hit) {
  split_xyz(world_a, scratch.xyz_a);
  split_xyz(world_b, scratch.xyz_b);
  scratch.dots.resize(std::max(world_a.size(), world_b.size()));
  const std::size_t na = world_a.size(), nb = world_b.size();
  const double* xa = scratch.xyz_a.data();
  const double* xb = scratch.xyz_b.data();
  CcdBody ca{na, xa, xa + na, xa + 2 * na, centre_a, 0.5 * margin};
  CcdBody cb{nb, xb, xb + nb, xb + 2 * nb, centre_b, 0.5 * margin};
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
