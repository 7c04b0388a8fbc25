// The spire with three stones per face (examples/spire/three_stones_per_face.toml,
// 514 blocks) against the paper's 3DEC range for the collapse acceleration
// onto the window face, 0.164-0.176 g. Re-sampled scene-wide at that
// trigger's automatic travel (0.25 % of the smallest block,
// docs/contact.md; how it was measured) it stands under a
// constant 0.13 g and collapses under 0.164 g (each rising over 0.5 s,
// then held): its collapse acceleration lies below the paper's band, as
// that of the two stones per face does scene-wide (λ 0.152 g, docs/contact.md,
// "Convergence of the answers"). Measured: at 0.15 g the upper spire is
// past its point of no return at the deck's 3 s. With the detection travel
// at half the margin it lay inside the band (0.1650-0.1662 g), a setting
// whose answers move with the margin. Slow label: two runs of a few
// minutes each.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace polydem {
namespace {

TEST(SpireBandSlow, ThreeStonesPerFaceStandsAt013gAndCollapsesAtTheBandsLowEnd) {
  const std::string deck = std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/three_stones_per_face.toml";
  RunControl control;
  control.threads = 2;
  for (const double a : {0.13, 0.164}) {
    const SceneSpec spec = read_deck(deck, {"ground_motion.acceleration_g=" + std::to_string(a),
                                            "simulation.detection_trigger=\"scene\""});
    ASSERT_EQ(spec.blocks.size(), 514u);
    const RunReport r = run_scene(spec, control);
    std::cout << "  three stones per face at " << a << " g: " << r.assessment.status << " (" << r.steps
              << " steps, " << r.wall_seconds << " s)\n";
    if (a < 0.15) EXPECT_EQ(r.assessment.status, "intact") << "does not stand at 0.13 g";
    else EXPECT_EQ(r.assessment.status, "collapsed") << "stands at the paper's band's low end";
  }
}

}  // namespace
}  // namespace polydem
