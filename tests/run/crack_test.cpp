// The crack judged on the joints of the initial mesh from the blocks' poses
// (run/crack.hpp): a joint that slid cracks as one that opened, a pair of
// stones moving together does not, and the crack is placed where it was
// built, beyond any contact margin.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace polydem {
namespace {

// A column of three 1 m stones on a fixed base, no gravity. The middle and
// top stones slide together along x at 10 mm/s; the top one also lifts at
// `lift` m/s. After 1 s the joint at z = 0.5 m has slid 10 mm without
// opening, the one at z = 1 m has opened by lift·t, the one at z = 0 has not
// moved. The stones still drift at the end, so the run is `undetermined`
// (run/assessment.hpp); its crack is measured all the same.
std::string column_deck(double lift, const std::string& extra = "") {
  std::ostringstream d;
  d << "[simulation]\nend_time = 1.0\ngravity = [0.0, 0.0, 0.0]\ncontact_margin = 0.003\n" << extra << "\n"
    << "[joint]\nnormal_stiffness = 1e9\ndamping = 0.0\n\n"
    << "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [1.0, 1.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
    << "motion = \"fixed\"\n\n";
  const char* names[] = {"s1", "s2", "s3"};
  for (int k = 0; k < 3; ++k) {
    d << "[[block]]\nname = \"" << names[k] << "\"\nshape = \"box\"\nsize = [1.0, 1.0, 0.5]\n"
      << "center = [0.0, 0.0, " << 0.25 + 0.5 * k << "]\n";
    if (k == 1) d << "velocity = [0.01, 0.0, 0.0]\n";
    if (k == 2) d << "velocity = [0.01, 0.0, " << lift << "]\n";
    d << "\n";
  }
  d << "[output]\nhistories = []\nenergies = false\n\n[assessment]\ndamage_displacement = 0.005\n";
  return d.str();
}

TEST(Crack, AJointThatSlidCracksAndStonesMovingTogetherDoNot) {
  const RunReport r = run_scene(parse_deck(column_deck(0.0), "slide.toml"));
  ASSERT_EQ(r.assessment.status, "undetermined");
  EXPECT_NEAR(r.end_time, 1.0, 1e-3);
  // One joint, the slid one at z = 0.5 m: one point has no axis.
  EXPECT_EQ(r.assessment.opened_joints, 1);
  EXPECT_EQ(r.assessment.crack_angle_deg, -1);
}

TEST(Crack, ASlidJointAndAnOpenedOneAboveItMakeAVerticalCrack) {
  for (const char* margin : {"", "contact_margin = 0.0015", "contact_margin = 0.006"}) {
    std::string text = column_deck(0.01);
    if (*margin) text.replace(text.find("contact_margin = 0.003"), 22, margin);
    const RunReport r = run_scene(parse_deck(text, "lift.toml"));
    ASSERT_EQ(r.assessment.status, "undetermined") << margin;
    EXPECT_EQ(r.assessment.opened_joints, 2) << margin;
    EXPECT_NEAR(r.assessment.crack_angle_deg, 90.0, 1e-9) << margin;
    EXPECT_NEAR(r.assessment.crack_low_z, 0.5, 1e-12) << margin;
    EXPECT_NEAR(r.assessment.crack_high_z, 1.0, 1e-12) << margin;
  }
}

}  // namespace
}  // namespace polydem
