// `polydem ensemble` and `polydem sweep --replicas` end to end through the
// built binary, on the spire's solid tip alone (examples/spire/tip_pulse.toml,
// one block, runs of about 0.05 s): the same seed gives the same tables bit
// for bit on one and two workers, a resumed ensemble with one replica's
// result deleted runs that one alone and gives the same summary, bad input is
// refused with nothing written, each point of a sweep as an ensemble, and
// the same ensemble under mpirun.
#include "io/json.hpp"

#include "tests/apps/binary.hpp"
#include "tests/test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace polydem {
namespace {

namespace fs = std::filesystem;
using test::column;
using test::exit_code;
using test::read_text;
using test::run_binary;
using test::start_binary;

const std::string kTipDeck = std::string(POLYDEM_SOURCE_DIR) + "/examples/spire/tip_pulse.toml";

class EnsembleCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polydem_ensemble_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Six replicas at 0.6 g (just past uplift: the tip rocks, and still rocks
  // when the runs end at 1.2 s: undetermined).
  std::vector<std::string> args(const fs::path& out, const std::string& jobs) const {
    return {"ensemble", kTipDeck, "--replicas", "6", "--seed", "5", "--jobs", jobs, "--threads", "1",
            "--set",    "simulation.end_time=1.2", "--out", out.string()};
  }

  fs::path dir_;
};

TEST_F(EnsembleCommand, SameSeedSameTablesOnOneAndTwoWorkersAndAResumeThatRunsOnlyWhatIsMissing) {
  const fs::path one = dir_ / "one", two = dir_ / "two";
  ASSERT_EQ(run_binary(args(one, "1"), dir_ / "one.txt"), 0) << read_text(dir_ / "one.txt");
  ASSERT_EQ(run_binary(args(two, "2"), dir_ / "two.txt"), 0) << read_text(dir_ / "two.txt");
  const std::string replicas = read_text(one / "replicas.csv"), summary = read_text(one / "ensemble.csv");
  EXPECT_EQ(read_text(two / "replicas.csv"), replicas);
  EXPECT_EQ(read_text(two / "ensemble.csv"), summary);
  // Replica 0 is the deck as written; the others drew within their bounds.
  const auto friction = column(replicas, "friction_angle_shift_deg");
  const auto kn = column(replicas, "normal_stiffness_factor");
  const auto shift = column(replicas, "time_shift_s");
  ASSERT_EQ(friction.size(), 6u) << replicas;
  EXPECT_EQ(friction[0], "0");
  EXPECT_EQ(kn[0], "1");
  for (std::size_t k = 1; k < 6; ++k) {
    EXPECT_LE(std::abs(std::stod(friction[k])), 0.5);
    EXPECT_LE(std::abs(std::stod(kn[k]) - 1), 0.05);
    EXPECT_GE(std::stod(shift[k]), 0.0);
    EXPECT_LT(std::stod(shift[k]), 0.005);  // half the 0.01 s sample step of a pulse
  }
  for (const auto& status : column(replicas, "status")) EXPECT_EQ(status, "undetermined") << replicas;
  EXPECT_EQ(column(summary, "n_undetermined"), std::vector<std::string>{"6"}) << summary;
  // The peak of the tip: the summary's median is the middle of the replicas' peaks.
  std::vector<double> peaks;
  for (const auto& p : column(replicas, "peak_tip_displacement_m")) peaks.push_back(std::stod(p));
  std::sort(peaks.begin(), peaks.end());
  EXPECT_NEAR(std::stod(column(summary, "peak_tip_displacement_m_median")[0]), 0.5 * (peaks[2] + peaks[3]), 1e-15);
  EXPECT_NE(read_text(dir_ / "one.txt").find("replica 5: undetermined"), std::string::npos) << read_text(dir_ / "one.txt");

  // The same command on the same directory without --resume: refused.
  ASSERT_EQ(run_binary(args(one, "2"), dir_ / "again.txt"), 2);
  EXPECT_NE(read_text(dir_ / "again.txt").find("--resume"), std::string::npos) << read_text(dir_ / "again.txt");

  // One replica's result deleted: --resume runs that one alone.
  const std::string lost = column(replicas, "point")[3];
  fs::remove(one / "points" / lost / "summary.json");
  auto resume = args(one, "2");
  resume.push_back("--resume");
  ASSERT_EQ(run_binary(resume, dir_ / "resume.txt"), 0) << read_text(dir_ / "resume.txt");
  EXPECT_EQ(read_text(one / "replicas.csv"), replicas);
  EXPECT_EQ(read_text(one / "ensemble.csv"), summary);
  const Json j = Json::parse(read_text(one / "ensemble.json"));
  EXPECT_EQ(j.find("ran")->as_integer(), 1);
  EXPECT_EQ(j.find("finished_before")->as_integer(), 5);
  EXPECT_EQ(j.find("outcome")->find("status_counts")->find("undetermined")->as_integer(), 6);

  // Another seed: other draws.
  auto other = args(dir_ / "other", "2");
  other[5] = "6";
  ASSERT_EQ(run_binary(other, dir_ / "other.txt"), 0) << read_text(dir_ / "other.txt");
  EXPECT_NE(column(read_text(dir_ / "other" / "replicas.csv"), "friction_angle_shift_deg")[1], friction[1]);
}

TEST_F(EnsembleCommand, BadInputIsRefusedAndNothingIsWritten) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--replicas", "0"}, "--replicas"},
      {{"--replicas", "2.5"}, "--replicas"},
      {{"--replicas", "3", "--seed", "-1"}, "--seed"},
      {{"--replicas", "3", "--set", "ensemble.stiffness=0.7"}, "tip_pulse.toml: --set key 'ensemble.stiffness'"},
      {{"--replicas", "3", "--set", "ensemble.friction_angle=-0.5"}, "key 'ensemble.friction_angle'"},
      {{}, "--replicas"},
  };
  for (const auto& [extra, message] : cases) {
    const fs::path out = dir_ / "bad";
    std::vector<std::string> a{"ensemble", kTipDeck, "--out", out.string()};
    a.insert(a.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_binary(a, dir_ / "log.txt"), 2) << message;
    const std::string log = read_text(dir_ / "log.txt");
    EXPECT_NE(log.find(message), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(out)) << log;
  }
  // A sweep's points as ensembles do not go with a boundary search.
  EXPECT_EQ(run_binary({"sweep", kTipDeck, "--out", (dir_ / "s").string(), "--replicas", "3", "--search",
                        "ground_motion.acceleration_g=0.3:2.1:7", "--resolution", "0.02"},
                       dir_ / "log.txt"),
            2);
  EXPECT_NE(read_text(dir_ / "log.txt").find("--search"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "s"));
}

TEST_F(EnsembleCommand, ASweepWithReplicasSummarisesEachPoint) {
  const fs::path out = dir_ / "sweep";
  ASSERT_EQ(run_binary({"sweep", kTipDeck, "--out", out.string(), "--jobs", "2", "--threads", "1", "--quiet",
                        "--vary", "ground_motion.acceleration_g=0.4,0.6", "--replicas", "3", "--seed", "5", "--set",
                        "simulation.end_time=1.2"},
                       dir_ / "log.txt"),
            0)
      << read_text(dir_ / "log.txt");
  const std::string csv = read_text(out / "ensembles.csv");
  EXPECT_EQ(column(csv, "ground_motion.acceleration_g"), (std::vector<std::string>{"0.4", "0.6"})) << csv;
  EXPECT_EQ(column(csv, "replicas"), (std::vector<std::string>{"3", "3"})) << csv;
  // 0.4 g is below uplift (tan α = 0.506 g): intact; 0.6 g rocks the tip,
  // which still rocks at 1.2 s: undetermined.
  EXPECT_EQ(column(csv, "n_intact"), (std::vector<std::string>{"3", "0"})) << csv;
  EXPECT_EQ(column(csv, "n_undetermined"), (std::vector<std::string>{"0", "3"})) << csv;
  // The 0.6 g point's replicas are those of `polydem ensemble` at 0.6 g.
  const fs::path lone = dir_ / "lone";
  ASSERT_EQ(run_binary({"ensemble", kTipDeck, "--replicas", "3", "--seed", "5", "--jobs", "2", "--threads", "1",
                        "--set", "simulation.end_time=1.2", "--set", "ground_motion.acceleration_g=0.6", "--out",
                        lone.string()},
                       dir_ / "lone.txt"),
            0)
      << read_text(dir_ / "lone.txt");
  EXPECT_EQ(column(csv, "peak_tip_displacement_m_p84")[1],
            column(read_text(lone / "ensemble.csv"), "peak_tip_displacement_m_p84")[0]);
}

// With output.walking: courses.csv, one row per course with the
// distribution of its joints' openings, the same on one and two workers,
// and the same rows in a sweep's courses.csv after the point's values. The
// column of four drums on a fixed plinth (examples/verification/
// column_rocking.toml): four bed levels, no vertical joints.
TEST_F(EnsembleCommand, CoursesOfAWalkingDeck) {
  const std::string deck = std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/column_rocking.toml";
  auto args = [&](const fs::path& out, const std::string& jobs) {
    return std::vector<std::string>{"ensemble", deck, "--replicas", "4", "--seed", "3", "--jobs", jobs, "--threads",
                                    "1", "--quiet", "--set", "output.walking=true", "--out", out.string()};
  };
  ASSERT_EQ(run_binary(args(dir_ / "one", "1"), dir_ / "one.txt"), 0) << read_text(dir_ / "one.txt");
  ASSERT_EQ(run_binary(args(dir_ / "two", "2"), dir_ / "two.txt"), 0) << read_text(dir_ / "two.txt");
  const std::string courses = read_text(dir_ / "one" / "courses.csv");
  EXPECT_EQ(read_text(dir_ / "two" / "courses.csv"), courses);
  EXPECT_EQ(column(courses, "course"), (std::vector<std::string>{"0", "1", "2", "3"})) << courses;
  for (const auto& n : column(courses, "vertical_joints")) EXPECT_EQ(n, "0");
  for (const auto& n : column(courses, "bed_joints")) EXPECT_EQ(n, "1");
  for (const auto& n : column(courses, "residual_bed_largest_m_n")) EXPECT_EQ(n, "4");
  // A drum's bed joint opens while the column rocks: the largest during the
  // run is at least the residual, replica by replica and so in the median.
  const auto peak = column(courses, "max_bed_m_median"), residual = column(courses, "residual_bed_largest_m_median");
  for (std::size_t k = 0; k < peak.size(); ++k) {
    EXPECT_GE(std::stod(peak[k]), std::stod(residual[k]));
    EXPECT_GT(std::stod(peak[k]), 1e-3) << "course " << k;
  }
  // In each replica the structure's largest residual bed opening
  // (ensemble.csv) bounds every course's, so no course's median exceeds its
  // median, nor its p84.
  const double largest_p84 = std::stod(column(read_text(dir_ / "one" / "ensemble.csv"), "residual_bed_opening_m_p84")[0]);
  for (const auto& r : residual) EXPECT_LE(std::stod(r), largest_p84 + 1e-12);

  const fs::path sweep = dir_ / "sweep";
  ASSERT_EQ(run_binary({"sweep", deck, "--out", sweep.string(), "--jobs", "2", "--threads", "1", "--quiet", "--vary",
                        "ground_motion.acceleration_g=0.4", "--replicas", "4", "--seed", "3", "--set",
                        "output.walking=true"},
                       dir_ / "sweep.txt"),
            0)
      << read_text(dir_ / "sweep.txt");
  const std::string by_point = read_text(sweep / "courses.csv");
  EXPECT_EQ(column(by_point, "ground_motion.acceleration_g"), (std::vector<std::string>{"0.4", "0.4", "0.4", "0.4"}));
  EXPECT_EQ(column(by_point, "max_bed_m_p84"), column(courses, "max_bed_m_p84"));
}

TEST_F(EnsembleCommand, BandsAlongAnIntensityAxisFromEachColumnsReplicas) {
  // Two periods, three amplitudes about the tip's uplift (tan α = 0.506 g),
  // four replicas each, run until the tip is at rest. Without a band axis
  // ensembles.csv has no fractions; the same sweep again with one reuses the
  // runs and adds them.
  const fs::path out = dir_ / "plain";
  const std::vector<std::string> common{
      "sweep",  kTipDeck,   "--jobs", "2",        "--threads", "1",       "--quiet",
      "--vary", "ground_motion.period=0.5,1.0",  "--vary",    "ground_motion.acceleration_g=0.4,0.6,0.8",
      "--replicas", "4",    "--seed", "3",        "--set",     "simulation.end_time=6", "--set",
      "simulation.settle_velocity=0.01",          "--set",     "simulation.settle_time=0.5"};
  std::vector<std::string> a = common;
  a.insert(a.end(), {"--out", (dir_ / "plain").string()});
  ASSERT_EQ(run_binary(a, dir_ / "plain.txt"), 0) << read_text(dir_ / "plain.txt");
  EXPECT_EQ(read_text(dir_ / "plain" / "ensembles.csv").find("p_collapse"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "plain" / "bands.csv"));
  const std::string plain = read_text(dir_ / "plain" / "ensembles.csv");

  a = common;
  a.insert(a.end(), {"--out", out.string(), "--band-axis", "ground_motion.acceleration_g"});
  ASSERT_EQ(run_binary(a, dir_ / "log.txt"), 0) << read_text(dir_ / "log.txt");
  const std::string log = read_text(dir_ / "log.txt");
  EXPECT_NE(log.find("period=0.5"), std::string::npos) << log;  // the table on stdout

  // ensembles.csv: the same rows with the observed fractions added, each
  // the class counts over the replicas with a verdict.
  const std::string ensembles = read_text(out / "ensembles.csv");
  std::istringstream with(ensembles), without(plain);
  for (std::string l1, l2; std::getline(without, l2);) {
    ASSERT_TRUE(std::getline(with, l1));
    EXPECT_EQ(l1.substr(0, l2.size()), l2);
  }
  const auto judged = column(ensembles, "judged"), p_damage = column(ensembles, "p_damage"),
             p_collapse = column(ensembles, "p_collapse"), intact = column(ensembles, "n_intact");
  ASSERT_EQ(judged.size(), 6u) << ensembles;
  for (std::size_t i = 0; i < judged.size(); ++i) {
    ASSERT_NE(judged[i], "0") << ensembles;
    EXPECT_NEAR(std::stod(p_damage[i]), 1.0 - std::stod(intact[i]) / std::stod(judged[i]), 1e-15) << ensembles;
  }
  // 0.4 g is below uplift; at 1 s, 0.8 g overturns the tip (docs/analytical.md).
  EXPECT_EQ(p_damage[0], "0");
  EXPECT_EQ(p_collapse[5], "1");

  // bands.csv: one row per period and outcome, every replica counted once.
  const std::string bands = read_text(out / "bands.csv");
  EXPECT_EQ(bands.substr(0, bands.find('\n')),
            "ground_motion.period,outcome,status,ground_motion.acceleration_g_16,ground_motion.acceleration_g_50,"
            "ground_motion.acceleration_g_84,beta,ground_motion.acceleration_g_below,"
            "ground_motion.acceleration_g_above,ground_motion.acceleration_g_falls_back,runs,reached,undetermined,"
            "failed,largest_gap");
  EXPECT_EQ(column(bands, "ground_motion.period"), (std::vector<std::string>{"0.5", "0.5", "0.5", "1", "1", "1"}));
  EXPECT_EQ(column(bands, "outcome"), (std::vector<std::string>{"damage", "stones_lost", "collapse", "damage",
                                                                 "stones_lost", "collapse"}));
  const auto runs = column(bands, "runs"), undetermined = column(bands, "undetermined"),
             status = column(bands, "status"), below = column(bands, "ground_motion.acceleration_g_below"),
             above = column(bands, "ground_motion.acceleration_g_above");
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(std::stoi(runs[i]) + std::stoi(undetermined[i]), 12) << bands;
  // At 1 s the tip's collapse is certain at 0.8 g and absent at 0.4 g: the
  // 50 % point is bracketed, with or without a fit.
  const double half = std::stod(p_collapse[4]);  // at 0.6 g
  EXPECT_EQ(above[5], half >= 0.5 ? "0.6" : "0.8") << bands;
  EXPECT_EQ(below[5], half >= 0.5 ? "0.4" : "0.6") << bands;
  EXPECT_NE(status[5], "no_runs");
  // Bad input writes nothing.
  for (const auto& [extra, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--band-axis", "ground_motion.acceleration_g"}, "--band-axis goes with --replicas"},
           {{"--replicas", "2", "--band-axis", "ground_motion.damping"}, "not one of the --vary keys"},
           {{"--replicas", "2", "--band-axis", "ensemble.replica"}, "not one of the --vary keys"}}) {
    std::vector<std::string> bad{"sweep", kTipDeck, "--out", (dir_ / "bad").string(), "--vary",
                                 "ground_motion.acceleration_g=0.4,0.6"};
    bad.insert(bad.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_binary(bad, dir_ / "bad.txt"), 2) << message;
    EXPECT_NE(read_text(dir_ / "bad.txt").find(message), std::string::npos) << read_text(dir_ / "bad.txt");
    EXPECT_FALSE(fs::exists(dir_ / "bad"));
  }
  EXPECT_EQ(run_binary({"sweep", kTipDeck, "--out", (dir_ / "bad").string(), "--vary",
                        "ground_motion.acceleration_g=0,0.6", "--replicas", "2", "--band-axis",
                        "ground_motion.acceleration_g"},
                       dir_ / "bad.txt"),
            2);
  EXPECT_NE(read_text(dir_ / "bad.txt").find("must be > 0"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

#ifdef POLYDEM_MPIEXEC
TEST_F(EnsembleCommand, UnderMpirunTheRanksShareTheReplicas) {
  const fs::path local = dir_ / "local", mpi = dir_ / "mpi";
  ASSERT_EQ(run_binary(args(local, "2"), dir_ / "local.txt"), 0) << read_text(dir_ / "local.txt");
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const char* asan = std::getenv("ASAN_OPTIONS");  // as the sweep's MPI test: no leak check in the ranks
  setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + (asan && *asan ? ":" : "") + "detect_leaks=0").c_str(), 1);
  std::vector<std::string> a{"-np", "2", "--oversubscribe", POLYDEM_BINARY};
  const auto ensemble = args(mpi, "2");
  a.insert(a.end(), ensemble.begin(), ensemble.end());
  ASSERT_EQ(exit_code(start_binary(a, dir_ / "mpi.txt", POLYDEM_MPIEXEC)), 0) << read_text(dir_ / "mpi.txt");
  EXPECT_EQ(read_text(mpi / "replicas.csv"), read_text(local / "replicas.csv"));
  EXPECT_EQ(read_text(mpi / "ensemble.csv"), read_text(local / "ensemble.csv"));
  EXPECT_EQ(Json::parse(read_text(mpi / "ensemble.json")).find("runner")->as_string(), "2 MPI ranks of 1 thread");
}
#endif

}  // namespace
}  // namespace polydem
