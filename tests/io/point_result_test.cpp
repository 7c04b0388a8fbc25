// What a sweep keeps of a run's summary.json: the stones lost apart from the
// collapse (issue 15: a "first stones lost" curve beside the collapse curve).
#include "io/summary.hpp"

#include <gtest/gtest.h>

namespace polydem {
namespace {

TEST(PointResult, StonesLostWithoutCollapseAreTheirOwnClass) {
  const PointResult r = point_result_from_summary(
      R"({"status": "damaged", "assessment": {"collapse_mode": "", "dislodged": {"count": 3, "mass_kg": 120.5}}})",
      "stones.json");
  EXPECT_EQ(r.dislodged, 3);
  EXPECT_EQ(r.klass(), "stones");
}

TEST(PointResult, DamageWithoutStonesLostAndCollapseKeepTheirClasses) {
  EXPECT_EQ(point_result_from_summary(R"({"status": "damaged", "assessment": {"dislodged": {"count": 0}}})", "d")
                .klass(),
            "damaged");
  // A summary written before dislodged stones were reported reads as none.
  EXPECT_EQ(point_result_from_summary(R"({"status": "damaged", "assessment": {}})", "old").dislodged, 0);
  const PointResult c = point_result_from_summary(
      R"({"status": "collapsed", "assessment": {"collapse_mode": "I", "dislodged": {"count": 40}}})", "c");
  EXPECT_EQ(c.klass(), "I");
}

}  // namespace
}  // namespace polydem
