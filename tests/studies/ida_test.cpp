// Incremental dynamic analysis without running a deck: hunt-and-fill on
// made-up records whose collapse intensity is known, the stripes, the
// damage-state mapping, a record's intensity measure (El Centro from
// ../shared/data, and two components) and its ground motion as the deck
// reads it.
#include "studies/ida.hpp"

#include "core/units.hpp"
#include "io/deck.hpp"
#include "io/fragility_tables.hpp"
#include "io/ida_tables.hpp"
#include "io/record_suite.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace polydem {
namespace {

SuiteRecord one_component(const std::string& name, double scale = 1.0) {
  SuiteRecord r;
  r.name = name;
  SuiteComponent c;
  c.record_path = "/dev/null/" + name + ".csv";
  c.scale = scale;
  c.time = {0.0, 0.1, 0.2, 0.3};
  c.acceleration = {0.0, 2.0, -4.0, 0.0};
  r.components.push_back(c);
  return r;
}

IdaReport search(const std::vector<double>& capacity, const HuntAndFill& h, int* batches = nullptr,
                 const IdaProgress& after_round = {}) {
  std::vector<std::string> names;
  std::vector<double> ims;
  for (std::size_t r = 0; r < capacity.size(); ++r) {
    names.push_back("rec" + std::to_string(r));
    ims.push_back(0.5 + 0.25 * static_cast<double>(r));
  }
  std::map<std::string, int> seen;
  const IdaPointOf point_of = [&](std::size_t r, double im, double factor) {
    EXPECT_DOUBLE_EQ(factor * ims[r], im);
    SweepPoint p;
    p.fixed.push_back(names[r]);
    p.values.emplace_back("im", im);
    return p;
  };
  const BatchRunner run = [&](const std::vector<SweepPoint>& batch) {
    if (batches) ++*batches;
    std::vector<PointResult> out;
    for (const SweepPoint& p : batch) {
      EXPECT_EQ(++seen[p.fixed[0] + value_text(p.values[0].second)], 1) << "run twice";
      const std::size_t r = static_cast<std::size_t>(std::stoi(p.fixed[0].substr(3)));
      const double im = p.values[0].second;
      PointResult res;
      res.status = im >= capacity[r] ? "collapsed" : im >= capacity[r] / 2 ? "damaged" : "intact";
      out.push_back(res);
    }
    return out;
  };
  return hunt_and_fill(names, ims, h, point_of, run, after_round);
}

TEST(HuntAndFill, BracketsEachRecordsCollapseToTheTolerance) {
  HuntAndFill h;
  h.tolerance = 0.01;
  h.max_runs = 20;  // record 1 needs 10 to hunt to 2.3 and 6 to bisect [1.85, 2.3]
  int batches = 0;
  const std::vector<double> capacity{0.537, 1.91, 0.031};
  const IdaReport rep = search(capacity, h, &batches);
  ASSERT_EQ(rep.records.size(), 3u);
  EXPECT_EQ(rep.rounds, batches);
  for (std::size_t r = 0; r < capacity.size(); ++r) {
    const IdaRecord& rec = rep.records[r];
    SCOPED_TRACE(rec.name);
    ASSERT_FALSE(std::isnan(rec.collapse_im));
    EXPECT_GE(rec.collapse_im, capacity[r]);
    EXPECT_LT(rec.below_collapse_im, capacity[r]);
    EXPECT_LE(rec.collapse_im - rec.below_collapse_im, h.tolerance);
    EXPECT_LE(static_cast<long>(rec.runs.size()), h.max_runs);
    EXPECT_GE(rec.damage_im, capacity[r] / 2);
    for (std::size_t i = 1; i < rec.runs.size(); ++i) EXPECT_LT(rec.runs[i - 1].im, rec.runs[i].im);
  }
  // The hunt's IMs as documented: 0.05, 0.10, 0.20, 0.35, 0.55 (first
  // collapse of record 0), then the bisection of [0.35, 0.55].
  const auto& runs = rep.records[0].runs;
  for (double x : {0.05, 0.1, 0.2, 0.35, 0.55, 0.45, 0.5, 0.525, 0.5375, 0.53125})
    EXPECT_TRUE(std::any_of(runs.begin(), runs.end(), [&](const IdaRun& r) { return r.im == x; })) << x;
  // Record 2 collapses at the first run: bisected from 0.
  EXPECT_LE(rep.records[2].collapse_im - rep.records[2].below_collapse_im, h.tolerance);
}

TEST(HuntAndFill, FillsTheWidestGapsBelowCollapseWithTheRunsLeft) {
  HuntAndFill h;
  h.tolerance = 0.02;
  h.max_runs = 16;
  const IdaReport rep = search({0.537}, h);
  const IdaRecord& rec = rep.records[0];
  EXPECT_EQ(static_cast<long>(rec.runs.size()), h.max_runs);
  // Without the fill the widest gap below collapse was 0.2-0.35; filled,
  // none left wider than 0.1.
  double widest = 0, from = 0;
  for (const IdaRun& r : rec.runs) {
    if (r.im > rec.collapse_im) break;
    widest = std::max(widest, r.im - from);
    from = r.im;
  }
  EXPECT_LE(widest, 0.1);
}

TEST(HuntAndFill, ARecordThatNeverCollapsesIsCensoredAtItsLargestRun) {
  HuntAndFill h;
  h.max_runs = 5;
  const IdaReport rep = search({100.0}, h);
  const IdaRecord& rec = rep.records[0];
  EXPECT_TRUE(std::isnan(rec.collapse_im));
  EXPECT_EQ(rec.runs.size(), 5u);
  EXPECT_DOUBLE_EQ(rec.below_collapse_im, 0.55);  // 0.05, 0.1, 0.2, 0.35, 0.55
}

TEST(HuntAndFill, ReportsTheRunsSoFarAfterEachRound) {
  std::vector<long> runs;
  IdaReport last;
  const IdaReport rep = search({0.537, 0.2}, HuntAndFill{}, nullptr, [&](const IdaReport& so_far) {
    runs.push_back(so_far.runs);
    last = so_far;
  });
  ASSERT_EQ(static_cast<int>(runs.size()), rep.rounds);
  EXPECT_EQ(runs.front(), 2);  // both records' first run
  EXPECT_EQ(runs.back(), rep.runs);
  ASSERT_EQ(last.records.size(), 2u);
  EXPECT_EQ(last.records[0].runs.size(), rep.records[0].runs.size());
  EXPECT_EQ(last.records[1].collapse_im, rep.records[1].collapse_im);
}

TEST(HuntAndFill, RefusesSettingsThatCannotSearch) {
  for (auto bad : {+[](HuntAndFill& h) { h.first = 0; }, +[](HuntAndFill& h) { h.step = -1; },
                   +[](HuntAndFill& h) { h.tolerance = 0; }, +[](HuntAndFill& h) { h.max_runs = 0; },
                   +[](HuntAndFill& h) { h.growth = -0.1; }}) {
    HuntAndFill h;
    bad(h);
    EXPECT_THROW(search({1.0}, h), std::invalid_argument);
  }
}

TEST(Stripes, EveryRecordAtEveryLevelInOneBatch) {
  int batches = 0;
  const std::vector<std::string> names{"a", "b"};
  const std::vector<double> ims{0.5, 0.25};
  const IdaPointOf point_of = [&](std::size_t r, double im, double factor) {
    SweepPoint p;
    p.values = {{"record", static_cast<double>(r)}, {"im", im}, {"factor", factor}};
    return p;
  };
  const BatchRunner run = [&](const std::vector<SweepPoint>& batch) {
    ++batches;
    EXPECT_EQ(batch.size(), 6u);
    std::vector<PointResult> out(batch.size());
    for (std::size_t i = 0; i < batch.size(); ++i) out[i].status = batch[i].values[1].second > 0.3 ? "collapsed" : "intact";
    return out;
  };
  const IdaReport at_ims = run_stripes(names, ims, {0.1, 0.2, 0.4}, false, point_of, run);
  EXPECT_EQ(batches, 1);
  EXPECT_EQ(at_ims.records[1].runs[2].factor, 0.4 / 0.25);
  EXPECT_EQ(at_ims.records[0].collapse_im, 0.4);
  const IdaReport at_factors = run_stripes(names, ims, {0.1, 0.2, 0.4}, true, point_of, run);
  EXPECT_EQ(at_factors.records[0].runs[2].im, 0.4 * 0.5);
  EXPECT_TRUE(std::isnan(at_factors.records[1].collapse_im));
}

TEST(DamageState, TheWorstStateTheRunReached) {
  PointResult r;
  for (const auto& [status, dislodged, state] :
       std::vector<std::tuple<std::string, int, std::string>>{{"intact", 0, "intact"},
                                                              {"damaged", 0, "damaged"},
                                                              {"damaged", 2, "stones_lost"},
                                                              {"intact", 1, "stones_lost"},
                                                              {"collapsed", 3, "collapsed"},
                                                              {"collapsed", 0, "collapsed"},
                                                              {"undetermined", 0, "undetermined"},
                                                              {"undetermined", 1, "undetermined"},
                                                              {"unstable", 0, "undetermined"},
                                                              {"error", 0, "undetermined"}}) {
    r.status = status;
    r.dislodged = dislodged;
    EXPECT_EQ(damage_state(r), state) << status << " " << dislodged;
  }
  EXPECT_EQ(damage_rank("stones_lost"), 2);
  EXPECT_EQ(damage_rank("undetermined"), -1);
}

TEST(RecordIntensity, PgaAndSaOfOneAndTwoHorizontalComponents) {
  SuiteRecord r = one_component("x", 0.5);
  EXPECT_DOUBLE_EQ(record_intensity(r, {}), 4.0 * 0.5 / kRecordG);
  IntensitySpec sa{IntensityMeasure::sa, 1e-4, 0.05};
  EXPECT_NEAR(record_intensity(r, sa), 2.0 / kRecordG, 0.01 * 2.0 / kRecordG);  // Sa → PGA as T → 0
  // A second horizontal component: the geometric mean; a vertical one is not counted.
  SuiteRecord two = r;
  two.components.push_back(one_component("y", 2.0).components[0]);
  two.components.back().direction = {0, 1, 0};
  SuiteRecord up = two;
  up.components.push_back(one_component("z", 9.0).components[0]);
  up.components.back().direction = {0, 0, 1};
  EXPECT_DOUBLE_EQ(record_intensity(two, {}), std::sqrt((2.0 / kRecordG) * (8.0 / kRecordG)));
  EXPECT_DOUBLE_EQ(record_intensity(up, {}), record_intensity(two, {}));
  SuiteRecord vertical = one_component("z");
  vertical.components[0].direction = {0, 0, 1};
  EXPECT_THROW(record_intensity(vertical, {}), std::invalid_argument);
}

TEST(RecordIntensity, ElCentroPgaFromTheSharedData) {
  const std::string dir = std::string(POLYDEM_SOURCE_DIR) + "/../shared/data";
  if (!std::filesystem::exists(dir + "/elcentro-1940-ns.AT2"))
    GTEST_SKIP() << "shared test data not found: " << dir << " (../shared/data beside the checkout)";
  const RecordSuite s =
      parse_record_suite("[[record]]\nfile = \"elcentro-1940-ns.AT2\"\nscale = 2.0\n", dir + "/suite.toml");
  EXPECT_NEAR(record_intensity(s.records[0], {}), 2 * 0.319, 0.002);
}

TEST(RecordMotion, TheDeckReadsTheRecordInPlaceOfItsOwnMotion) {
  const auto dir = std::filesystem::temp_directory_path() / ("polydem_ida_motion_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"a.csv", "b.csv"}) {
    std::FILE* f = std::fopen((dir / name).c_str(), "w");
    std::fputs("time_s,acceleration_g\n0,0\n0.1,0.5\n0.2,0\n", f);
    std::fclose(f);
  }
  const RecordSuite suite = parse_record_suite(
      "[suite]\nbaseline_order = 1\n[[record]]\nname = \"two\"\n[[record.component]]\nfile = \"a.csv\"\nscale = 2\n"
      "[[record.component]]\nfile = \"b.csv\"\ndirection = [0, 1, 0]\nscale = 0.5\n",
      (dir / "suite.toml").string());
  const std::string deck =
      "[[block]]\nname = \"base\"\nshape = \"box\"\nsize = [1, 1, 0.1]\ncenter = [0, 0, -0.05]\nmotion = \"fixed\"\n"
      "[[block]]\nname = \"b\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.4]\ncenter = [0, 0, 0.2]\n"
      "[ground_motion]\nkind = \"sine_pulse\"\nacceleration_g = 0.3\nperiod = 0.5\ntower_frequency = 6.8\n"
      "[[ground_motion.component]]\nkind = \"constant\"\nacceleration = 1\n";
  GroundMotionSpec base = parse_deck(deck, (dir / "deck.toml").string(), {}).ground_motion;
  const std::string motion = record_motion_override(suite.records[0], suite, base);
  const SweepPoint p = record_point(suite.records[0], motion, 1.5);
  const SceneSpec spec = parse_deck(deck, (dir / "deck.toml").string(), p.overrides());
  const GroundMotionSpec& g = spec.ground_motion;
  EXPECT_EQ(g.kind, GroundMotionKind::record);
  EXPECT_EQ(g.scale, 3.0);
  EXPECT_EQ(g.tower_frequency, 6.8);
  ASSERT_EQ(g.components.size(), 1u);  // the deck's own component replaced
  EXPECT_EQ(g.components[0].kind, GroundMotionKind::record);
  EXPECT_EQ(g.components[0].scale, 0.75);
  EXPECT_EQ(g.components[0].direction, Vec3(0, 1, 0));
  // The suite's baseline correction, as the suite read it.
  EXPECT_EQ(g.record_acceleration, suite.records[0].components[0].acceleration);
  std::filesystem::remove_all(dir);
}

TEST(IdaTables, FragilityReadsTheTableAndLeavesUndeterminedRunsOut) {
  IdaReport rep;
  IdaRecord rec;
  rec.name = "r,1";  // a comma in a name does not break the CSV
  rec.record_im = 0.3;
  for (const auto& [im, status, dislodged] :
       std::vector<std::tuple<double, std::string, int>>{{0.1, "intact", 0}, {0.2, "damaged", 1}, {0.3, "unstable", 0},
                                                         {0.4, "collapsed", 2}}) {
    IdaRun run;
    run.im = im;
    run.factor = im / 0.3;
    run.result.status = status;
    run.result.dislodged = dislodged;
    run.state = damage_state(run.result);
    rec.runs.push_back(run);
  }
  rep.records.push_back(rec);
  const FragilityInput in = parse_fragility_runs(ida_csv(rep), "ida.csv");
  EXPECT_TRUE(in.has_records);
  EXPECT_EQ(in.undetermined, 1);
  ASSERT_EQ(in.runs.size(), 3u);
  EXPECT_EQ(in.runs[1].record, "r_1");
  EXPECT_EQ(in.runs[1].state, analytical::DamageState::stones_lost);
}

}  // namespace
}  // namespace polydem
