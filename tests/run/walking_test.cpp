// Walking (output.walking) measured from the blocks' motion at the joints of
// the initial mesh: openings of any size read exactly, far beyond the
// contact margin (3 mm here), where a detected contact no longer exists.
#include "io/deck.hpp"
#include "run/run_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace polydem {
namespace {

// A fixed base and a free stone on it (bed joint) or beside it (vertical
// joint), no gravity, the stone moving away at `speed` m/s: the joint's
// opening at time t is speed·t exactly.
std::string deck(bool bed, double speed, double end_time) {
  std::ostringstream d;
  d << "[simulation]\nend_time = " << end_time << "\ngravity = [0.0, 0.0, 0.0]\ncontact_margin = 0.003\n\n"
    << "[joint]\nnormal_stiffness = 1e9\ndamping = 0.0\n\n"
    << "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [1.0, 1.0, 0.5]\n"
    << "center = " << (bed ? "[0.0, 0.0, -0.25]" : "[0.0, 0.0, 0.25]") << "\nmotion = \"fixed\"\n\n"
    << "[[block]]\nname = \"stone\"\nshape = \"box\"\nsize = [1.0, 1.0, 0.5]\n"
    << "center = " << (bed ? "[0.0, 0.0, 0.25]" : "[1.0, 0.0, 0.25]") << "\n"
    << "velocity = " << (bed ? "[0.0, 0.0, " : "[") << speed << (bed ? "]" : ", 0.0, 0.0]") << "\n\n"
    << "[output]\nhistory_interval = 0.005\nwalking = true\nenergies = false\n";
  return d.str();
}

double column(const HistoryTable& h, std::size_t row, const std::string& name) {
  for (std::size_t c = 0; c < h.columns.size(); ++c)
    if (h.columns[c] == name) return h.rows[row * h.columns.size() + c];
  ADD_FAILURE() << "no column " << name;
  return NAN;
}

// Openings of 0.5, 2, 5 and 20 mm against a 3 mm contact margin, for a bed
// joint and for a vertical joint: every recorded row equals speed·t to 1e-9 m.
void check_openings(bool bed) {
  const double speed = 0.01;  // m/s: 20 mm after 2 s (the run goes on to 2.1 s)
  const RunReport r = run_scene(parse_deck(deck(bed, speed, 2.1), bed ? "bed.toml" : "vertical.toml"));
  const std::string name = bed ? "walking.bed_opening" : "walking.vertical_opening";
  const std::string other = bed ? "walking.vertical_opening" : "walking.bed_opening";
  ASSERT_GT(r.histories.row_count(), 100u);
  int seen = 0;
  for (double target : {0.5e-3, 2e-3, 5e-3, 20e-3}) {
    for (std::size_t row = 0; row < r.histories.row_count(); ++row) {
      const double t = column(r.histories, row, "time");
      if (std::abs(speed * t - target) > 0.5 * speed * 0.005) continue;  // the row nearest the target
      EXPECT_NEAR(column(r.histories, row, name), speed * t, 1e-9) << "t = " << t << " s";
      EXPECT_EQ(column(r.histories, row, other), 0.0) << "no joint of the other kind";
      ++seen;
    }
  }
  EXPECT_EQ(seen, 4);
  const double t_end = column(r.histories, r.histories.row_count() - 1, "time");
  const double peak = bed ? r.walking.max_bed_opening : r.walking.max_vertical_opening;
  const double residual = bed ? r.walking.bed_opening : r.walking.vertical_opening;
  EXPECT_NEAR(peak, speed * t_end, 1e-9);
  EXPECT_GE(residual, peak - 1e-9);  // still moving away at the end
  EXPECT_NEAR(residual, speed * (r.end_time - r.time_step), 1e-9);
  EXPECT_EQ(bed ? r.walking.bed_joint : r.walking.vertical_joint, "base|stone");
}

TEST(Walking, BedJointOpeningsOfAnySizeFromTheBlocksMotion) { check_openings(true); }
TEST(Walking, VerticalJointOpeningsOfAnySizeFromTheBlocksMotion) { check_openings(false); }

// A pair within the contact margin but not touching at t = 0 is no joint.
TEST(Walking, AGapAtTheStartIsNoJoint) {
  std::string text = deck(true, 0.0, 0.01);
  const std::string from = "center = [0.0, 0.0, 0.25]";
  text.replace(text.find(from), from.size(), "center = [0.0, 0.0, 0.251]");  // 1 mm gap, margin 3 mm
  const RunReport r = run_scene(parse_deck(text, "gap.toml"));
  EXPECT_EQ(r.walking.bed_joint, "");
  EXPECT_EQ(r.walking.max_bed_opening, 0.0);
}

// Two courses on a fixed base, no gravity: course 0 is three stones in a
// row (C0, A0, B0), course 1 one narrower stone on A0. B0 moves away along
// x at v (it opens the vertical joint A0|B0 and slides on the base), A1
// lifts off A0 at w (it opens the bed joint under course 1). At the end of
// the run, course 0: bed joints closed, vertical joints 0 and v·t (mean
// v·t/2, largest v·t); course 1: its bed joint w·t, no vertical joint. The
// largest during the run equals the end value (every opening grows).
TEST(Walking, PerCourseOpeningsFromTheBedLevels) {
  const double v = 0.01, w = 0.02, end = 0.5;
  std::ostringstream d;
  d << "[simulation]\nend_time = " << end << "\ngravity = [0.0, 0.0, 0.0]\ncontact_margin = 0.003\n\n"
    << "[joint]\nnormal_stiffness = 1e9\ndamping = 0.0\n\n"
    << "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [3.0, 1.0, 0.5]\ncenter = [0.0, 0.0, -0.25]\n"
    << "motion = \"fixed\"\n\n";
  auto stone = [&](const char* name, double x, double z, double sx, const char* velocity) {
    d << "[[block]]\nname = \"" << name << "\"\nshape = \"box\"\nsize = [" << sx << ", 1.0, 0.5]\n"
      << "center = [" << x << ", 0.0, " << z << "]\nvelocity = " << velocity << "\n\n";
  };
  stone("C0", -1.0, 0.25, 1.0, "[0.0, 0.0, 0.0]");
  stone("A0", 0.0, 0.25, 1.0, "[0.0, 0.0, 0.0]");
  stone("B0", 1.0, 0.25, 1.0, "[0.01, 0.0, 0.0]");
  stone("A1", 0.0, 0.75, 0.8, "[0.0, 0.0, 0.02]");
  d << "[output]\nhistory_interval = 0.01\nwalking = true\nenergies = false\n";
  const RunReport r = run_scene(parse_deck(d.str(), "courses.toml"));
  const double t = r.end_time - r.time_step;  // the force time of the last state
  ASSERT_EQ(r.walking.courses.size(), 2u);
  const CourseWalking& c0 = r.walking.courses[0];
  const CourseWalking& c1 = r.walking.courses[1];
  EXPECT_NEAR(c0.level, 0.0, 1e-12);
  EXPECT_NEAR(c1.level, 0.5, 1e-12);
  EXPECT_EQ(c0.bed_joints, 3);
  EXPECT_EQ(c0.vertical_joints, 2);
  EXPECT_EQ(c1.bed_joints, 1);
  EXPECT_EQ(c1.vertical_joints, 0);
  EXPECT_LT(c0.bed_largest, 1e-9);
  EXPECT_NEAR(c0.vertical_largest, v * t, 1e-9);
  EXPECT_NEAR(c0.vertical_mean, v * t / 2, 1e-9);
  EXPECT_NEAR(c1.bed_largest, w * t, 1e-9);
  EXPECT_NEAR(c1.bed_mean, w * t, 1e-9);
  EXPECT_EQ(c1.vertical_largest, 0.0);
  EXPECT_NEAR(c0.peak_vertical, c0.vertical_largest, 0.01 * v + 1e-9);  // the last record is within one interval
  EXPECT_NEAR(c1.peak_bed, c1.bed_largest, 0.01 * w + 1e-9);
  EXPECT_GT(c1.peak_bed, 0.9 * w * t);
}

}  // namespace
}  // namespace polydem
