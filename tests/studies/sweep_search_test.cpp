// The sweep's grid and boundary search, without running any deck: the axes
// a user types, the Cartesian product, and the search on a made-up response
// whose thresholds are known, including a Mode I loop that closes before
// Mode II (the case a plain bisection of "collapsed or not" would miss).
#include "studies/sweep_grid.hpp"
#include "studies/sweep_search.hpp"
#include "io/sweep_tables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

namespace polydem {
namespace {

TEST(SweepAxis, RangesAndListsAsTyped) {
  const SweepAxis a = parse_axis("ground_motion.acceleration_g=0.4:1.6:4");
  EXPECT_EQ(a.key, "ground_motion.acceleration_g");
  // Decimal steps come out as written (rounded to 12 digits), ends exact.
  EXPECT_EQ(a.values, (std::vector<double>{0.4, 0.8, 1.2, 1.6}));
  EXPECT_EQ(parse_axis("ground_motion.period=0.5,0.75,2").values, (std::vector<double>{0.5, 0.75, 2.0}));
  EXPECT_EQ(parse_axis("joint.friction_angle=30:30:1").values, (std::vector<double>{30.0}));
  EXPECT_EQ(parse_axis("a.b=0:1:11").values[3], 0.3);
}

TEST(SweepAxis, RejectsWhatIsNotAnAxis) {
  for (const char* bad : {"period=0.5:1:3", "ground_motion.period", "ground_motion.period=", "=1,2",
                          "ground_motion.period=1:0.5:3", "ground_motion.period=0.5:1", "ground_motion.period=0.5:1:0",
                          "ground_motion.period=0.5:1:x", "ground_motion.period=1,,2", "ground_motion.period=nan",
                          "ground_motion.period=0.5:1:3:4"}) {
    try {
      (void)parse_axis(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST(SweepGrid, CartesianProductFirstAxisSlowest) {
  const auto points = grid_points({parse_axis("g.t=1,2"), parse_axis("g.a=0.1,0.2,0.3")});
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[0].label(), "t=1 a=0.1");
  EXPECT_EQ(points[2].label(), "t=1 a=0.3");
  EXPECT_EQ(points[3].label(), "t=2 a=0.1");
  EXPECT_EQ(points[5].overrides(), (std::vector<std::string>{"g.t=2", "g.a=0.3"}));
  EXPECT_EQ(grid_points({}).size(), 1u);  // a search without --vary: one column
}

// A response with known thresholds along a (amplitude, in g) for a period t:
// intact below 0.5 + 0.1/t, damaged up to 0.7, Mode I up to 1.0 + 0.1 t, a
// damaged gap 0.04 wide, then Mode II. The lattice is 0.01 g, so every
// threshold is a lattice value and the search must land on it exactly.
PointResult response(double t, double a) {
  PointResult r;
  const double damage = 0.5 + 0.1 / t, loop_top = 1.0 + 0.1 * t;
  if (a < damage - 1e-9) {
    r.status = "intact";
  } else if (a < 0.7 - 1e-9) {
    r.status = "damaged";
  } else if (a < loop_top - 1e-9) {
    r.status = "collapsed";
    r.collapse_mode = "I";
  } else if (a < loop_top + 0.04 - 1e-9) {
    r.status = "damaged";
  } else {
    r.status = "collapsed";
    r.collapse_mode = "II";
  }
  r.wall_seconds = 1;
  return r;
}

TEST(BoundarySearch, FindsEveryThresholdToTheResolutionWithFewRuns) {
  const auto outer = grid_points({parse_axis("ground_motion.period=1,2")});
  const SearchAxis axis = parse_search_axis("ground_motion.acceleration_g=0.2:3.0:15", 0.01);
  EXPECT_EQ(axis.lattice_points(), 281);
  std::set<std::string> seen;
  int batches = 0;
  const SearchReport rep = boundary_search(outer, axis, [&](const std::vector<SweepPoint>& batch) {
    ++batches;
    std::vector<PointResult> out;
    for (const SweepPoint& p : batch) {
      EXPECT_TRUE(seen.insert(p.label()).second) << "ran twice: " << p.label();
      out.push_back(response(p.values[0].second, p.values[1].second));
    }
    return out;
  });
  ASSERT_EQ(rep.columns.size(), 2u);
  for (const ColumnResult& c : rep.columns) {
    const double t = c.outer.values[0].second;
    EXPECT_NEAR(c.damage_threshold, 0.5 + 0.1 / t, 1e-12);
    EXPECT_NEAR(c.collapse_threshold, 0.7, 1e-12);
    EXPECT_EQ(c.collapse_mode, "I");
    ASSERT_EQ(c.transitions.size(), 4u) << transitions_text(c.transitions);
    EXPECT_EQ(c.transitions[2].from, "I");
    EXPECT_EQ(c.transitions[2].to, "damaged");
    EXPECT_NEAR(c.transitions[2].above, 1.0 + 0.1 * t, 1e-12);  // the Mode I loop closes...
    EXPECT_NEAR(c.transitions[3].above, 1.04 + 0.1 * t, 1e-12);  // ...and Mode II starts 0.04 g higher
    EXPECT_NEAR(c.transitions[3].above - c.transitions[3].below, 0.01, 1e-12);
    EXPECT_EQ(c.transitions[3].to, "II");
  }
  EXPECT_EQ(rep.full_grid, 2 * 281);
  EXPECT_EQ(rep.runs, static_cast<long>(seen.size()));
  EXPECT_LT(rep.runs, 80);  // 15 coarse + ~5 bisections per transition, per column
  EXPECT_EQ(rep.rounds, batches);
  EXPECT_LE(batches, 1 + 6);  // coarse scan + log2(0.2 / 0.01) rounds, all columns together
}

TEST(BoundarySearch, ALoopBetweenTwoCoarsePointsIsNotSeen) {
  // The documented limit: the coarse step (0.2 g) is wider than the Mode I
  // loop of width 0.04 g placed between two coarse points, so the search
  // reports no collapse below Mode II; a finer coarse scan finds it.
  auto loop = [](double a) {
    PointResult r;
    r.status = (a > 1.01 && a < 1.05) || a >= 2.0 ? "collapsed" : "damaged";
    r.collapse_mode = r.status == "collapsed" ? (a >= 2.0 ? "II" : "I") : "";
    return r;
  };
  auto search = [&](const char* arg) {
    return boundary_search(grid_points({}), parse_search_axis(arg, 0.01), [&](const std::vector<SweepPoint>& b) {
      std::vector<PointResult> out;
      for (const auto& p : b) out.push_back(loop(p.values[0].second));
      return out;
    });
  };
  EXPECT_NEAR(search("g.a=0.2:3.0:15").columns[0].collapse_threshold, 2.0, 1e-12);
  const SearchReport fine = search("g.a=0.2:3.0:71");  // 0.04 g coarse step
  EXPECT_NEAR(fine.columns[0].collapse_threshold, 1.02, 1e-12);
  EXPECT_EQ(fine.columns[0].collapse_mode, "I");
}

TEST(BoundarySearch, FindsTheFirstStonesLostApartFromTheCollapse) {
  // Stones fall out from 0.83 g (damaged, with dislodged stones: class
  // "stones"), the structure collapses from 1.37 g: two curves, each to the
  // resolution, and the stones' class is a transition of its own.
  auto response = [](double a) {
    PointResult r;
    r.status = a < 0.5 - 1e-9 ? "intact" : (a < 1.37 - 1e-9 ? "damaged" : "collapsed");
    r.dislodged = a < 0.83 - 1e-9 ? 0 : 3;
    if (r.status == "collapsed") r.collapse_mode = "II";
    return r;
  };
  const SearchReport rep =
      boundary_search(grid_points({}), parse_search_axis("g.a=0.2:3.0:15", 0.01), [&](const std::vector<SweepPoint>& b) {
        std::vector<PointResult> out;
        for (const auto& p : b) out.push_back(response(p.values[0].second));
        return out;
      });
  const ColumnResult& c = rep.columns[0];
  EXPECT_NEAR(c.damage_threshold, 0.5, 1e-12);
  EXPECT_NEAR(c.stones_threshold, 0.83, 1e-12);
  EXPECT_NEAR(c.collapse_threshold, 1.37, 1e-12);
  ASSERT_EQ(c.transitions.size(), 3u) << transitions_text(c.transitions);
  EXPECT_EQ(c.transitions[1].from, "damaged");
  EXPECT_EQ(c.transitions[1].to, "stones");
  EXPECT_EQ(c.transitions[2].from, "stones");
  EXPECT_EQ(c.transitions[2].to, "II");
}

TEST(BoundarySearch, RejectsASearchFinerThanItsResolution) {
  EXPECT_THROW((void)parse_search_axis("g.a=0.2:0.3:15", 0.01), std::invalid_argument);
  EXPECT_THROW((void)parse_search_axis("g.a=0.2,0.3", 0.01), std::invalid_argument);
  EXPECT_THROW((void)parse_search_axis("g.a=0.2:0.3:2", 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace polydem
