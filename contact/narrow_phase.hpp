// Narrow phase: are two convex blocks within the contact margin, and by how
// much do they overlap?
//
// libccd's MPR (Minkowski portal refinement) on the blocks' support
// functions, each block inflated by a sphere of radius margin/2: the inflated
// blocks overlap exactly when the real ones are closer than the margin. MPR
// then gives the penetration depth of the inflated blocks, its direction and
// a point in the middle of the overlap. The depth less the margin is the
// overlap of the real blocks (negative: a gap smaller than the margin).
//
// The common plane and the patch (contact_patch.hpp) are found from the
// faces; this answer serves to reject distant pairs and as the fallback
// normal when no face separates the blocks (edge against edge).
#pragma once

#include "geometry/polyhedron.hpp"

#include <vector>

namespace polydem {

struct NarrowPhaseHit {
  double overlap = 0;              // of the real (uninflated) blocks, m: MPR depth − margin
  Vec3 direction = Vec3::Zero();   // MPR penetration direction, from the first block towards the second
  Vec3 point = Vec3::Zero();       // MPR contact point (middle of the overlap), world
};

// world_a, world_b: the blocks' vertices in world coordinates; centre_a,
// centre_b: a point inside each (the centroid). Returns false when the
// blocks are farther apart than `margin`; otherwise fills `hit`.
bool narrow_phase(const std::vector<Vec3>& world_a, const Vec3& centre_a, const std::vector<Vec3>& world_b,
                  const Vec3& centre_b, double margin, NarrowPhaseHit& hit);

}  // namespace polydem
