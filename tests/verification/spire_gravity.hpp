// Shared by spire_gravity_test.cpp (coarse spire, short settle: the default
// suite) and spire_gravity_slow_test.cpp (the paper's spire, 1 s settle):
// run the spire deck under gravity alone and measure how far every free
// block moved. A block that the masonry does not support (no horizontal or
// inclined joint under it, only vertical ones) falls freely: 0.1 m in 0.15 s.
#pragma once

#include "run/run_scene.hpp"
#include "core/blocks.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

namespace polydem::spire_gravity {

inline std::string spire_deck() { return std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/spire_geometry.toml"; }

struct Settle {
  RunReport report;
  double largest = 0;     // m: largest displacement of any corner of any free block
  std::string which;      // the block that moved most
  double largest_head = 0;  // m: the same over the window pieces and head blocks
  std::string which_head;
  int free_blocks = 0;
};

// Runs the spire deck with the overrides (no early stop: the whole end_time)
// and returns the largest corner displacement over the free blocks.
inline Settle settle(std::vector<std::string> overrides) {
  overrides.push_back("simulation.settle_velocity=0");
  const SceneSpec spec = read_deck(spire_deck(), overrides);
  EXPECT_EQ(spec.ground_motion.kind, GroundMotionKind::none) << "gravity alone";
  const Blocks initial = build_blocks(spec.blocks);
  RunControl control;
  control.threads = 2;
  Settle s;
  s.report = run_scene(spec, control);
  for (int i = 0; i < initial.count; ++i) {
    if (!initial.is_free(i)) continue;
    ++s.free_blocks;
    const Mat3 r0 = initial.initial_orientation[i].toRotationMatrix();
    const Mat3 r1 = s.report.final_orientation[i].toRotationMatrix();
    for (const Vec3& v : initial.props.local_shape[i].vertices) {
      const Vec3 x0 = initial.initial_position[i] + r0 * v;
      const Vec3 x1 = s.report.final_position[i] + r1 * v;
      const double d = (x1 - x0).norm();
      const std::string& name = initial.props.name[i];
      if (d > s.largest) s.largest = d, s.which = name;
      const bool head = name.find("_piece") != std::string::npos || name.find("_voussoir") != std::string::npos ||
                        name.find("_lintel") != std::string::npos;
      if (head && d > s.largest_head) s.largest_head = d, s.which_head = name;
    }
  }
  std::cout << "  " << s.free_blocks << " free blocks, " << s.report.steps << " steps of dt = " << s.report.time_step
            << " s to t = " << s.report.end_time << " s in " << s.report.wall_seconds
            << " s wall; largest displacement " << s.largest * 1e3 << " mm (" << s.which << "), of the window pieces "
            << s.largest_head * 1e3 << " mm (" << s.which_head << ")\n";
  return s;
}

}  // namespace polydem::spire_gravity
