// Running the points of a sweep and reading their results back.
//
// Every point is an ordinary `polydem run` of the deck with the point's
// overrides, into DIR/points/<id>/ (summary.json, results.h5, log.txt, and
// point.json naming the overrides). The id is a checksum of what decides the
// run — deck text, all overrides, the ground-motion record's bytes and the
// polydem version — so a resumed sweep finds a point's results only if they
// are still valid, and an edited deck is run again. A point is finished when
// its summary.json exists: run_command writes it last and atomically, so a
// sweep killed at any moment leaves either a complete point or one that is
// run again from the start.
#pragma once

#include "studies/point_result.hpp"
#include "studies/sweep_grid.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace polydem {

struct SweepSetup {
  std::string deck_path;  // empty with use_default
  bool use_default = false;
  std::vector<std::string> overrides;  // the user's --set, before each point's own
  std::string out_dir;                 // DIR: points/ and the tables
  int threads = 1;                     // OpenMP threads of each run
  bool quiet = false;
  std::string executable;  // polydem binary for local worker processes (default /proc/self/exe)
  // Called by the leader as each point of a batch finishes (not for points
  // finished before), e.g. for a progress line; may be empty.
  std::function<void(const SweepPoint&, const PointResult&)> finished;

  std::vector<std::string> point_overrides(const SweepPoint& p) const;
};


// The setup of a command's runs from its options (SweepOptions,
// EnsembleOptions: the same names for the deck, its overrides, the output,
// the threads of each run, quiet and the worker binary).
template <class Options>
SweepSetup setup_from(const Options& o) {
  SweepSetup setup;
  setup.deck_path = o.deck_path;
  setup.use_default = o.use_default;
  setup.overrides = o.overrides;
  setup.out_dir = o.out_dir;
  setup.threads = o.threads > 1 ? o.threads : 1;
  setup.quiet = o.quiet;
  setup.executable = o.executable;
  return setup;
}

// True when DIR already holds a study's results: its `table` (e.g.
// "replicas.csv") or finished points in DIR/points.
bool has_study_results(const std::string& dir, const std::string& table);

// The point's directory: DIR/points/<16 hex digits>. Throws DeckError-like
// std::runtime_error if the deck with these overrides is not valid.
std::string point_directory(const SweepSetup& setup, const SweepPoint& point);

// The result of a finished point, or nullopt-like empty status if its
// summary.json is missing. A summary.json that cannot be parsed counts as
// missing (the point is run again).
PointResult read_point_result(const std::string& dir);
bool point_finished(const std::string& dir);

// Parses a summary.json text (as run_command writes it) into a result.
PointResult point_result_from_summary(const std::string& summary_text, const std::string& what);

// A batch before it runs: each point's directory, the results of the points
// already finished on disk (marked reused), and the indices still to run.
struct BatchStart {
  std::vector<std::string> dirs;
  std::vector<PointResult> results;
  std::vector<std::size_t> pending;
};
BatchStart start_batch(const SweepSetup& setup, const std::vector<SweepPoint>& batch);


// Runs batches of points, skipping the finished ones, and returns one result
// per point in the order given.
class PointRunner {
 public:
  virtual ~PointRunner() = default;
  virtual std::vector<PointResult> run(const std::vector<SweepPoint>& batch) = 0;
  // The process that prints, writes the tables and decides what to run next
  // (rank 0 under MPI, the only process otherwise).
  virtual bool leader() const { return true; }
  virtual std::string describe() const = 0;  // e.g. "2 local processes"
  // Ranks other than the leader: run what the leader hands out until it
  // calls finish().
  virtual void serve() {}
  // The leader, when the sweep is over (releases the other ranks).
  virtual void finish() {}
};

// `jobs` worker processes on this machine (each `polydem run`, killed with
// the sweep if it dies).
std::unique_ptr<PointRunner> local_runner(const SweepSetup& setup, int jobs);

// One process per MPI rank when polydem was built with MPI and started by
// mpirun; nullptr otherwise. Rank 0 leads; every rank (0 too) runs its share
// of each batch in its own process, and rank 0 gathers the summaries and
// writes them into its points/ (so it has every result even without a shared
// file system). Ranks other than 0 return from serve() when the sweep ends.
std::unique_ptr<PointRunner> mpi_runner(const SweepSetup& setup);
bool started_by_mpirun();

// The runner a command uses: MPI ranks when started by mpirun, else `jobs`
// local processes (0: the cores over setup.threads). Throws
// std::runtime_error when started by mpirun without MPI in this build.
std::unique_ptr<PointRunner> point_runner(const SweepSetup& setup, int jobs);

// The runner of `polydem NAME` as its leader uses it; nullptr, with
// `exit_code` set, when this process is done: a rank other than the leader
// once it has served (exit_success), or no runner could be made ("polydem
// NAME: error: ..." printed, exit_bad_input).
std::unique_ptr<PointRunner> leader_runner(const SweepSetup& setup, int jobs, const std::string& name, int& exit_code);

// Runs one point in this process (MPI ranks) and returns its result.
PointResult run_point_here(const SweepSetup& setup, const SweepPoint& point, const std::string& dir);
// Empties the point's directory and writes its point.json (before a run).
void prepare_point_directory(const std::string& dir, const SweepPoint& point, const SweepSetup& setup);

}  // namespace polydem
