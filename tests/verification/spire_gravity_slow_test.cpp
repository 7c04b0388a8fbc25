// The paper's spire (examples/spire/spire_geometry.toml, 401 free blocks)
// stands under gravity alone: after a 1 s settle with the deck's damping no
// corner of any free block has moved 1 mm. Also with flat window heads
// (lintels). Minutes each: label `slow`.
#include "spire_gravity.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kSettle = {"simulation.end_time=1.0", "output.history_interval=0.05"};

TEST(SpireGravitySlow, PapersSpireStandsForOneSecond) {
  const auto s = spire_gravity::settle(kSettle);
  EXPECT_EQ(s.free_blocks, 401);
  EXPECT_LT(s.largest, 1e-3) << s.which;
}

TEST(SpireGravitySlow, FlatHeadsStandForOneSecond) {
  auto o = kSettle;
  o.push_back("spire.window_head_shape=flat");
  const auto s = spire_gravity::settle(o);
  EXPECT_LT(s.largest, 1e-3) << s.which;
}

}  // namespace
}  // namespace polydem
