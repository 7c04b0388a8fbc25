// The MPI point runner (only when CMake found MPI; see sweep_points.hpp).
//
// Protocol, per batch: rank 0 broadcasts the unfinished points as JSON
// ([{dir, values, fixed}]), rank r runs points r, r + size, ... in its own process,
// and the summaries (text) come back to rank 0 with one gather. An empty
// broadcast with "stop" ends the sweep. Points are dealt out round-robin
// rather than on request: the runs of one batch take similar times (the same
// deck, nearby values), and a static deal needs no message per point.
#include "apps/sweep_points.hpp"

#ifdef POLYDEM_HAVE_MPI

#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "io/summary.hpp"

#include <mpi.h>
#include <fmt/core.h>

#include <filesystem>

namespace polydem {
namespace {

void broadcast(std::string& text) {
  long long n = static_cast<long long>(text.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(n));
  if (n > 0) MPI_Bcast(text.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
}

// Every rank's `mine` arrives at rank 0 in rank order.
std::vector<std::string> gather(const std::string& mine, int rank, int size) {
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), offsets(size);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank == 0) {
    int total = 0;
    for (int r = 0; r < size; ++r) {
      offsets[r] = total;
      total += counts[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> out;
  if (rank == 0)
    for (int r = 0; r < size; ++r) out.push_back(all.substr(offsets[r], counts[r]));
  return out;
}

class MpiRunner final : public PointRunner {
 public:
  explicit MpiRunner(const SweepSetup& setup) : setup_(setup) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }

  ~MpiRunner() override {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
  }

  bool leader() const override { return rank_ == 0; }
  std::string describe() const override {
    return fmt::format("{} MPI rank{} of {} thread{}", size_, size_ == 1 ? "" : "s", setup_.threads,
                       setup_.threads == 1 ? "" : "s");
  }

  std::vector<PointResult> run(const std::vector<SweepPoint>& batch) override {
    BatchStart b = start_batch(setup_, batch);
    std::vector<PointResult>& results = b.results;
    const std::vector<std::string>& dirs = b.dirs;
    const std::vector<std::size_t>& pending = b.pending;
    Json work = Json::array();
    for (std::size_t i : pending) {
      Json values = Json::array();
      for (const auto& [key, value] : batch[i].values) values.push_back(Json::array().push_back(key).push_back(value));
      Json fixed = Json::array();
      for (const std::string& f : batch[i].fixed) fixed.push_back(f);
      work.push_back(Json::object().set("dir", dirs[i]).set("values", std::move(values)).set("fixed", std::move(fixed)));
    }
    if (pending.empty()) return results;
    Json message = Json::object().set("work", std::move(work));
    std::string text = message.dump(0);
    broadcast(text);
    const std::vector<std::string> replies = gather(run_share(message), rank_, size_);
    // Replies are arrays of [index, exit code, summary text] (index into pending).
    for (const std::string& reply : replies) {
      const Json r = Json::parse(reply, "MPI reply");
      for (std::size_t k = 0; k < r.size(); ++k) {
        const Json& item = r.at(k);
        const auto j = static_cast<std::size_t>(item.at(0).as_integer());
        const int code = static_cast<int>(item.at(1).as_integer());
        const std::string& summary = item.at(2).as_string();
        const std::size_t i = pending.at(j);
        if (summary.empty()) {
          PointResult failed;
          failed.status = "error";
          failed.exit_code = code;
          failed.message = item.at(3).as_string();
          failed.directory = dirs[i];
          results[i] = failed;
          continue;
        }
        results[i] = point_result_from_summary(summary, dirs[i] + "/summary.json");
        results[i].exit_code = code;
        results[i].directory = dirs[i];
        // Another machine's rank wrote its copy there; this one keeps the
        // result for a resumed sweep.
        if (!std::filesystem::exists(dirs[i] + "/summary.json")) {
          std::filesystem::create_directories(dirs[i]);
          write_file_atomic(dirs[i] + "/summary.json", summary);
        }
      }
    }
    if (setup_.finished)
      for (std::size_t i : pending) setup_.finished(batch[i], results[i]);
    return results;
  }

  void serve() override {
    for (;;) {
      std::string text;
      broadcast(text);
      const Json message = Json::parse(text, "MPI message");
      if (message.find("stop")) return;
      (void)gather(run_share(message), rank_, size_);
    }
  }

  void finish() override {
    if (rank_ != 0 || finished_) return;
    finished_ = true;
    std::string text = Json::object().set("stop", true).dump(0);
    broadcast(text);
  }

 private:
  // This rank's points of the message: work[k] for k % size == rank.
  std::string run_share(const Json& message) {
    const Json& work = *message.find("work");
    Json reply = Json::array();
    for (std::size_t k = static_cast<std::size_t>(rank_); k < work.size(); k += static_cast<std::size_t>(size_)) {
      const Json& item = work.at(k);
      SweepPoint p;
      const Json& values = *item.find("values");
      for (std::size_t v = 0; v < values.size(); ++v)
        p.values.emplace_back(values.at(v).at(0).as_string(), values.at(v).at(1).as_number());
      const Json& fixed = *item.find("fixed");
      for (std::size_t f = 0; f < fixed.size(); ++f) p.fixed.push_back(fixed.at(f).as_string());
      const std::string dir = item.find("dir")->as_string();
      const PointResult r = run_point_here(setup_, p, dir);
      const std::string summary = r.status == "error" ? std::string() : read_file_text(dir + "/summary.json");
      reply.push_back(Json::array()
                          .push_back(static_cast<std::int64_t>(k))
                          .push_back(r.exit_code)
                          .push_back(summary)
                          .push_back(r.message));
    }
    return reply.dump(0);
  }

  SweepSetup setup_;
  int rank_ = 0, size_ = 1;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<PointRunner> mpi_runner(const SweepSetup& setup) {
  if (!started_by_mpirun()) return nullptr;
  return std::make_unique<MpiRunner>(setup);
}

}  // namespace polydem

#else

namespace polydem {
std::unique_ptr<PointRunner> mpi_runner(const SweepSetup&) { return nullptr; }
}  // namespace polydem

#endif
