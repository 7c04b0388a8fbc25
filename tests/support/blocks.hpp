// Blocks built by hand for the contact tests: a block's spec from a shape
// in world coordinates, and a joint law of round numbers.
#pragma once

#include "contact/joint_law_kernels.hpp"
#include "core/blocks.hpp"

#include <string>
#include <utility>

namespace polydem::test {

inline BlockSpec block_spec(std::string name, Polyhedron shape, BlockMotion motion) {
  BlockSpec s;
  s.name = std::move(name);
  s.shape = std::move(shape);
  s.motion = motion;
  return s;
}

// kn = 1e10 Pa/m, ks = 4e9 Pa/m, tan φ = `tan_phi`, no strength, no damping.
inline JointLaw round_law(double tan_phi = 0.5) {
  JointLaw law;
  law.kn = 1e10;
  law.ks = 4e9;
  law.tan_phi = tan_phi;
  return law;
}

}  // namespace polydem::test
