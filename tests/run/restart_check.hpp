// A restart from the first checkpoint a run writes ends bit for bit as the
// run that was not stopped: steps, final positions and velocities, ledger.
// (The deck must ask for checkpoints: output.checkpoint_interval.)
#pragma once

#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace polydem {

// The 52-stone dry-stone wall under a 0.5 g, 0.05 s one-sine pulse for
// 0.03 s with a checkpoint every 0.01 s, and `setting` (a deck key=value):
// joints slip and are re-sampled between checkpoints.
inline SceneSpec pulsed_wall_with_checkpoints(const std::string& setting) {
  const std::string path = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/dry_stone_wall.toml";
  return read_deck(path, {setting, "simulation.end_time=0.03", "output.checkpoint_interval=0.01",
                          "ground_motion.kind=\"sine_pulse\"", "ground_motion.acceleration_g=0.5",
                          "ground_motion.period=0.05", "ground_motion.direction=[1.0, 0.0, 0.0]"});
}

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
