// Contacts between blocks: pairs, and the subcontacts that carry the joint.
//
// A joint between two blocks is a contact *patch*: the overlap of a reference
// face of one block with the incident face of the other, projected on the
// common plane (the reference face's plane). Its vertices are the
// subcontacts (3DEC style), each with a tributary area; the areas add up to
// the patch area. A block resting face to face thus has springs at the
// corners of its footprint and can rock about an edge, which a single deepest
// point per pair cannot do.
//
// Each subcontact is body-fixed between detections: the reference plane in
// the reference block's body frame, the incident point in the incident
// block's body frame. So the normal gap and the shear displacement follow
// the blocks exactly until the next detection, which only rebuilds the patch
// when some block has moved more than half the contact margin.
//
// Storage is a struct of arrays indexed by subcontact; one force slot per
// subcontact is written in parallel and gathered per block in a fixed order
// (see gather.hpp), so results do not depend on the number of threads.
#pragma once

#include "core/byte_stream.hpp"
#include "geometry/polyhedron.hpp"

#include <cstdint>
#include <vector>

namespace polydem {

struct ContactPair {
  int a = 0, b = 0;        // block indices, a < b
  int ref_block = 0;       // a or b: the block whose face is the common plane
  int ref_face = 0;        // face of ref_block
  int inc_face = 0;        // face of the other block
  int first = 0, count = 0;  // range in Subcontacts
  double patch_area = 0;   // m²
};

struct Subcontacts {
  // Identity.
  std::vector<int> pair;
  std::vector<int> ref_block, inc_block;
  std::vector<std::uint64_t> key;  // (pair-local) features that make the subcontact
  // Body-fixed geometry.
  std::vector<Vec3> ref_normal_local;   // reference face normal, ref body frame
  std::vector<double> ref_offset_local;  // plane n·x = offset, ref body frame
  std::vector<Vec3> inc_point_local;     // incident point, inc body frame
  std::vector<double> area;              // tributary area, m²
  // History carried across detections.
  std::vector<Vec3> shear_force;   // elastic shear force on the incident block, world, N
  std::vector<std::uint8_t> bonded;  // still has cohesion / tensile strength
  // Per-step results (one slot each).
  std::vector<Vec3> force;          // total joint force on the incident block, N
  std::vector<Vec3> point;          // world point where it acts
  std::vector<double> overlap;      // normal overlap u_n (> 0 closed), m
  std::vector<double> normal_force;  // total normal force incl. damping, N
  std::vector<double> slip_energy;     // cumulative slip dissipation, J
  std::vector<double> damping_energy;  // cumulative damping dissipation, J

  std::size_t size() const { return key.size(); }
  void clear();
  void resize(std::size_t n);
};

struct ContactSet {
  std::vector<ContactPair> pairs;
  Subcontacts sub;
  // CSR list of the subcontacts acting on each block, in a fixed order:
  // gather_offset[i] .. gather_offset[i+1] index gather_sub/gather_sign.
  std::vector<int> gather_offset, gather_sub;
  std::vector<double> gather_sign;  // +1 incident, −1 reference
  // Dissipation of subcontacts that no longer exist (kept for the ledger).
  double retired_slip_energy = 0, retired_damping_energy = 0;
  int detections = 0;

  // Checkpoints: every array above, bit for bit (see core/byte_stream.hpp).
  // load() checks that the arrays agree in length and that every block and
  // subcontact index is in range for `blocks` blocks; throws StateFormatError.
  void save(ByteWriter& w) const;
  void load(ByteReader& r, int blocks);
};

}  // namespace polydem
