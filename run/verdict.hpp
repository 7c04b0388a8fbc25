// The run's verdict: what `polydem run` prints last, in three plain lines
// that answer what the user ran it for.
//
//   collapsed (Mode II) at t = 2.55 s: the mechanism formed at 0.218 g (t = 2.18 s), 15 joints open at z = 0.00-0.77 m
//   lost: 41 of 401 blocks (38 fell), 14.9 % of the free mass, from z = 5.55-6.85 m: course18 (16 of 16), course19 (24 of 24), tip
//   energy: balance error 1.2e-05 of 22.0 kJ; slip dissipated 893 J, damping 8.21 J
//
// 1. the status (intact, damaged, collapsed, undetermined) and the
//    mechanism: when the first block moved the damage displacement and the
//    ground acceleration then (under a rising load, the acceleration at
//    which the mechanism formed), the collapse mode and time, the joints the
//    crack opened, and whether the monitored body's point of no return
//    decided it; an undetermined run names the block still moving and how
//    fast (run it longer);
// 2. what was lost, the blocks that end more than the collapse displacement
//    from their place: their count, how many of them fell, their fraction
//    of the free mass, and where they came from (the heights of their
//    starting centroids, and the groups, e.g. a spire's courses, with how
//    many of each group's blocks were lost);
// 3. the energy balance: the ledger's error against its reference energy,
//    and what slip and damping dissipated.
// Every figure is one of summary.json's (io/summary.cpp). A run the guard
// stopped has no verdict: its message says why it stopped.
#pragma once

#include "core/scene_spec.hpp"
#include "run/run_scene.hpp"

#include <string>
#include <vector>

namespace polydem {

std::vector<std::string> verdict_lines(const SceneSpec& spec, const RunReport& report);

}  // namespace polydem
