// A restart from the first checkpoint a run writes ends bit for bit as the
// run that was not stopped: steps, final positions and velocities, ledger.
// (The deck must ask for checkpoints: output.checkpoint_interval.)
#pragma once

#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace polydem {

inline RunReport expect_restart_continues_bitwise(const SceneSpec& spec) {
  std::string first;
  RunControl keep;
  keep.checkpoint = [&](const std::string& state) {
    if (first.empty()) first = state;
  };
  const RunReport whole = run_scene(spec, keep);
  EXPECT_FALSE(first.empty());
  if (first.empty()) return whole;
  RunControl again;
  again.restart = &first;
  const RunReport resumed = run_scene(spec, again);
  EXPECT_EQ(whole.steps, resumed.steps);
  EXPECT_EQ(std::memcmp(whole.final_position.data(), resumed.final_position.data(),
                        whole.final_position.size() * sizeof(Vec3)),
            0);
  EXPECT_EQ(std::memcmp(whole.final_velocity.data(), resumed.final_velocity.data(),
                        whole.final_velocity.size() * sizeof(Vec3)),
            0);
  EXPECT_EQ(std::memcmp(&whole.energy, &resumed.energy, sizeof(EnergyLedger)), 0);
  return whole;
}

}  // namespace polydem
