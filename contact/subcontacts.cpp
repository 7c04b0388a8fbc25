#include "contact/subcontacts.hpp"

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
  shear_force.resize(n);
  bonded.resize(n);
  force.resize(n);
  point.resize(n);
  overlap.resize(n);
  normal_force.resize(n);
  slip_energy.resize(n);
  damping_energy.resize(n);
}

}  // namespace polydem
