// `polydem ida` end to end through the built binary, on the spire's solid tip
// alone (examples/spire/tip_pulse.toml, runs of about 0.1 s) under a suite of
// one-sine pulses written as two-column records: the IDA's collapse scale is
// the sweep's boundary for the same deck and record, each run's state is
// that of a plain `polydem run` at its scale, one and two workers give the
// same tables bit for bit, a resumed analysis runs only what is missing,
// multiple stripes, `polydem analytic fragility` reads the tables as they
// are, and bad input is refused with nothing written.
#include "io/json.hpp"

#include "tests/apps/binary.hpp"
#include "tests/test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace polydem {
namespace {

namespace fs = std::filesystem;
using test::column;
using test::exit_code;
using test::read_text;
using test::run_binary;
using test::start_binary;
using test::write_text;

const std::string kTipDeck = std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/tip_pulse.toml";

// A one-sine pulse of period T and peak exactly 1 g, sampled every 0.01 s.
std::string pulse_record(double period) {
  std::string out = "time_s,acceleration_g\n";
  const int n = static_cast<int>(std::lround(period / 0.01));
  for (int i = 0; i <= n; ++i) {
    char line[64];
    const double a = i == n / 4 ? 1.0 : std::sin(2 * M_PI * i * 0.01 / period);
    std::snprintf(line, sizeof line, "%.2f,%.17g\n", i * 0.01, a);
    out += line;
  }
  return out;
}

class IdaCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polydem_ida_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write_text((dir_ / "pulse10.csv").string(), pulse_record(1.0));
    write_text((dir_ / "pulse07.csv").string(), pulse_record(0.7));
    write_text((dir_ / "one.toml").string(), "[[record]]\nfile = \"pulse10.csv\"\n");
    write_text((dir_ / "two.toml").string(),
               "[suite]\nname = \"two pulses\"\n[[record]]\nfile = \"pulse10.csv\"\n"
               "[[record]]\nfile = \"pulse07.csv\"\nscale = 0.8\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> ida(const std::string& suite, const fs::path& out, const std::string& jobs,
                               std::vector<std::string> extra = {}) const {
    std::vector<std::string> a{"ida", (dir_ / suite).string(), kTipDeck, "--jobs", jobs, "--threads", "1",
                               "--set", "simulation.end_time=2.5", "--out", out.string()};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  fs::path dir_;
};

TEST_F(IdaCommand, CollapseScaleIsTheSweepsBoundaryAndEachRunIsAPlainRun) {
  const fs::path out = dir_ / "ida";
  ASSERT_EQ(run_binary(ida("one.toml", out, "2", {"--tolerance", "0.02", "--max-runs", "10"}), dir_ / "ida.txt"), 0)
      << read_text(dir_ / "ida.txt");
  const std::string capacities = read_text(out / "capacities.csv");
  const double collapse = std::stod(column(capacities, "collapse_im")[0]);
  const double below = std::stod(column(capacities, "below_collapse_im")[0]);
  EXPECT_LE(collapse - below, 0.02) << capacities;
  EXPECT_EQ(column(capacities, "record_im")[0], "1");  // the pulse's PGA: IM = scale
  EXPECT_NE(read_text(dir_ / "ida.txt").find("pulse10 im=0.05 (scale 0.05): intact"), std::string::npos)
      << read_text(dir_ / "ida.txt");

  // The sweep's boundary search along the record's scale (issue 33 item 7).
  const fs::path sweep = dir_ / "sweep";
  ASSERT_EQ(run_binary({"sweep", kTipDeck, "--jobs", "2", "--threads", "1", "--quiet", "--set",
                        "simulation.end_time=2.5", "--set", "ground_motion.kind=record", "--set",
                        "ground_motion.record=" + (dir_ / "pulse10.csv").string(), "--search",
                        "ground_motion.scale=0.2:1.0:5", "--resolution", "0.01", "--out", sweep.string()},
                       dir_ / "sweep.txt"),
            0)
      << read_text(dir_ / "sweep.txt");
  const double boundary = std::stod(column(read_text(sweep / "boundaries.csv"), "collapse_ground_motion.scale")[0]);
  EXPECT_LE(std::abs(collapse - boundary), 0.02 + 0.01) << collapse << " against " << boundary;

  // The runs on either side of the collapse, as plain runs of the deck.
  const std::string table = read_text(out / "ida.csv");
  const auto ims = column(table, "im"), states = column(table, "state"), peaks = column(table, "peak_tip_displacement_m");
  int checked = 0;
  for (std::size_t i = 0; i < ims.size(); ++i) {
    if (std::stod(ims[i]) != collapse && std::stod(ims[i]) != below) continue;
    const fs::path run = dir_ / ("run" + std::to_string(i));
    ASSERT_EQ(run_binary({"run", kTipDeck, "--quiet", "--threads", "1", "--set", "simulation.end_time=2.5", "--set",
                          "ground_motion.kind=record", "--set", "ground_motion.record=" + (dir_ / "pulse10.csv").string(),
                          "--set", "ground_motion.scale=" + ims[i], "--out", run.string()},
                         dir_ / "run.txt"),
              0)
        << read_text(dir_ / "run.txt");
    const Json s = Json::parse(read_text(run / "summary.json"));
    const std::string status = s.find("status")->as_string();
    EXPECT_EQ(states[i], status) << ims[i];  // intact, damaged or collapsed here (no stone lost short of collapse)
    EXPECT_EQ(std::stod(peaks[i]), s.find("assessment")->find("monitor_peak_displacement_m")->as_number());
    ++checked;
  }
  EXPECT_EQ(checked, 2) << table;
}

TEST_F(IdaCommand, OneAndTwoWorkersSameTablesResumeAndStripes) {
  const fs::path one = dir_ / "one", two = dir_ / "two";
  const std::vector<std::string> settings{"--tolerance", "0.05", "--max-runs", "6"};
  ASSERT_EQ(run_binary(ida("two.toml", one, "1", settings), dir_ / "one.txt"), 0) << read_text(dir_ / "one.txt");
  ASSERT_EQ(run_binary(ida("two.toml", two, "2", settings), dir_ / "two.txt"), 0) << read_text(dir_ / "two.txt");
  const std::string table = read_text(one / "ida.csv"), capacities = read_text(one / "capacities.csv");
  EXPECT_EQ(read_text(two / "ida.csv"), table);
  EXPECT_EQ(read_text(two / "capacities.csv"), capacities);
  EXPECT_EQ(column(capacities, "record"), (std::vector<std::string>{"pulse10", "pulse07"}));
  EXPECT_EQ(column(capacities, "record_im")[1], "0.8");  // the suite's scale
  EXPECT_EQ(column(table, "record").size(), 12u) << table;

  // Again without --resume: refused; one run's result deleted: --resume runs it alone.
  ASSERT_EQ(run_binary(ida("two.toml", one, "2", settings), dir_ / "again.txt"), 2);
  EXPECT_NE(read_text(dir_ / "again.txt").find("--resume"), std::string::npos);
  fs::remove(one / "points" / column(table, "point")[4] / "summary.json");
  auto resume = ida("two.toml", one, "2", settings);
  resume.push_back("--resume");
  ASSERT_EQ(run_binary(resume, dir_ / "resume.txt"), 0) << read_text(dir_ / "resume.txt");
  EXPECT_EQ(read_text(one / "ida.csv"), table);
  const Json j = Json::parse(read_text(one / "ida.json"));
  EXPECT_EQ(j.find("ran")->as_integer(), 1);
  EXPECT_EQ(j.find("finished_before")->as_integer(), 11);

  // Multiple stripes: every record at each IM.
  const fs::path stripes = dir_ / "stripes";
  ASSERT_EQ(run_binary(ida("two.toml", stripes, "2", {"--stripes", "0.5,0.9"}), dir_ / "stripes.txt"), 0)
      << read_text(dir_ / "stripes.txt");
  const std::string st = read_text(stripes / "ida.csv");
  EXPECT_EQ(column(st, "im"), (std::vector<std::string>{"0.5", "0.9", "0.5", "0.9"})) << st;
  EXPECT_EQ(column(st, "scale")[3], "1.125");  // 0.9 / 0.8

  // The fragility fit reads both tables as they are.
  EXPECT_EQ(run_binary({"analytic", "fragility", (one / "ida.csv").string(), "--method", "ida", "--bootstrap", "0",
                        "--no-plot", "--out", (dir_ / "fit_ida").string()},
                       dir_ / "fit.txt"),
            0)
      << read_text(dir_ / "fit.txt");
  EXPECT_EQ(run_binary({"analytic", "fragility", (stripes / "ida.csv").string(), "--method", "stripes", "--bootstrap",
                        "0", "--no-plot", "--out", (dir_ / "fit_stripes").string()},
                       dir_ / "fit.txt"),
            0)
      << read_text(dir_ / "fit.txt");
}

TEST_F(IdaCommand, SaIsTheSpectrumsOrdinateAndScalesMultiplyIt) {
  const fs::path out = dir_ / "sa", spectrum = dir_ / "spectrum";
  ASSERT_EQ(run_binary(ida("two.toml", out, "2", {"--im", "sa", "--period", "0.5", "--scales", "1,2"}),
                       dir_ / "sa.txt"),
            0)
      << read_text(dir_ / "sa.txt");
  ASSERT_EQ(run_binary({"analytic", "spectrum", (dir_ / "pulse07.csv").string(), "--periods", "0.5", "--no-plot",
                        "--out", spectrum.string()},
                       dir_ / "spectrum.txt"),
            0)
      << read_text(dir_ / "spectrum.txt");
  const double psa = std::stod(column(read_text(spectrum / "spectra.csv"), "pulse07.psa_g")[0]);
  const std::string capacities = read_text(out / "capacities.csv");
  const double record_im = std::stod(column(capacities, "record_im")[1]);
  EXPECT_NEAR(record_im, 0.8 * psa, 1e-8 * psa) << capacities;  // the suite's scale 0.8
  const auto ims = column(read_text(out / "ida.csv"), "im");
  ASSERT_EQ(ims.size(), 4u);
  EXPECT_EQ(std::stod(ims[3]), 2 * record_im);
  const Json j = Json::parse(read_text(out / "ida.json"));
  EXPECT_EQ(j.find("im")->find("name")->as_string(), "sa(0.5 s, 5 %)");
  EXPECT_EQ(j.find("analysis")->as_string(), "scales");
}

TEST_F(IdaCommand, BadInputIsRefusedAndNothingIsWritten) {
  write_text((dir_ / "missing.toml").string(), "[[record]]\nfile = \"pulse10.csv\"\n\n[[record]]\nfile = \"nope.csv\"\n");
  write_text((dir_ / "negative.toml").string(), "[[record]]\nfile = \"pulse10.csv\"\nscale = -1\n");
  write_text((dir_ / "vertical.toml").string(), "[[record]]\nfile = \"pulse10.csv\"\ndirection = [0, 0, 1]\n");
  const std::vector<std::tuple<std::string, std::vector<std::string>, std::string>> cases{
      {"missing.toml", {}, "missing.toml:5: key 'record[2].file': file not found"},
      {"negative.toml", {}, "negative.toml:3: key 'record[1].scale': must be > 0"},
      {"vertical.toml", {}, "vertical.toml:1: record pulse10: no horizontal component"},
      {"one.toml", {"--im", "sa", "--period", "0"}, "--period must be > 0"},
      {"one.toml", {"--im", "sa"}, "--im sa needs --period"},
      {"one.toml", {"--im", "pgv"}, "--im must be pga or sa"},
      {"one.toml", {"--scales", "1,-2"}, "--scales must be > 0"},
      {"one.toml", {"--stripes", "0.5", "--scales", "1"}, "not both"},
      {"one.toml", {"--tolerance", "0"}, "--tolerance must be > 0"},
      {"one.toml", {"--max-runs", "0"}, "--max-runs"},
      {"one.toml", {"--set", "joint.friction_angle=-3"}, "key 'joint.friction_angle'"},
      {"none.toml", {}, "none.toml: cannot open"},
  };
  for (const auto& [suite, extra, message] : cases) {
    const fs::path out = dir_ / "bad";
    EXPECT_EQ(run_binary(ida(suite, out, "1", extra), dir_ / "log.txt"), 2) << message;
    const std::string log = read_text(dir_ / "log.txt");
    EXPECT_NE(log.find(message), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(out)) << log;
  }
}

#ifdef POLYDEM_MPIEXEC
TEST_F(IdaCommand, UnderMpirunTheRanksShareTheRuns) {
  const fs::path local = dir_ / "local", mpi = dir_ / "mpi";
  const std::vector<std::string> settings{"--tolerance", "0.05", "--max-runs", "5"};
  ASSERT_EQ(run_binary(ida("two.toml", local, "2", settings), dir_ / "local.txt"), 0) << read_text(dir_ / "local.txt");
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const char* asan = std::getenv("ASAN_OPTIONS");  // as the sweep's MPI test: no leak check in the ranks
  setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + (asan && *asan ? ":" : "") + "detect_leaks=0").c_str(), 1);
  std::vector<std::string> a{"-np", "2", "--oversubscribe", POLYDEM_BINARY};
  const auto run = ida("two.toml", mpi, "2", settings);
  a.insert(a.end(), run.begin(), run.end());
  ASSERT_EQ(exit_code(start_binary(a, dir_ / "mpi.txt", POLYDEM_MPIEXEC)), 0) << read_text(dir_ / "mpi.txt");
  EXPECT_EQ(read_text(mpi / "ida.csv"), read_text(local / "ida.csv"));
  EXPECT_EQ(Json::parse(read_text(mpi / "ida.json")).find("runner")->as_string(), "2 MPI ranks of 1 thread");
}
#endif

}  // namespace
}  // namespace polydem
