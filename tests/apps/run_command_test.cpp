// `polydem run` end to end: exit codes, error messages that name the deck's
// file, line and key, nothing written on bad input, overrides, the
// summary's checks, and the verdict it prints last. Most cases call run_command() in-process (stderr is
// captured); --version and one bad deck go through the built binary.
//
// The scene is a 1 m stone cube on a fixed base run for 2 ms (about 25
// steps), so every run takes milliseconds.
#include "apps/run_command.hpp"

#include "tests/test_util.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace polydem {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const char* const kDeck = R"(# A stone cube resting on a fixed base.
[simulation]
end_time = 0.002

[joint]
normal_stiffness = 98e9

[[block]]
name = "base"
shape = "box"
size = [2.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "stone"
shape = "box"
size = [1.0, 1.0, 1.0]
center = [0.0, 0.0, 0.5]
density = 2600.0

[[check]]
kind = "no_drift"
block = "stone"
tolerance = 1e-3
)";

// 1-based line of the first line of `text` that starts with `prefix`.
int line_of(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  return 0;
}

std::string replace_once(std::string text, const std::string& what, const std::string& with) {
  const auto at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  if (at != std::string::npos) text.replace(at, what.size(), with);
  return text;
}

// Number that follows `"key": ` in JSON text (first occurrence from `from`).
double json_number(const std::string& json, const std::string& key, std::size_t from = 0) {
  const std::regex re("\"" + key + "\"\\s*:\\s*([-+0-9.eE]+|null)");
  std::smatch m;
  const std::string tail = json.substr(from);
  if (!std::regex_search(tail, m, re)) return std::nan("");
  return m[1] == "null" ? std::nan("") : std::stod(m[1]);
}

// The run takes whole steps and stops at the step nearest the deck's end
// time: the summary's end time is steps × dt, within dt/2 of the deck's.
void expect_end_time(const std::string& json, double deck_end_time) {
  const double steps = json_number(json, "steps"), dt = json_number(json, "time_step_s");
  const double end = json_number(json, "end_time_s");
  ASSERT_GT(steps, 0) << json;
  EXPECT_NEAR(end, steps * dt, 1e-12 * end) << json;
  EXPECT_LE(std::abs(end - deck_end_time), 0.5 * dt + 1e-15) << json;
}

class RunCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("polydem_apps_test_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    out_ = dir_ / "out";
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Writes the deck and runs it; stderr goes to err_.
  int run(const std::string& deck_text, std::vector<std::string> overrides = {}) {
    deck_ = dir_ / "deck.toml";
    std::ofstream(deck_) << deck_text;
    RunOptions o;
    o.deck_path = deck_.string();
    o.out_dir = out_.string();
    o.quiet = true;
    o.threads = 1;
    o.overrides = std::move(overrides);
    std::ostringstream captured;
    auto* old = std::cerr.rdbuf(captured.rdbuf());
    int code = -1;
    try {
      code = run_command(o);
    } catch (...) {
      std::cerr.rdbuf(old);
      throw;
    }
    std::cerr.rdbuf(old);
    err_ = captured.str();
    return code;
  }

  // Nothing at all in the output directory (it may not exist).
  void expect_nothing_written() {
    if (!fs::exists(out_)) return;
    for (const auto& e : fs::directory_iterator(out_)) ADD_FAILURE() << "left behind: " << e.path();
  }

  // summary.json and results.h5, and no temporary file left beside them.
  void expect_only_results() {
    ASSERT_TRUE(fs::exists(out_ / "summary.json"));
    ASSERT_TRUE(fs::exists(out_ / "results.h5"));
    int files = 0;
    for (const auto& e : fs::directory_iterator(out_)) {
      ++files;
      EXPECT_TRUE(e.path().filename() == "summary.json" || e.path().filename() == "results.h5") << e.path();
    }
    EXPECT_EQ(files, 2);
  }

  fs::path dir_, out_, deck_;
  std::string err_;
};

TEST_F(RunCommandTest, GoodDeckWritesResultsAndExitsZero) {
  EXPECT_EQ(run(kDeck), exit_success) << err_;
  expect_only_results();
  const std::string json = read_text(out_ / "summary.json");
  EXPECT_NE(json.find("\"checks_passed\": true"), std::string::npos) << json;
  expect_end_time(json, 0.002);
  EXPECT_NE(json.find("\"polydem_version\": \"" POLYDEM_VERSION "\""), std::string::npos) << json;
}

TEST_F(RunCommandTest, UnknownKeyIsRejectedWithFileLineAndKey) {
  const std::string deck = replace_once(kDeck, "end_time = 0.002\n", "end_time = 0.002\nend_tme = 3\n");
  EXPECT_EQ(run(deck), exit_bad_input);
  const std::string where = deck_.string() + ":" + std::to_string(line_of(deck, "end_tme"));
  EXPECT_NE(err_.find(where), std::string::npos) << err_;
  EXPECT_NE(err_.find("simulation.end_tme"), std::string::npos) << err_;
  expect_nothing_written();
}

TEST_F(RunCommandTest, NegativeDensityIsRejectedWithFileLineAndKey) {
  const std::string deck = replace_once(kDeck, "density = 2600.0", "density = -5.0");
  EXPECT_EQ(run(deck), exit_bad_input);
  const std::string where = deck_.string() + ":" + std::to_string(line_of(deck, "density"));
  EXPECT_NE(err_.find(where), std::string::npos) << err_;
  EXPECT_NE(err_.find("block[2].density"), std::string::npos) << err_;
  expect_nothing_written();
}

// A generated wall whose window does not fit (issue 13): refused naming the
// opening's key, and nothing written.
TEST_F(RunCommandTest, WallOpeningThatDoesNotFitIsRejectedAndNothingWritten) {
  const std::string deck = kDeck + std::string(R"(
[[wall]]
name = "w"
origin = [3.0, 0.0, 0.0]
length = 2.0
height = 1.6

[[wall.opening]]
position = 0.7
width = 1.2
height = 0.6
)");
  EXPECT_EQ(run(deck), exit_bad_input);
  const std::string where = deck_.string() + ":" + std::to_string(line_of(deck, "width = 1.2"));
  EXPECT_NE(err_.find(where), std::string::npos) << err_;
  EXPECT_NE(err_.find("wall[1].opening[1].width"), std::string::npos) << err_;
  expect_nothing_written();
}

TEST_F(RunCommandTest, OverlappingBlocksAreRejected) {
  // The stone sunk 0.1 m into the base.
  const std::string deck = replace_once(kDeck, "center = [0.0, 0.0, 0.5]", "center = [0.0, 0.0, 0.4]");
  EXPECT_EQ(run(deck), exit_bad_input);
  // Named by the later block's [[block]] header line.
  int line = 0;
  {
    std::istringstream in(deck);
    std::string l;
    for (int n = 1; std::getline(in, l); ++n) {
      if (l == "[[block]]") line = n;
      if (l == "name = \"stone\"") break;
    }
  }
  const std::string where = deck_.string() + ":" + std::to_string(line);
  EXPECT_NE(err_.find(where), std::string::npos) << err_;
  EXPECT_NE(err_.find("'stone'"), std::string::npos) << err_;
  EXPECT_NE(err_.find("overlaps"), std::string::npos) << err_;
  expect_nothing_written();
}

// With snapshots asked for, a deck rejected at setup leaves no vtk/ folder
// either (the writer makes it at its first snapshot).
TEST_F(RunCommandTest, OverlappingBlocksWithSnapshotsLeaveNothing) {
  std::string deck = replace_once(kDeck, "center = [0.0, 0.0, 0.5]", "center = [0.0, 0.0, 0.4]");
  deck += "\n[output]\nsnapshot_interval = 0.001\n";
  EXPECT_EQ(run(deck), exit_bad_input);
  EXPECT_NE(err_.find("overlaps"), std::string::npos) << err_;
  expect_nothing_written();
}

TEST_F(RunCommandTest, TimeStepAboveTheCriticalStepIsRejected) {
  const std::string deck = replace_once(kDeck, "end_time = 0.002\n", "end_time = 0.002\ntime_step = 1e-3\n");
  EXPECT_EQ(run(deck), exit_bad_input);
  const std::string where = deck_.string() + ":" + std::to_string(line_of(deck, "time_step"));
  EXPECT_NE(err_.find(where), std::string::npos) << err_;
  EXPECT_NE(err_.find("simulation.time_step"), std::string::npos) << err_;
  expect_nothing_written();
}

TEST_F(RunCommandTest, TimeStepFromAnOverrideIsRejectedNamingTheOverride) {
  EXPECT_EQ(run(kDeck, {"simulation.time_step=1e-3"}), exit_bad_input);
  EXPECT_NE(err_.find("simulation.time_step"), std::string::npos) << err_;
  expect_nothing_written();
  // The deck has no time_step line: like every other override error, the
  // message names the override, not a line.
  EXPECT_EQ(err_.find(deck_.string() + ":0:"), std::string::npos) << err_;
  EXPECT_NE(err_.find("--set"), std::string::npos) << err_;
}

TEST_F(RunCommandTest, FailedCheckExitsOneAndStillWritesResults) {
  const std::string deck = replace_once(kDeck, "tolerance = 1e-3", "expected = 1.0\ntolerance = 1e-6");
  EXPECT_EQ(run(deck), exit_check_failed) << err_;
  expect_only_results();
  const std::string json = read_text(out_ / "summary.json");
  EXPECT_NE(json.find("\"checks_passed\": false"), std::string::npos) << json;
  // The check's record: name, measured, expected, tolerance, passed.
  const std::size_t checks = json.find("\"checks\"");
  ASSERT_NE(checks, std::string::npos) << json;
  EXPECT_NE(json.find("\"name\": \"no_drift:stone\"", checks), std::string::npos) << json;
  EXPECT_EQ(json_number(json, "expected", checks), 1.0);
  EXPECT_EQ(json_number(json, "tolerance", checks), 1e-6);
  const double measured = json_number(json, "measured", checks);
  EXPECT_GE(measured, 0.0);
  EXPECT_LT(measured, 1e-3);  // the stone barely moves in 2 ms
  EXPECT_NE(json.find("\"passed\": false", checks), std::string::npos) << json;
}

TEST_F(RunCommandTest, OverridesApply) {
  EXPECT_EQ(run(kDeck, {"simulation.end_time=0.001", "block[2].density=2000"}), exit_success) << err_;
  const std::string json = read_text(out_ / "summary.json");
  expect_end_time(json, 0.001);
  // A lighter stone has a higher frequency on the same joints: ρ enters as 1/√ρ.
  const double w_light = json_number(json, "highest_frequency_rad_s");
  fs::remove_all(out_);
  EXPECT_EQ(run(kDeck, {"simulation.end_time=0.001"}), exit_success) << err_;
  const double w_default = json_number(read_text(out_ / "summary.json"), "highest_frequency_rad_s");
  EXPECT_NEAR(w_light / w_default, std::sqrt(2600.0 / 2000.0), 1e-9);
}

TEST_F(RunCommandTest, BadOverrideIsRejectedNamingTheOverride) {
  EXPECT_EQ(run(kDeck, {"block[2].density=-5"}), exit_bad_input);
  EXPECT_NE(err_.find("--set"), std::string::npos) << err_;
  EXPECT_NE(err_.find("block[2].density"), std::string::npos) << err_;
  EXPECT_NE(err_.find(deck_.string()), std::string::npos) << err_;
  expect_nothing_written();
}

TEST_F(RunCommandTest, NonFiniteStateExitsThreeAndKeepsTheLastGoodState) {
  // Gravity so strong that m·g overflows: the state becomes infinite at once.
  const std::string deck = replace_once(kDeck, "end_time = 0.002\n", "end_time = 0.05\ngravity = [0.0, 0.0, -1e308]\n");
  EXPECT_EQ(run(deck), exit_instability) << err_;
  EXPECT_NE(err_.find("step"), std::string::npos) << err_;
  EXPECT_NE(err_.find("'stone'"), std::string::npos) << err_;
  EXPECT_NE(err_.find("last good state"), std::string::npos) << err_;
  // The guard keeps the state of its last passed check and says so.
  const fs::path out = dir_ / "out";
  EXPECT_TRUE(fs::exists(out / "last_good_state.vtu"));
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"unstable\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"instability\""), std::string::npos) << summary;
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "temporary left behind: " << e.path();
}

// The built binary; stdout goes to `out`, and stderr too unless `err` is
// given.
std::string shell_run(const std::string& args, const fs::path& out, int& status, const fs::path& err = {}) {
  const std::string cmd = std::string("\"") + POLYDEM_BINARY + "\" " + args + " > \"" + out.string() + "\" " +
                          (err.empty() ? std::string("2>&1") : "2> \"" + err.string() + "\"");
  const int rc = std::system(cmd.c_str());
  status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return read_text(out);
}

TEST_F(RunCommandTest, BinaryPrintsItsVersion) {
  int status = -1;
  const std::string text = shell_run("--version", dir_ / "version.txt", status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(text.find("polydem " POLYDEM_VERSION), std::string::npos) << text;
}

TEST_F(RunCommandTest, BinaryRejectsABadDeckWithExitTwo) {
  const fs::path deck = dir_ / "bad.toml";
  const std::string text = replace_once(kDeck, "density = 2600.0", "density = -5.0");
  std::ofstream(deck) << text;
  int status = -1;
  const std::string err =
      shell_run("run \"" + deck.string() + "\" --quiet --out \"" + out_.string() + "\"", dir_ / "err.txt", status);
  EXPECT_EQ(status, exit_bad_input) << err;
  EXPECT_NE(err.find(deck.string() + ":" + std::to_string(line_of(text, "density"))), std::string::npos) << err;
  EXPECT_NE(err.find("block[2].density"), std::string::npos) << err;
  expect_nothing_written();
  // And --set reaches the deck through the command line.
  const fs::path good = dir_ / "good.toml";
  std::ofstream(good) << kDeck;
  shell_run("run \"" + good.string() + "\" --quiet --out \"" + out_.string() + "\" --set simulation.end_time=0.001",
            dir_ / "err2.txt", status);
  EXPECT_EQ(status, exit_success);
  expect_end_time(read_text(out_ / "summary.json"), 0.001);
}

// What `polydem run` shows last (run/verdict.hpp): three plain lines on
// stdout, after everything on stderr, as a user runs the binary.
class VerdictTest : public RunCommandTest {
 protected:
  // Runs `deck_text` through the binary with `flags`; stdout's lines in
  // out_lines_, stderr in err_.
  int run_binary(const std::string& deck_text, const std::string& flags = "") {
    deck_ = dir_ / "deck.toml";
    std::ofstream(deck_) << deck_text;
    int status = -1;
    std::istringstream out(shell_run("run \"" + deck_.string() + "\" --threads 1 --out \"" + out_.string() + "\" " +
                                         flags,
                                     dir_ / "stdout.txt", status, dir_ / "stderr.txt"));
    out_lines_.clear();
    for (std::string line; std::getline(out, line);) out_lines_.push_back(line);
    err_ = read_text(dir_ / "stderr.txt");
    return status;
  }
  std::vector<std::string> out_lines_;
};

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The cube on its base turned into a stack of two 0.4 x 0.4 x 1 m stones,
// each in its own group (b/h = 0.2 for the stack), under a constant 0.5 g:
// they tip over (friction 45° keeps them from sliding).
std::string stack_deck() {
  std::string deck = replace_once(kDeck, "end_time = 0.002", "end_time = 1.5");
  deck = replace_once(deck, "normal_stiffness = 98e9", "normal_stiffness = 98e9\nfriction_angle = 45.0\ndamping = 2.1e-5");
  deck = replace_once(deck, "name = \"stone\"", "name = \"lower\"\ngroup = \"course0\"");
  deck = replace_once(deck, "size = [1.0, 1.0, 1.0]", "size = [0.4, 0.4, 1.0]");
  deck = replace_once(deck, "[[check]]\nkind = \"no_drift\"\nblock = \"stone\"\ntolerance = 1e-3\n", R"([[block]]
name = "upper"
group = "course1"
shape = "box"
size = [0.4, 0.4, 1.0]
center = [0.0, 0.0, 1.5]

[ground_motion]
kind = "constant"
acceleration_g = 0.5

[assessment]
collapse_displacement = 0.05
collapse_mass_fraction = 0.9
stop_on_collapse = true
)");
  return deck;
}

TEST_F(VerdictTest, ACollapseSaysWhenHowAndWhatFell) {
  EXPECT_EQ(run_binary(stack_deck()), exit_success) << err_;
  ASSERT_EQ(out_lines_.size(), 3u) << err_;
  // The mechanism under a constant acceleration: the acceleration it formed
  // at is the load's, 0.5 g; without rocking back it is Mode II.
  EXPECT_TRUE(starts_with(out_lines_[0], "collapsed (Mode II) at t = ")) << out_lines_[0];
  EXPECT_TRUE(has(out_lines_[0], ": the mechanism formed at 0.5 g (t = ")) << out_lines_[0];
  // Both stones went (the collapse waits for 90 % of the mass), each its
  // group's only block; they started at heights 0.5 and 1.5 m.
  EXPECT_EQ(out_lines_[1], "lost: 2 of 2 blocks (2 fell), 100 % of the free mass, from z = 0.50-1.50 m: course0, course1");
  EXPECT_TRUE(starts_with(out_lines_[2], "energy: ")) << out_lines_[2];
  EXPECT_TRUE(has(out_lines_[2], " put in, ")) << out_lines_[2];
  EXPECT_TRUE(has(out_lines_[2], " dissipated (slip ")) << out_lines_[2];
  EXPECT_TRUE(has(out_lines_[2], "; numerical ")) << out_lines_[2];
  EXPECT_TRUE(has(err_, "results in ")) << err_;
  EXPECT_FALSE(has(err_, "profile")) << err_;
}

TEST_F(VerdictTest, AStoneThatStaysPutIsIntactAndNothingFell) {
  EXPECT_EQ(run_binary(kDeck), exit_success) << err_;
  ASSERT_EQ(out_lines_.size(), 3u) << err_;
  EXPECT_TRUE(starts_with(out_lines_[0], "intact: peak displacement ")) << out_lines_[0];
  EXPECT_TRUE(has(out_lines_[0], " µm (stone), ")) << out_lines_[0];
  EXPECT_EQ(out_lines_[1], "lost: nothing (no block ends more than 100 mm from its place)");
  EXPECT_TRUE(starts_with(out_lines_[2], "energy: ")) << out_lines_[2];
  EXPECT_TRUE(has(out_lines_[2], "; numerical ")) << out_lines_[2];
  // The deck's check comes before the verdict, on stderr.
  EXPECT_TRUE(has(err_, "check no_drift:stone")) << err_;
}

TEST_F(VerdictTest, VerboseAddsTheStepStatisticsAndTheProfile) {
  EXPECT_EQ(run_binary(kDeck, "--verbose"), exit_success) << err_;
  EXPECT_EQ(out_lines_.size(), 3u) << err_;
  EXPECT_TRUE(has(err_, " steps of ")) << err_;
  EXPECT_TRUE(has(err_, "polydem: profile ")) << err_;
}

TEST_F(VerdictTest, QuietPrintsNothing) {
  EXPECT_EQ(run_binary(kDeck, "--quiet"), exit_success) << err_;
  EXPECT_TRUE(out_lines_.empty());
  EXPECT_TRUE(err_.empty()) << err_;
}

}  // namespace
}  // namespace polydem
