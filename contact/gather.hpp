// Gather: the per-block sum of the joint forces, in a fixed order.
//
// The joint law writes one force slot per subcontact, in parallel; each
// block then sums the slots of its own subcontacts. The order of that sum is
// fixed once per detection by a CSR list (compressed sparse rows): block i's
// entries are gather_offset[i] .. gather_offset[i+1] of gather_sub (the
// subcontact) and gather_sign (+1: the block is the incident one and feels
// the slot's force, −1: it is the reference one and feels the reaction), in
// increasing subcontact order. No atomics and no per-thread partial sums
// merged in arrival order, so a block's force has the same bits for any
// thread count (Chrono's multicore DEM does the same).
#pragma once

#include "contact/gather_lanes.hpp"
#include "contact/subcontacts.hpp"
#include "core/code_path.hpp"

#include <vector>

namespace polydem {

// Rebuilds contacts.gather_offset / gather_sub / gather_sign for `blocks`
// blocks from contacts.sub. `count`: scratch reused across detections.
void build_gather_lists(int blocks, ContactSet& contacts, std::vector<int>& count);

// The arrays the gather's kernels read and write: `contacts`' lists and
// slots, the blocks' centroids, and their contact force and moment (the sum
// over block i's gather list of the subcontacts' force slots, N, and of
// their moments about the centroid, N·m).
gather_lanes::GatherArrays gather_lane_arrays(const ContactSet& contacts, const std::vector<Vec3>& centroid,
                                              std::vector<Vec3>& force, std::vector<Vec3>& torque);

// The gather's kernels of `path` on this machine (core/code_path.hpp).
gather_lanes::GatherKernels gather_kernels(CodePath path);

}  // namespace polydem
