#include "apps/ensemble_command.hpp"

#include "apps/option_number.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_points.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/ensemble_tables.hpp"
#include "io/json.hpp"
#include "studies/ensemble.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace polydem {

namespace fs = std::filesystem;

namespace {

std::string figure(double x) { return std::isfinite(x) ? fmt::format("{:.6g}", x) : std::string("-"); }

}  // namespace

int ensemble_command(const EnsembleOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  SweepSetup setup = setup_from(o);
  const std::string deck_name = o.use_default ? std::string(kDefaultDeckName) : o.deck_path;

  long replicas = 0;
  std::uint64_t seed = 0;
  SceneSpec base;
  std::vector<SweepPoint> points;
  try {
    if (o.replicas.empty()) throw std::invalid_argument("give --replicas N");
    replicas = static_cast<long>(read_whole_option("replicas", o.replicas, 1, 1000000));
    if (!o.seed.empty())
      setup.overrides.push_back(std::string(kSeedKey) + "=" +
                                std::to_string(read_whole_option("seed", o.seed, 0, (1LL << 53) - 1)));
    // The deck as written (replica 0), whatever replica it names itself:
    // every replica's draw is made from it.
    std::vector<std::string> unperturbed = setup.overrides;
    unperturbed.push_back(std::string(kReplicaKey) + "=0");
    base = o.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, unperturbed)
                         : read_deck(o.deck_path, unperturbed);
    seed = base.ensemble.seed;
    for (long k = 0; k < replicas; ++k) points.push_back(SweepPoint{{{kReplicaKey, static_cast<double>(k)}}});
    for (const SweepPoint& p : points) (void)point_directory(setup, p);  // every replica's deck is valid
    if (!o.resume && has_study_results(o.out_dir, "replicas.csv"))
      throw std::invalid_argument(o.out_dir + " holds the results of an earlier ensemble or sweep: give --resume "
                                              "to continue it, or another --out");
  } catch (const std::exception& e) {
    std::cerr << "polydem ensemble: error: " << e.what() << "\n";
    return exit_bad_input;
  }

  long done = 0;
  if (!o.quiet)
    setup.finished = [&](const SweepPoint& p, const PointResult& r) {
      ++done;
      std::cerr << fmt::format("  replica {}: {}{}  ({:.1f} s)  [{} of {}]{}\n",
                               static_cast<long>(p.values.at(0).second), r.status,
                               r.collapse_mode.empty() ? "" : " (Mode " + r.collapse_mode + ")", r.wall_seconds, done,
                               replicas, r.message.empty() ? "" : "  " + r.message);
    };
  int done_code = exit_success;
  const std::unique_ptr<PointRunner> runner = leader_runner(setup, o.jobs, "ensemble", done_code);
  if (!runner) return done_code;
  if (!o.quiet)
    std::cerr << fmt::format("polydem ensemble: {} replica{} of {} (seed {}) on {}\n", replicas,
                             replicas == 1 ? "" : "s", deck_name, seed, runner->describe());

  std::vector<PointResult> results;
  try {
    results = runner->run(points);
  } catch (const std::exception& e) {
    runner->finish();
    std::cerr << "polydem ensemble: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  runner->finish();

  std::vector<ReplicaRow> rows;
  long reused = 0, failed = 0;
  double run_seconds = 0;
  for (long k = 0; k < replicas; ++k) {
    const PointResult& r = results[static_cast<std::size_t>(k)];
    rows.push_back(ReplicaRow{k, seed, draw_perturbation(base, k, seed).drawn, r,
                              fs::path(r.directory).filename().string()});
    if (r.reused) ++reused;
    if (r.status == "error" || r.status == "unstable") ++failed;
    run_seconds += r.wall_seconds;
  }
  const EnsembleOutcome outcome = summarise_ensemble(results);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  fs::create_directories(o.out_dir);
  write_file_atomic(o.out_dir + "/replicas.csv", replicas_csv(rows));
  write_file_atomic(o.out_dir + "/ensemble.csv", ensemble_csv({}, {EnsemblePoint{SweepPoint{}, outcome, {}}}));
  const std::string courses = courses_csv({}, {EnsemblePoint{SweepPoint{}, outcome, {}}});
  if (!courses.empty()) write_file_atomic(o.out_dir + "/courses.csv", courses);
  Json j = Json::object();
  j.set("deck", deck_name);
  j.set("seed", static_cast<std::int64_t>(seed));
  const EnsembleSpec& e = base.ensemble;
  j.set("perturbation", Json::object()
                            .set("friction_angle_deg", e.friction_angle)
                            .set("stiffness", e.stiffness)
                            .set("velocity_m_s", e.velocity)
                            .set("time_shift", e.time_shift)
                            .set("sample_step_s", motion_sample_step(base)));
  j.set("outcome", outcome_json(outcome));
  j.set("runner", runner->describe());
  j.set("ran", replicas - reused);
  j.set("finished_before", reused);
  j.set("unstable_or_failed", failed);
  j.set("run_seconds_total", run_seconds);
  j.set("wall_seconds", wall);
  write_file_atomic(o.out_dir + "/ensemble.json", j.dump(2) + "\n");

  std::string counts;
  for (const auto& [status, n] : outcome.status_counts) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", status, n);
  std::cout << fmt::format("{} replicas of {} (seed {}): {} run, {} finished before; {:.1f} s\n", replicas, deck_name,
                           seed, replicas - reused, reused, wall);
  std::cout << fmt::format("status: {}; collapse modes: I {}, II {}\n", counts, outcome.mode_I, outcome.mode_II);
  std::cout << fmt::format("{:<34} {:>4} {:>12} {:>12} {:>12}\n", "outcome", "n", "p16", "median", "p84");
  const auto quantities = ensemble_quantities();
  for (std::size_t i = 0; i < quantities.size(); ++i) {
    const Distribution& d = outcome.quantities[i];
    if (d.n == 0) continue;
    std::cout << fmt::format("{:<34} {:>4} {:>12} {:>12} {:>12}\n", quantities[i].name, d.n, figure(d.p16),
                             figure(d.median), figure(d.p84));
  }
  std::cout << "results in " << o.out_dir << "/replicas.csv, ensemble.csv" << (courses.empty() ? "" : ", courses.csv")
            << " and ensemble.json\n";
  return failed > 0 ? exit_instability : exit_success;
}

}  // namespace polydem
