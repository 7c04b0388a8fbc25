// The spire stands under gravity: every block is carried by the masonry
// under it (horizontal beds, or the inclined springing joints of the window
// heads), none only by vertical joints. Coarse spire (one stone per face,
// 0.6 m courses; the windows and the joints above them as in the paper's
// spire) for 0.15 s, long enough for an unsupported block to fall 0.11 m;
// the paper's spire for 1 s is spire_gravity_slow_test.cpp.
#include "spire_gravity.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kCoarse = {"spire.stones_per_face=1", "spire.course_height=0.6",
                                          "simulation.end_time=0.15", "output.history_interval=0.05"};

TEST(SpireGravity, CoarseSpireWithPointedHeadsStands) {
  const auto s = spire_gravity::settle(kCoarse);
  EXPECT_GT(s.free_blocks, 80);
  EXPECT_LT(s.largest, 1e-3) << s.which;
}

TEST(SpireGravity, CoarseSpireWithFlatHeadsStands) {
  auto o = kCoarse;
  o.push_back("spire.window_head_shape=flat");
  const auto s = spire_gravity::settle(o);
  EXPECT_LT(s.largest, 1e-3) << s.which;
}

}  // namespace
}  // namespace polydem
