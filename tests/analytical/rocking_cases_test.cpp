// The rocking cases as the command line and Python give them
// (analytical/rocking_cases.hpp) and the cracked spire's curve.
#include "analytical/rocking_cases.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pa = polydem::analytical;

TEST(RockingCases, EachShapeIsItsModel) {
  const double g = 9.81;
  pa::BodySpec s;
  s.shape = pa::BodyShape::block;
  EXPECT_EQ(pa::rocking_body(s, g).I0, pa::rectangular_block(s.b, s.h, 1.0, g).I0);
  s.shape = pa::BodyShape::shell;
  EXPECT_EQ(pa::rocking_body(s, g).p, pa::conical_shell(s.r_b, s.H, 1.0, g).p);
  s.shape = pa::BodyShape::cone;
  EXPECT_EQ(pa::rocking_body(s, g).p, pa::solid_cone(s.r_b, s.H, 1.0, g).p);
  s.shape = pa::BodyShape::cracked;  // the paper's spire; H_bar: the tip alone unless given
  const pa::SpireGeometry spire;
  EXPECT_EQ(pa::rocking_body(s, g).p, pa::cracked_spire_body(spire, spire.tip_height, g).p);
  s.H_bar = 5.0;
  EXPECT_EQ(pa::rocking_body(s, g).p, pa::cracked_spire_body(spire, 5.0, g).p);
  s.thickness = 0.3;
  EXPECT_NE(pa::rocking_body(s, g).p, pa::cracked_spire_body(spire, 5.0, g).p);
}

TEST(RockingCases, LoadsAreInG) {
  const double g = 9.81;
  pa::LoadSpec l;
  l.kind = pa::LoadKind::constant;
  l.a = 0.3;
  EXPECT_EQ(pa::ground_motion(l, g).acceleration(1.0), 0.3 * g);
  l.kind = pa::LoadKind::pulse;
  EXPECT_DOUBLE_EQ(pa::ground_motion(l, g).acceleration(0.25 * l.T_p), l.a_p * g);
  l.kind = pa::LoadKind::record;
  l.record_dt = 0.1;
  l.record = {0.0, 0.5, 0.0};
  EXPECT_EQ(pa::ground_motion(l, g).acceleration(0.1), 0.5 * g);
}

// One sample per interval, the first and the last always.
TEST(RockingCases, SamplesEveryKeepsTheEnds) {
  std::vector<pa::RockingSample> h;
  for (int i = 0; i <= 10; ++i) h.push_back({0.03 * i, 0.0, 0.0, 0.0});
  const auto kept = pa::samples_every(h, 0.1);
  std::vector<double> t;
  for (const auto& s : kept) t.push_back(s.t);
  EXPECT_EQ(t, (std::vector<double>{h[0].t, h[4].t, h[8].t, h[10].t}));
  EXPECT_EQ(pa::samples_every(h, 0.0).size(), h.size());
}

TEST(RockingCases, ResponseRecordsTheHistory) {
  pa::RockingCase c;
  c.body.shape = pa::BodyShape::block;
  c.load.kind = pa::LoadKind::constant;
  c.load.a = 0.25;  // above tan(alpha) = b/h = 0.2: uplift at once, no impact
  c.options.t_end = 2.0;
  const auto r = pa::rocking_response(c);
  EXPECT_FALSE(r.result.history.empty());
  EXPECT_EQ(r.result.t_uplift, 0.0);
  EXPECT_EQ(r.result.mode, pa::CollapseMode::mode_2);
}

TEST(RockingCases, CollapseDiagramSpacesThePeriodsEvenly) {
  pa::CollapseDiagramCase c;
  c.body.shape = pa::BodyShape::block;
  c.T_p_min = 0.5;
  c.T_p_max = 1.5;
  c.T_p_count = 3;
  c.scan.coarse_points = 10;
  const auto d = pa::pulse_collapse_diagram(c);
  ASSERT_EQ(d.columns.size(), 3u);
  EXPECT_EQ(d.columns[1].T_p, 1.0);
  EXPECT_EQ(d.body.p, pa::rectangular_block(c.body.b, c.body.h, 1.0, c.scan.g).p);
  c.T_p_count = 1;
  EXPECT_EQ(pa::pulse_collapse_diagram(c).columns.at(0).T_p, 0.5);
}

TEST(CrackedSpire, CurveRunsFromTheTipToTheBase) {
  const pa::SpireGeometry s;
  const auto c = pa::cracked_spire_curve(s, 3, 9.81);
  ASSERT_EQ(c.points.size(), 3u);
  EXPECT_EQ(c.points.front().H_bar, s.tip_height);
  EXPECT_EQ(c.points.back().H_bar, s.H);
  EXPECT_DOUBLE_EQ(c.points[1].H_bar, 0.5 * (s.tip_height + s.H));
  EXPECT_EQ(c.points[1].body.p, pa::cracked_spire_body(s, c.points[1].H_bar, 9.81).p);
  EXPECT_EQ(c.p_max.H_bar, pa::cracked_spire_p_max(s, 9.81).H_bar);
  EXPECT_THROW(pa::cracked_spire_curve(s, 1, 9.81), std::invalid_argument);
}
