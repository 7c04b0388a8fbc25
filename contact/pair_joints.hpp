// The state of a joint taken as a whole (the overlap joint model,
// contact/overlap_joint.hpp): one entry per block pair, in the order of
// ContactSet::pairs. Plain arrays, sized only when the scene uses that model.
#pragma once

#include "contact/joint_law_kernels.hpp"
#include "contact/overlap_integral.hpp"
#include "core/byte_stream.hpp"
#include "geometry/polyhedron.hpp"

#include <vector>

namespace polydem {

struct PairJoints {
  // The joint's plane, kept while the pair is found again: the block that
  // carries it (the pair's reference block when first found) and, in that
  // block's frame, its unit normal and offset (plane normal·x = offset).
  std::vector<int> ref_block;
  std::vector<Vec3> normal_local;
  std::vector<double> offset_local;
  // History carried across detections by the pair's identity.
  std::vector<Vec3> shear;     // elastic shear force on the incident block, world, N
  std::vector<double> twist;   // elastic twisting moment on the incident block about the normal, N·m
  std::vector<double> slip_energy;     // cumulative friction work, J
  std::vector<double> damping_energy;  // cumulative dashpot work, J
  // The dashpots' wrench of the last step (force on the incident block, its
  // moment about that block's centroid and the reaction's about the
  // reference block's): the second half of its work is booked with the next
  // step's velocities (contact/joint_law.hpp explains the halves).
  std::vector<lanes::PairRest> damping;
  // Per-step results.
  std::vector<lanes::PairRest> wrench;  // the joint's whole wrench, same convention
  std::vector<double> normal_force;     // elastic plus viscous, N
  std::vector<double> overlap;          // the largest overlap over the contact region, m
  std::vector<double> area;             // area of the contact region, m² (carried: the shear follows it)
  std::vector<double> polar;            // its polar moment about the pressure centroid, m⁴ (likewise)
  std::vector<double> strain_energy;    // ½·kn·∫t² + shear and twist spring energies, J
  std::vector<std::uint8_t> sliding;    // 1 while the joint slips
  // Each pair's faces that can meet before the next detection
  // (overlap_face_pairs): cells[cell_first[q] .. cell_first[q + 1]).
  // Derived from the poses at the detection; not checkpointed.
  std::vector<int> cell_first;
  std::vector<FacePair> cells;

  std::size_t size() const { return shear.size(); }
  void resize(std::size_t n);
  void save(ByteWriter& w) const;
  void load(ByteReader& r, std::size_t pairs);
};

}  // namespace polydem
