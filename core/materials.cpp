#include "core/materials.hpp"

namespace polydem {

double series_joint_normal_stiffness(double pitch, double mortar_thickness, double e_stone, double e_mortar) {
  return 1.0 / ((pitch - mortar_thickness) / e_stone + mortar_thickness / e_mortar);
}

double joint_shear_stiffness(double normal_stiffness, double shear_ratio) { return shear_ratio * normal_stiffness; }

}  // namespace polydem
