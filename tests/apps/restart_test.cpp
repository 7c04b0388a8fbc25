// Checkpoint and restart (issue 5): a run killed at a random step and
// continued from its last checkpoint ends bitwise identical to a run that
// was never interrupted, and a checkpoint that is not what it claims is
// refused with a clear message.
//
// The scene slides and rocks under a one-sine pulse: a wide block slides on
// the fixed base (pulse 0.7 g, friction 30°) and a slender pillar rocks on
// it, so shear-force history, opening joints and re-detections all cross the
// checkpoint. The killed run is tests/apps/killed_run.cpp (fork + exec): the
// run command with an after-step callback that raises SIGKILL at a chosen
// step, as a machine that dies would; the restart goes through run_scene() in-process
// (to compare the final state bit for bit) and through the binary (to
// compare the files).
#include "io/checkpoint.hpp"
#include "apps/run_command.hpp"
#include "run/run_scene.hpp"
#include "io/deck.hpp"
#include "io/hdf5_results.hpp"

#include "tests/test_util.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace polydem {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const char* const kDeck = R"(# A pillar rocking on a block that slides on a fixed base.
[simulation]
end_time = 0.5

[joint]
normal_stiffness = 98e9
friction_angle = 30.0
damping = 2.1e-5

[[block]]
name = "base"
shape = "box"
size = [3.0, 2.0, 0.5]
center = [0.0, 0.0, -0.25]
motion = "fixed"

[[block]]
name = "slab"
shape = "box"
size = [1.0, 1.0, 0.3]
center = [0.0, 0.0, 0.15]
density = 2600.0

[[block]]
name = "pillar"
shape = "box"
size = [0.3, 0.3, 1.0]
center = [0.0, 0.0, 0.8]
density = 2600.0

[ground_motion]
kind = "sine_pulse"
applied_as = "body_force"
direction = [1.0, 0.0, 0.0]
acceleration_g = 0.7
period = 0.4

[output]
history_interval = 0.002
histories = ["slab.position", "pillar.rotation", "pillar.contact_force"]
energies = true
walking = true
checkpoint_interval = 0.05

[[check]]
kind = "energy_conservation"
tolerance = 0.05

[[check]]
kind = "no_drift"
block = "pillar"
tolerance = 10.0
)";

const std::vector<std::string> kOverrides = {"simulation.end_time=0.4"};

void write_bytes(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << s;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Runs `binary` (the built polydem, or the killed run) with `args`.
// Returns the wait status.
int run_binary(const std::vector<std::string>& args, const char* binary = POLYDEM_BINARY) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    std::string name = binary;
    argv.push_back(name.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(binary, argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

std::vector<std::string> run_args(const fs::path& deck, const std::vector<std::string>& overrides,
                                  const char* threads = "2") {
  std::vector<std::string> a = {"run", deck.string(), "--quiet", "--threads", threads};
  for (const std::string& o : overrides) {
    a.push_back("--set");
    a.push_back(o);
  }
  return a;
}

// The summary without the lines that describe the machine, not the run.
std::string summary_without_timing(const std::string& json) {
  std::istringstream in(json);
  std::string line, out;
  bool in_profile = false;  // the run's profile is all wall time
  while (std::getline(in, line)) {
    if (line.find("\"profile\": {") != std::string::npos) in_profile = true;
    if (in_profile) {
      if (line == "  }," || line == "  }") in_profile = false;
      continue;
    }
    if (line.find("wall_seconds") == std::string::npos && line.find("per_second") == std::string::npos &&
        line.find("\"threads\"") == std::string::npos)
      out += line + "\n";
  }
  return out;
}

// Every field of two runs equal, bit for bit (below).
void expect_identical(const RunReport& a, const RunReport& b);

class Restart : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polydem_restart_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    deck_ = dir_ / "slide_rock.toml";
    write_bytes(deck_, kDeck);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The run of the deck with kOverrides into `out`, killed after step
  // `kill_at` (tests/apps/killed_run.cpp); returns its wait status.
  int run_killed(long kill_at, const fs::path& out) const {
    std::vector<std::string> args = {std::to_string(kill_at), deck_.string(), out.string(), "2"};
    args.insert(args.end(), overrides_.begin(), overrides_.end());
    return run_binary(args, POLYDEM_KILLED_RUN);
  }
  std::uint64_t fingerprint() const { return deck_fingerprint(kDeck, overrides_, "", POLYDEM_VERSION); }
  // A run with `sampling` killed half way between its first checkpoint and
  // its end continues from the checkpoint bit for bit.
  void expect_killed_run_continues(const std::string& sampling, const fs::path& out) {
    overrides_.push_back("simulation.joint_sampling=\"" + sampling + "\"");
    const SceneSpec spec = read_deck(deck_.string(), overrides_);
    const RunReport ref = run_scene(spec);
    ASSERT_GT(ref.detections, 2);
    const long first_checkpoint_step = static_cast<long>(0.05 / ref.time_step) + 2;
    const long kill_at = first_checkpoint_step + (ref.steps - first_checkpoint_step) / 2;
    const int status = run_killed(kill_at, out);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "status " << status;
    const std::string state =
        decode_checkpoint(read_text(out / kCheckpointFile), fingerprint(), (out / kCheckpointFile).string());
    RunControl control;
    control.restart = &state;
    expect_identical(ref, run_scene(spec, control));
  }

  // run_command in-process with stderr captured.
  int run_in_process(const RunOptions& o) {
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

  fs::path dir_, deck_;
  std::string err_;
  std::vector<std::string> overrides_ = kOverrides;  // what run_killed and fingerprint use
};

void expect_identical(const RunReport& a, const RunReport& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_TRUE(same_bits(a.end_time, b.end_time));
  EXPECT_TRUE(same_bits(a.time_step, b.time_step));
  EXPECT_EQ(a.time_step_reductions, b.time_step_reductions);
  EXPECT_EQ(a.detections, b.detections);
  EXPECT_EQ(a.subcontact_updates, b.subcontact_updates);
  EXPECT_TRUE(same_bits(a.final_position, b.final_position)) << "positions differ";
  EXPECT_TRUE(same_bits(a.final_velocity, b.final_velocity)) << "velocities differ";
  ASSERT_EQ(a.final_orientation.size(), b.final_orientation.size());
  for (std::size_t i = 0; i < a.final_orientation.size(); ++i)
    EXPECT_EQ(std::memcmp(a.final_orientation[i].coeffs().data(), b.final_orientation[i].coeffs().data(),
                          4 * sizeof(double)),
              0)
        << "orientation of block " << i;
  for (auto m : {&EnergyLedger::kinetic, &EnergyLedger::gravitational, &EnergyLedger::strain, &EnergyLedger::slip,
                 &EnergyLedger::damping, &EnergyLedger::load_work, &EnergyLedger::balance})
    EXPECT_TRUE(same_bits(a.energy.*m, b.energy.*m)) << "energy ledger differs";
  EXPECT_TRUE(same_bits(a.energy_balance_error, b.energy_balance_error));
  EXPECT_TRUE(same_bits(a.histories.rows, b.histories.rows)) << "histories differ";
  EXPECT_TRUE(same_bits(a.energies.rows, b.energies.rows)) << "energy histories differ";
  EXPECT_TRUE(same_bits(a.walking.max_bed_opening, b.walking.max_bed_opening));
  EXPECT_TRUE(same_bits(a.walking.max_vertical_opening, b.walking.max_vertical_opening));
  ASSERT_EQ(a.checks.size(), b.checks.size());
  for (std::size_t k = 0; k < a.checks.size(); ++k) {
    EXPECT_TRUE(same_bits(a.checks[k].measured, b.checks[k].measured)) << a.checks[k].name;
    EXPECT_EQ(a.checks[k].passed, b.checks[k].passed);
  }
  EXPECT_EQ(a.status, b.status);
  EXPECT_TRUE(same_bits(a.assessment.peak_displacement, b.assessment.peak_displacement));
  EXPECT_TRUE(same_bits(a.assessment.damage_time, b.assessment.damage_time));
  EXPECT_EQ(a.assessment.moved_blocks, b.assessment.moved_blocks);
}

TEST_F(Restart, KilledRunContinuesBitwiseIdentical) {
  const SceneSpec spec = read_deck(deck_.string(), kOverrides);
  // The reference: uninterrupted, and without checkpoints (checkpoints must
  // not change the run either).
  const RunReport ref = run_scene(spec);
  ASSERT_GT(ref.steps, 1000);
  ASSERT_GT(ref.detections, 2) << "the scene should slide enough to re-detect contacts";
  ASSERT_GT(ref.assessment.peak_displacement, 1e-3) << "the slab should slide";

  // Kill points: a random step past the first checkpoint (logged), and the
  // last step before the end.
  std::random_device rd;
  const unsigned seed = rd();
  std::mt19937 rng(seed);
  const long first_checkpoint_step = static_cast<long>(0.05 / ref.time_step) + 2;
  std::uniform_int_distribution<long> pick(first_checkpoint_step, ref.steps - 1);
  for (const long kill_at : {pick(rng), ref.steps - 1}) {
    SCOPED_TRACE("killed at step " + std::to_string(kill_at) + " of " + std::to_string(ref.steps) + " (seed " +
                 std::to_string(seed) + ")");
    const fs::path out = dir_ / ("killed_" + std::to_string(kill_at));
    const int status = run_killed(kill_at, out);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "status " << status;
    EXPECT_FALSE(fs::exists(out / "summary.json"));
    EXPECT_FALSE(fs::exists(out / "results.h5"));
    ASSERT_TRUE(fs::exists(out / kCheckpointFile));

    // In-process restart: the final state, bit for bit.
    const std::string state =
        decode_checkpoint(read_text(out / kCheckpointFile), fingerprint(), (out / kCheckpointFile).string());
    RunControl control;
    control.restart = &state;
    const RunReport again = run_scene(spec, control);
    expect_identical(ref, again);
  }
}

// With the joints' points following the blocks (their definitions in the
// checkpoint), a killed run continues bit for bit too.
TEST_F(Restart, PointsFollowingTheBlocksContinueBitwiseIdentical) {
  expect_killed_run_continues("step", dir_ / "killed_step");
}

// With the joints clipped at every step (their points and areas in the
// checkpoint, the clip's rest made again from the pose), likewise.
TEST_F(Restart, ClippedJointsContinueBitwiseIdentical) {
  expect_killed_run_continues("clip", dir_ / "killed_clip");
}

TEST_F(Restart, BinaryRestartWritesTheSameResults) {
  // Uninterrupted binary run with checkpoints.
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  std::vector<std::string> a = run_args(deck_, kOverrides);
  a.insert(a.end(), {"--out", whole.string()});
  const int st_whole = run_binary(a);
  ASSERT_TRUE(WIFEXITED(st_whole)) << st_whole;
  ASSERT_TRUE(fs::exists(whole / kCheckpointFile));

  ASSERT_TRUE(WIFSIGNALED(run_killed(2500, killed)));

  std::vector<std::string> c = run_args(deck_, kOverrides, "1");  // another thread count: same bits
  c.insert(c.end(), {"--restart", killed.string()});
  const int st_restart = run_binary(c);
  ASSERT_TRUE(WIFEXITED(st_restart));
  EXPECT_EQ(WEXITSTATUS(st_restart), WEXITSTATUS(st_whole));

  EXPECT_EQ(summary_without_timing(read_text(whole / "summary.json")),
            summary_without_timing(read_text(killed / "summary.json")));
  for (const char* path : {"/histories/time", "/histories/pillar.rotation.y", "/histories/slab.position.x",
                           "/histories/walking.bed_opening", "/energies/slip", "/energies/numerical"}) {
    EXPECT_TRUE(same_bits(read_vector((whole / "results.h5").string(), path),
                          read_vector((killed / "results.h5").string(), path)))
        << path;
  }
  EXPECT_EQ(read_string((whole / "results.h5").string(), "/deck"), read_string((killed / "results.h5").string(), "/deck"));
}

TEST_F(Restart, RefusesAnotherDeckOrOverrides) {
  const fs::path out = dir_ / "run";
  ASSERT_TRUE(WIFSIGNALED(run_killed(2000, out)));
  ASSERT_TRUE(fs::exists(out / kCheckpointFile));

  RunOptions o;
  o.deck_path = deck_.string();
  o.restart_dir = out.string();
  o.quiet = true;
  o.overrides = {"simulation.end_time=0.4", "joint.friction_angle=35"};
  EXPECT_EQ(run_in_process(o), exit_bad_input);
  EXPECT_NE(err_.find("different deck, --set overrides"), std::string::npos) << err_;
  o.overrides = {};
  EXPECT_EQ(run_in_process(o), exit_bad_input);
  EXPECT_NE(err_.find("different deck"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(out / "summary.json"));

  // --out elsewhere with --restart is refused by the command line.
  std::vector<std::string> b = run_args(deck_, kOverrides);
  b.insert(b.end(), {"--restart", out.string(), "--out", (dir_ / "elsewhere").string()});
  const int st = run_binary(b);
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), exit_bad_input);
}

TEST_F(Restart, RefusesDamagedCheckpoints) {
  const fs::path out = dir_ / "run";
  ASSERT_TRUE(WIFSIGNALED(run_killed(2000, out)));
  const fs::path file = out / kCheckpointFile;
  const std::string good = read_text(file);
  ASSERT_GT(good.size(), 1000u);
  // A kill during the write leaves a temporary beside it, never a torn
  // checkpoint.bin (write_file_atomic); whatever is there is complete.
  EXPECT_NO_THROW(decode_checkpoint(good, fingerprint(), file.string()));

  RunOptions o;
  o.deck_path = deck_.string();
  o.restart_dir = out.string();
  o.quiet = true;
  o.overrides = kOverrides;
  struct Damage {
    std::string bytes;
    std::string message;
  };
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  std::string bad_version = good;
  bad_version[8] = static_cast<char>(kCheckpointVersion + 1);
  const std::vector<Damage> cases = {
      {good.substr(0, good.size() / 2), "truncated checkpoint"},
      {good.substr(0, 20), "truncated checkpoint"},
      {good + "xx", "oversized checkpoint"},
      {flipped, "checksum does not match"},
      {bad_version, "format version " + std::to_string(kCheckpointVersion + 1)},
      {"{\"status\": \"intact\"}\n", "not a polydem checkpoint"},
      {"", "not a polydem checkpoint"},
  };
  for (const Damage& d : cases) {
    write_bytes(file, d.bytes);
    EXPECT_EQ(run_in_process(o), exit_bad_input) << d.message;
    EXPECT_NE(err_.find(d.message), std::string::npos) << err_;
    EXPECT_NE(err_.find(file.string()), std::string::npos) << err_;
  }
  fs::remove(file);
  EXPECT_EQ(run_in_process(o), exit_bad_input);
  EXPECT_NE(err_.find("cannot open the checkpoint"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(out / "summary.json"));

  // A payload that passes the checksum but was not written for this scene.
  write_bytes(file, encode_checkpoint(fingerprint(), good.substr(40, 100)));
  EXPECT_EQ(run_in_process(o), exit_bad_input);
  EXPECT_NE(err_.find("does not fit this scene"), std::string::npos) << err_;
}

TEST_F(Restart, NoCheckpointWithoutTheKey) {
  RunOptions o;
  o.deck_path = deck_.string();
  o.out_dir = (dir_ / "plain").string();
  o.quiet = true;
  o.overrides = {"simulation.end_time=0.05", "output.checkpoint_interval=0"};
  const int code = run_in_process(o);
  EXPECT_TRUE(code == exit_success || code == exit_check_failed) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "plain" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "plain" / kCheckpointFile));
}

}  // namespace
}  // namespace polydem
