// Through the collapse (issue 15), the `slow` label: a tower of 50 blocks
// 0.4 x 0.4 x 0.2 m (10 m tall), each course shifted 1 cm further along x
// than the one below, so that the 10 lowest joints carry their upper part's
// weight outside their footprint. It breaks up and falls over onto a 150 m
// base; the blocks hit the base and each other at up to ~15 m/s, tumble and
// come to rest. The run must reach its end time (8 s) without a guard stop,
// the energy ledger must close within 5 % of the energy in play, no joint
// may overlap by more than 5 % of the smaller block's size (17 mm), and no
// block may end below the base's top by more than 1 % of its size. Measured
// (1 thread, loaded machine): 349 305 steps in 76 s, balance error 2.9 %,
// deepest overlap 1.69 mm (0.53 %); 4.8 % and 1.96 mm before issue 15's
// history and ledger changes. Coming to rest is not yet checked: one block
// still moves at ~12 m/s at 8 s.
#include "collapse_cases.hpp"

namespace polydem::collapse {
namespace {

std::string tower_deck(double end_time) {
  Header h;
  h.end_time = end_time;
  std::string deck = header(h) + extreme::base(150);
  for (int k = 0; k < 50; ++k)
    deck += box(extreme::numbered("c", k + 1), {0.4, 0.4, 0.2}, {0.01 * k, 0, 0.1 + 0.2 * k});
  return deck;
}

TEST(Tower, FiftyBlocksToppleToRest) {
  const Outcome o = run(tower_deck(8.0), "tower50");
  print("tower of 50 toppling", o);
  ASSERT_FALSE(o.stopped) << o.message;
  EXPECT_LT(o.balance_error, 0.05);
  EXPECT_LT(o.deepest_fraction, 0.05);
  const Blocks& b = o.sim->blocks();
  double fastest = 0, lowest = 0, fell = 0;
  for (int i : b.free_blocks) {
    fastest = std::max(fastest, o.sim->velocity_at_force_time(i).norm());
    lowest = std::min(lowest, lowest_z(b, i) / b.props.size[i]);
    fell = std::max(fell, b.initial_position[i].z() - b.state.position[i].z());
  }
  std::cout << "tower: fastest final speed " << fastest << " m/s, deepest sink " << lowest
            << " of a size, largest fall " << fell << " m" << std::endl;
  // Not yet: at 8 s one block still moves at ~10 m/s (measured 9.96 m/s;
  // not investigated, issue 15). Printed above; the stop is the open item.
  EXPECT_GT(lowest, -0.01);
  EXPECT_GT(fell, 5.0) << "the tower did not fall";
}

}  // namespace
}  // namespace polydem::collapse
