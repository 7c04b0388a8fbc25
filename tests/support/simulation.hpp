// A Simulation of blocks under one joint law, for tests that build their
// blocks by hand: the laws are made from the blocks before they move in.
#pragma once

#include "integrators/simulation.hpp"

namespace polydem {

inline Simulation one_law_simulation(Blocks blocks, const SimulationSpec& sim, const JointSpec& joint,
                                     GroundMotion motion, double margin, double dt, bool adaptive_time_step = true) {
  JointLaws laws = make_joint_laws(blocks, joint, {});
  return Simulation(std::move(blocks), sim, std::move(laws), std::move(motion), margin, dt, adaptive_time_step);
}

}  // namespace polydem
