// The structures examples (examples/structures/*.toml) keep working: each
// deck reads, and a short run of it (end_time cut to a millisecond)
// ends stable, with its energy ledger closed and every block where it
// started to within a millimetre (blocks overlapping at t = 0 would be
// thrown apart: an overlap of a millimetre under joints of ~1e11 Pa/m moves
// a stone far more in a millisecond; free fall alone moves it 5 um).
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

namespace polydem {
namespace {

std::string deck(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/examples/structures/" + name; }

class StructuresExample : public ::testing::TestWithParam<const char*> {};

TEST_P(StructuresExample, ShortRunStaysPut) {
  const SceneSpec s = read_deck(deck(GetParam()), {"simulation.end_time=0.001"});
  ASSERT_GT(s.blocks.size(), 100u);
  const RunReport r = run_scene(s);
  ASSERT_FALSE(r.unstable) << r.instability;
  EXPECT_LT(r.energy_balance_error, 0.05);
  double worst = 0;
  for (std::size_t i = 0; i < s.blocks.size(); ++i)
    worst = std::max(worst, (r.final_position[i] - mass_properties(s.blocks[i].shape).centroid).norm());
  std::cout << "  " << GetParam() << ": " << s.blocks.size() << " blocks, " << r.steps << " steps, largest move "
            << worst << " m\n";
  EXPECT_LT(worst, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Decks, StructuresExample,
                         ::testing::Values("wall_gallery.toml", "tower_gallery.toml", "bell_tower.toml",
                                           "gable_wall.toml"),
                         [](const auto& info) {
                           std::string n = info.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace polydem
