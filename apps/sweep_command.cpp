#include "apps/sweep_command.hpp"

#include "apps/option_number.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_points.hpp"
#include "studies/ensemble.hpp"
#include "studies/ensemble_bands.hpp"
#include "studies/sweep_search.hpp"
#include "io/ensemble_tables.hpp"
#include "io/sweep_tables.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/json.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <thread>

namespace polydem {
namespace {

Json axis_json(const std::string& key, const std::vector<double>& values) {
  return Json::object().set("key", key).set("values", Json(values));
}

// Checks the deck with the given points' overrides before anything runs, so
// a bad key or value stops the sweep at once (exit 2, nothing run).
void validate(const SweepSetup& setup, const std::vector<SweepPoint>& points) {
  for (const SweepPoint& p : points) (void)point_directory(setup, p);
}

// --band-axis needs the replicas and names a --vary key whose values are
// intensities (> 0: the fit is in ln of them).
void check_band_axis(const SweepOptions& o, const std::vector<SweepAxis>& axes) {
  if (o.replicas.empty()) throw std::invalid_argument("--band-axis goes with --replicas");
  const auto axis = std::find_if(axes.begin(), axes.end(), [&](const SweepAxis& a) { return a.key == o.band_axis; });
  if (axis == axes.end() || axis->key == kReplicaKey)
    throw std::invalid_argument("--band-axis " + o.band_axis + " is not one of the --vary keys");
  for (double x : axis->values)
    if (!(x > 0.0)) throw std::invalid_argument("--band-axis " + o.band_axis + ": every value must be > 0");
}

// DIR/bands.csv, and the table of the collapse bands on stdout.
void write_bands(const SweepOptions& o, const std::vector<std::string>& outer,
                 const std::vector<std::pair<SweepPoint, PointResult>>& results) {
  std::vector<std::string> columns;
  for (const auto& key : outer)
    if (key != o.band_axis) columns.push_back(key);
  const std::vector<ColumnBands> bands = fit_bands(columns, o.band_axis, results);
  write_file_atomic(o.out_dir + "/bands.csv", bands_csv(columns, o.band_axis, bands));
  std::cout << fmt::format("{:<40} {:<12} {:<15} {:>9} {:>9} {:>9} {:>7} {:>11}  along {}\n", "column", "outcome",
                           "status", "16 %", "50 %", "84 %", "beta", "undetermined", o.band_axis);
  auto number = [](double x) { return std::isnan(x) ? std::string("-") : fmt::format("{:.4g}", x); };
  for (const ColumnBands& c : bands)
    for (const OutcomeBand& b : c.outcomes) {
      // Without a fit, the observed bracket of the 50 % point.
      const std::string at50 = b.status == "fitted"  ? number(b.at50)
                               : b.status == "no_runs" ? std::string("-")
                                                       : fmt::format("({}, {})", number(b.below), number(b.above));
      std::cout << fmt::format("{:<40} {:<12} {:<15} {:>9} {:>9} {:>9} {:>7} {:>11}\n",
                               c.column.values.empty() ? "-" : c.column.label(), b.outcome, b.status,
                               number(b.at16), at50, number(b.at84), number(b.beta), b.undetermined);
    }
}

}  // namespace

int sweep_command(const SweepOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  SweepSetup setup = setup_from(o);

  std::vector<SweepAxis> axes;
  SearchAxis search;
  const bool searching = !o.search.empty();
  std::vector<SweepPoint> grid;
  SceneSpec base;
  try {
    for (const auto& v : o.vary) axes.push_back(parse_axis(v));
    if (searching) search = parse_search_axis(o.search, o.resolution);
    if (!o.replicas.empty()) {
      if (searching) throw std::invalid_argument("--replicas runs each point of a grid as an ensemble: not with --search");
      const long n = static_cast<long>(read_whole_option("replicas", o.replicas, 1, 1000000));
      SweepAxis replica{kReplicaKey, {}};
      for (long k = 0; k < n; ++k) replica.values.push_back(static_cast<double>(k));
      axes.push_back(std::move(replica));
    }
    if (!o.seed.empty()) {
      if (o.replicas.empty()) throw std::invalid_argument("--seed goes with --replicas");
      setup.overrides.push_back(std::string(kSeedKey) + "=" +
                                std::to_string(read_whole_option("seed", o.seed, 0, (1LL << 53) - 1)));
    }
    if (!o.band_axis.empty()) check_band_axis(o, axes);
    if (axes.empty() && !searching) throw std::invalid_argument("give at least one --vary KEY=... or a --search");
    std::map<std::string, int> seen;
    for (const auto& a : axes) ++seen[a.key];
    if (searching) ++seen[search.key];
    for (const auto& [key, n] : seen)
      if (n > 1) throw std::invalid_argument("key " + key + " is varied twice");
    grid = grid_points(axes);
    if (grid.size() > 1000000) throw std::invalid_argument("more than a million points");
    base = setup.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, setup.overrides)
                             : read_deck(setup.deck_path, setup.overrides);
    if (searching) {
      std::vector<SweepPoint> ends;
      for (const SweepPoint& p : grid) {
        ends.push_back(p.with(search.key, search.start));
        ends.push_back(p.with(search.key, search.stop));
      }
      validate(setup, ends);
    } else {
      validate(setup, grid);
    }
  } catch (const std::exception& e) {
    std::cerr << "polydem sweep: error: " << e.what() << "\n";
    return exit_bad_input;
  }

  int done_code = exit_success;
  const std::unique_ptr<PointRunner> runner = leader_runner(setup, o.jobs, "sweep", done_code);
  if (!runner) return done_code;

  // Every result so far, by point directory; the tables are rewritten from it
  // after each batch.
  std::map<std::string, SweepRow> rows;
  std::vector<std::string> keys;
  for (const auto& a : axes) keys.push_back(a.key);
  if (searching) keys.push_back(search.key);
  SweepTables tables;
  tables.keys = keys;
  tables.deck_text = base.deck_text;
  tables.deck_path = setup.use_default ? std::string(kDefaultDeckName) : setup.deck_path;
  long ran = 0, reused = 0, failed = 0;
  int batches = 0;
  auto write_tables = [&]() {
    tables.rows.clear();
    for (const auto& [id, row] : rows) tables.rows.push_back(row);
    write_sweep_tables(setup.out_dir, tables);
  };
  if (!o.quiet)
    std::cerr << fmt::format("polydem sweep: {} {} on {}\n", searching ? "boundary search over" : "grid of",
                             searching ? fmt::format("{} column{} along {}", grid.size(), grid.size() == 1 ? "" : "s",
                                                     search.key)
                                       : fmt::format("{} point{}", grid.size(), grid.size() == 1 ? "" : "s"),
                             runner->describe());
  const BatchRunner run_batch = [&](const std::vector<SweepPoint>& batch) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<PointResult> results = runner->run(batch);
    ++batches;
    long batch_reused = 0;
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const std::string id = std::filesystem::path(results[i].directory).filename().string();
      rows[id] = SweepRow{batch[i], results[i], id};
      if (results[i].reused) ++batch_reused;
      if (results[i].status == "error" || results[i].status == "unstable") ++failed;
      if (!o.quiet && !results[i].reused)
        std::cerr << fmt::format("  {}: {}{}  ({:.1f} s){}\n", batch[i].label(), results[i].status,
                                 results[i].collapse_mode.empty() ? "" : " (Mode " + results[i].collapse_mode + ")",
                                 results[i].wall_seconds,
                                 results[i].message.empty() ? "" : "  " + results[i].message);
    }
    reused += batch_reused;
    ran += static_cast<long>(batch.size()) - batch_reused;
    write_tables();
    if (!o.quiet)
      std::cerr << fmt::format("polydem sweep: batch {}: {} point{}, {} finished before, {:.1f} s\n", batches,
                               batch.size(), batch.size() == 1 ? "" : "s", batch_reused,
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return results;
  };

  SearchReport report;
  try {
    if (searching) {
      report = boundary_search(grid, search, run_batch);
      tables.search = &report;
      tables.axis = &search;
      write_tables();
    } else {
      (void)run_batch(grid);
    }
  } catch (const std::exception& e) {
    runner->finish();
    std::cerr << "polydem sweep: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  runner->finish();
  const bool ensembles = !o.replicas.empty();
  std::string courses;
  if (ensembles) {
    std::vector<std::string> outer(keys.begin(), keys.end() - 1);
    std::vector<std::pair<SweepPoint, PointResult>> results;
    for (const auto& [id, row] : rows) results.emplace_back(row.point, row.result);
    const bool bands = !o.band_axis.empty();
    const std::vector<EnsemblePoint> points = ensemble_points(outer, results);
    write_file_atomic(setup.out_dir + "/ensembles.csv", ensemble_csv(outer, points, bands));
    courses = courses_csv(outer, points);
    if (!courses.empty()) write_file_atomic(setup.out_dir + "/courses.csv", courses);
    if (bands) write_bands(o, outer, results);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  Json s = Json::object();
  s.set("deck", tables.deck_path);
  Json axes_json = Json::array();
  for (const auto& a : axes) axes_json.push_back(axis_json(a.key, a.values));
  s.set("vary", std::move(axes_json));
  if (searching) {
    s.set("search", Json::object()
                        .set("key", search.key)
                        .set("start", search.start)
                        .set("stop", search.stop)
                        .set("coarse_points", search.coarse)
                        .set("resolution", (search.stop - search.start) / (search.lattice_points() - 1))
                        .set("rounds", report.rounds)
                        .set("runs", report.runs)
                        .set("full_grid_runs", report.full_grid)
                        .set("runs_saved_fraction",
                             report.full_grid > 0 ? 1.0 - static_cast<double>(report.runs) / report.full_grid : 0.0));
  }
  if (ensembles) s.set("replicas", static_cast<std::int64_t>(axes.back().values.size()));
  if (!o.band_axis.empty()) s.set("band_axis", o.band_axis);
  s.set("runner", runner->describe());
  s.set("points", static_cast<std::int64_t>(rows.size()));
  s.set("ran", ran);
  s.set("finished_before", reused);
  s.set("unstable_or_failed", failed);
  double run_seconds = 0;
  for (const auto& [id, row] : rows) run_seconds += row.result.wall_seconds;
  s.set("run_seconds_total", run_seconds);
  s.set("wall_seconds", wall);
  write_file_atomic(setup.out_dir + "/sweep.json", s.dump(2) + "\n");

  if (searching) {
    std::cout << fmt::format("{:<40} {:>12} {:>12} {:>12} {:>5} {:>5}  transitions ({})\n", "column", "damage",
                             "stones lost", "collapse", "mode", "runs", search.key);
    for (const ColumnResult& c : report.columns)
      std::cout << fmt::format("{:<40} {:>12} {:>12} {:>12} {:>5} {:>5}  {}\n", c.outer.label(),
                               std::isnan(c.damage_threshold) ? "-" : value_text(c.damage_threshold),
                               std::isnan(c.stones_threshold) ? "-" : value_text(c.stones_threshold),
                               std::isnan(c.collapse_threshold) ? "-" : value_text(c.collapse_threshold),
                               c.collapse_mode, c.runs.size(), transitions_text(c.transitions));
    std::cout << fmt::format("{} runs ({} finished before) against {} for the full grid at the same resolution "
                             "({:.0f} % saved); {:.1f} s\n",
                             report.runs, reused, report.full_grid,
                             100.0 * (1.0 - static_cast<double>(report.runs) / report.full_grid), wall);
  } else {
    std::cout << fmt::format("{} points: {} run, {} finished before, {} unstable or failed; {:.1f} s\n", rows.size(),
                             ran, reused, failed, wall);
  }
  std::cout << "results in " << setup.out_dir << "/sweep.csv" << (searching ? ", boundaries.csv" : "")
            << (ensembles ? ", ensembles.csv" : "") << (courses.empty() ? "" : ", courses.csv") << (o.band_axis.empty() ? "" : ", bands.csv")
            << " and sweep.h5\n";
  return failed > 0 ? exit_instability : exit_success;
}

}  // namespace polydem
