#include "apps/sweep_points.hpp"

#include "io/checkpoint.hpp"
#include "apps/run_command.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/json.hpp"
#include "io/summary.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace polydem {

namespace fs = std::filesystem;

namespace {


// The last non-empty line of a worker's log: what it said before it failed.
std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of("\n\r ");
  if (end == std::string::npos) return "";
  const std::size_t begin = text.rfind('\n', end);
  return text.substr(begin == std::string::npos ? 0 : begin + 1, end + 1 - (begin == std::string::npos ? 0 : begin + 1));
}

PointResult failed_point(int exit_code, const std::string& message) {
  PointResult r;
  r.status = "error";
  r.exit_code = exit_code;
  r.message = message.empty() ? fmt::format("polydem run exited with code {} without a summary", exit_code) : message;
  return r;
}

}  // namespace

BatchStart start_batch(const SweepSetup& setup, const std::vector<SweepPoint>& batch) {
  BatchStart b;
  b.dirs.resize(batch.size());
  b.results.resize(batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    b.dirs[i] = point_directory(setup, batch[i]);
    b.results[i] = read_point_result(b.dirs[i]);
    if (b.results[i].status.empty())
      b.pending.push_back(i);
    else
      b.results[i].reused = true;
    b.results[i].directory = b.dirs[i];
  }
  return b;
}

std::vector<std::string> SweepSetup::point_overrides(const SweepPoint& p) const {
  std::vector<std::string> all = overrides;
  const auto own = p.overrides();
  all.insert(all.end(), own.begin(), own.end());
  return all;
}

std::string point_directory(const SweepSetup& setup, const SweepPoint& point) {
  const auto overrides = setup.point_overrides(point);
  const SceneSpec spec = setup.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, overrides)
                                           : read_deck(setup.deck_path, overrides);
  const std::uint64_t id = run_fingerprint(spec, overrides);
  return (fs::path(setup.out_dir) / "points" / fmt::format("{:016x}", id)).string();
}



bool has_study_results(const std::string& dir, const std::string& table) {
  if (fs::exists(fs::path(dir) / table)) return true;
  const fs::path points = fs::path(dir) / "points";
  return fs::is_directory(points) && !fs::is_empty(points);
}

bool point_finished(const std::string& dir) { return !read_point_result(dir).status.empty(); }

void prepare_point_directory(const std::string& dir, const SweepPoint& point, const SweepSetup& setup) {
  // Whatever an interrupted run left here goes: the point starts afresh.
  fs::remove_all(dir);
  fs::create_directories(dir);
  Json p = Json::object();
  Json values = Json::object();
  for (const auto& [key, value] : point.values) values.set(key, value);
  p.set("values", std::move(values));
  Json all = Json::array();
  for (const auto& o : setup.point_overrides(point)) all.push_back(o);
  p.set("overrides", std::move(all));
  p.set("deck", setup.use_default ? std::string(kDefaultDeckName) : setup.deck_path);
  write_file_atomic(dir + "/point.json", p.dump(2) + "\n");
}

PointResult run_point_here(const SweepSetup& setup, const SweepPoint& point, const std::string& dir) {
  prepare_point_directory(dir, point, setup);
  RunOptions o;
  o.deck_path = setup.deck_path;
  o.use_default = setup.use_default;
  o.out_dir = dir;
  o.threads = setup.threads;
  o.quiet = true;
  o.overrides = setup.point_overrides(point);
  const int code = run_command(o);
  PointResult r = read_point_result(dir);
  if (r.status.empty()) r = failed_point(code, "");
  r.exit_code = code;
  r.directory = dir;
  return r;
}

// ------------------------------------------------------------ local workers

namespace {

class LocalRunner final : public PointRunner {
 public:
  LocalRunner(const SweepSetup& setup, int jobs) : setup_(setup), jobs_(std::max(1, jobs)) {
    if (setup_.executable.empty()) setup_.executable = fs::read_symlink("/proc/self/exe").string();
  }

  std::string describe() const override {
    return fmt::format("{} local process{} of {} thread{}", jobs_, jobs_ == 1 ? "" : "es", setup_.threads,
                       setup_.threads == 1 ? "" : "s");
  }

  std::vector<PointResult> run(const std::vector<SweepPoint>& batch) override {
    BatchStart b = start_batch(setup_, batch);
    std::vector<PointResult>& results = b.results;
    const std::vector<std::string>& dirs = b.dirs;
    const std::vector<std::size_t>& pending = b.pending;
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0;
    while (next < pending.size() || !running.empty()) {
      while (next < pending.size() && static_cast<int>(running.size()) < jobs_) {
        const std::size_t i = pending[next++];
        running[start(batch[i], dirs[i])] = i;
      }
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(std::string("polydem sweep: waitpid: ") + std::strerror(errno));
      }
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const std::size_t i = it->second;
      running.erase(it);
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      results[i] = read_point_result(dirs[i]);
      if (results[i].status.empty())
        results[i] = failed_point(code, last_line(read_file_text(dirs[i] + "/log.txt")));
      else
        results[i].exit_code = code;
      results[i].directory = dirs[i];
      if (setup_.finished) setup_.finished(batch[i], results[i]);
    }
    for (std::size_t i = 0; i < batch.size(); ++i) results[i].directory = dirs[i];
    return results;
  }

 private:
  // fork + exec `polydem run` with the point's overrides; its stdout and
  // stderr go to DIR/log.txt. The child dies with the sweep (PDEATHSIG), so a
  // killed sweep leaves no orphan writing into a point directory.
  pid_t start(const SweepPoint& point, const std::string& dir) {
    prepare_point_directory(dir, point, setup_);
    std::vector<std::string> args{setup_.executable, "run"};
    if (setup_.use_default)
      args.push_back("--default");
    else
      args.push_back(setup_.deck_path);
    for (const auto& o : setup_.point_overrides(point)) {
      args.push_back("--set");
      args.push_back(o);
    }
    args.insert(args.end(), {"--out", dir, "--quiet", "--threads", std::to_string(setup_.threads)});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string log = dir + "/log.txt";
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("polydem sweep: fork: ") + std::strerror(errno));
    if (pid == 0) {
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(127);  // the sweep died before prctl
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) {
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        close(fd);
      }
      execv(argv[0], argv.data());
      _exit(127);
    }
    return pid;
  }

  SweepSetup setup_;
  int jobs_;
};

}  // namespace

std::unique_ptr<PointRunner> local_runner(const SweepSetup& setup, int jobs) {
  return std::make_unique<LocalRunner>(setup, jobs);
}

std::unique_ptr<PointRunner> point_runner(const SweepSetup& setup, int jobs) {
  if (started_by_mpirun()) {
    std::unique_ptr<PointRunner> runner = mpi_runner(setup);
    if (!runner)
      throw std::runtime_error("started by mpirun, but this polydem was built without MPI "
                               "(install libopenmpi-dev and rebuild, or run without mpirun and use --jobs)");
    return runner;
  }
  if (jobs <= 0) jobs = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / std::max(1, setup.threads));
  return local_runner(setup, jobs);
}

std::unique_ptr<PointRunner> leader_runner(const SweepSetup& setup, int jobs, const std::string& name, int& exit_code) {
  std::unique_ptr<PointRunner> runner;
  try {
    runner = point_runner(setup, jobs);
  } catch (const std::exception& e) {
    std::cerr << "polydem " << name << ": error: " << e.what() << "\n";
    exit_code = exit_bad_input;
    return nullptr;
  }
  if (runner->leader()) return runner;
  runner->serve();
  exit_code = exit_success;
  return nullptr;
}

bool started_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace polydem
