// Setting a run up, before its first step: the contact margin, the time
// step and the check that no blocks overlap at the start.
//
//   margin     the deck's simulation.contact_margin, or 2 % of the smallest
//              free block's size (of any block when none is free)
//   time step  the critical step of the stiffest block mode, corrected for
//              the joint damping, times simulation.safety_factor
//              (integrators/critical_time_step.hpp); a deck may only lower it
//   overlap    blocks overlapping more than simulation.overlap_tolerance at
//              t = 0 are bad input
//
// Errors are SceneErrors naming the deck key: the command line turns them
// into the deck's file and line.
#pragma once

#include "core/scene_spec.hpp"
#include "integrators/simulation.hpp"

#include <memory>

namespace polydem {

struct RunSetup {
  double margin = 0;     // m
  CriticalStep critical; // the estimate before the first detection
  double time_step = 0;  // s, the step the run starts with
};

// 2 % of the smallest free block's size (of any block when none is free).
double automatic_margin(const Blocks& blocks);

// The margin and the time step for these blocks and their joints' laws.
// Throws SceneError ("simulation.time_step") when the deck's step exceeds
// the stable one.
RunSetup choose_margin_and_step(const SceneSpec& spec, const Blocks& blocks, const JointLaws& laws);

// Throws SceneError ("block", with the later block's deck line) when two
// blocks overlap beyond the tolerance at the start.
void check_initial_overlaps(const SceneSpec& spec, const Simulation& sim);

// The blocks, the ground motion (its record was read with the deck, and the
// caller's extra acceleration if any: GroundMotion::extra), the margin and
// the step, the first contact detection and the overlap check.
std::unique_ptr<Simulation> build_simulation(const SceneSpec& spec, RunSetup& setup,
                                             ExtraGroundAcceleration extra = {});

}  // namespace polydem
