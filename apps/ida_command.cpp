#include "apps/ida_command.hpp"

#include "apps/option_number.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_points.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/ida_tables.hpp"
#include "io/json.hpp"
#include "io/record_suite.hpp"
#include "studies/ida.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

namespace polydem {

namespace fs = std::filesystem;

namespace {

// "A,B,C" (or "A:B:C" with `separator` ':'), each a number checked by `read`.
std::vector<double> option_list(const std::string& name, const std::string& text, char separator,
                                double (*read)(const std::string&, const std::string&)) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, separator);) out.push_back(read(name, item));
  if (out.empty()) throw std::invalid_argument("--" + name + " expects a list of numbers");
  return out;
}

IntensitySpec intensity_of(const IdaOptions& o) {
  IntensitySpec im;
  if (o.im == "pga") {
    im.measure = IntensityMeasure::pga;
    if (!o.period.empty()) throw std::invalid_argument("--period goes with --im sa");
  } else if (o.im == "sa") {
    im.measure = IntensityMeasure::sa;
    if (o.period.empty()) throw std::invalid_argument("--im sa needs --period T (s), the structure's period");
    im.period = read_positive_option("period", o.period);
    im.damping = read_option_number("damping", o.damping);
    if (!(im.damping >= 0 && im.damping < 1)) throw std::invalid_argument("--damping must be in [0, 1)");
  } else {
    throw std::invalid_argument("--im must be pga or sa (got '" + o.im + "')");
  }
  return im;
}

HuntAndFill hunt_of(const IdaOptions& o) {
  HuntAndFill h;
  if (!o.hunt.empty()) {
    const std::vector<double> v = option_list("hunt", o.hunt, ':', read_option_number);
    if (v.size() != 3) throw std::invalid_argument("--hunt expects FIRST:STEP:GROWTH (IMs, g)");
    if (!(v[0] > 0) || !(v[1] > 0) || !(v[2] >= 0))
      throw std::invalid_argument("--hunt: FIRST and STEP must be > 0, GROWTH >= 0");
    h.first = v[0];
    h.step = v[1];
    h.growth = v[2];
  }
  h.tolerance = read_positive_option("tolerance", o.tolerance);
  h.max_runs = static_cast<long>(read_whole_option("max-runs", o.max_runs, 1, 10000));
  return h;
}

std::string figure(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : std::string("-"); }

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) out += p + '\n';
  return out;
}

}  // namespace

int ida_command(const IdaOptions& o) {
  const auto wall_start = std::chrono::steady_clock::now();
  SweepSetup setup = setup_from(o);
  const std::string deck_name = o.use_default ? std::string(kDefaultDeckName) : o.deck_path;

  IntensitySpec im;
  HuntAndFill hunt;
  std::vector<double> levels;
  const bool stripes = !o.stripes.empty(), factors = !o.scales.empty();
  RecordSuite suite;
  std::vector<std::string> names, motions;
  std::vector<double> record_ims;
  try {
    im = intensity_of(o);
    hunt = hunt_of(o);
    if (stripes && factors) throw std::invalid_argument("give --stripes or --scales, not both");
    if (stripes) levels = option_list("stripes", o.stripes, ',', read_positive_option);
    if (factors) levels = option_list("scales", o.scales, ',', read_positive_option);
    suite = read_record_suite(o.suite_path);
    const SceneSpec base = o.use_default ? parse_deck(default_deck_text(), kDefaultDeckName, setup.overrides)
                                         : read_deck(o.deck_path, setup.overrides);
    for (const SuiteRecord& r : suite.records) {
      try {
        record_ims.push_back(record_intensity(r, im));
      } catch (const std::invalid_argument& e) {
        throw DeckError(suite.path + ":" + std::to_string(r.line) + ": " + e.what());
      }
      names.push_back(r.name);
      motions.push_back(record_motion_override(r, suite, base.ground_motion));
      (void)point_directory(setup, record_point(r, motions.back(), 1.0));  // the deck takes every record
    }
    if (!o.resume && has_study_results(o.out_dir, "ida.csv"))
      throw std::invalid_argument(o.out_dir + " holds the results of an earlier analysis: give --resume to continue "
                                              "it, or another --out");
  } catch (const std::exception& e) {
    std::cerr << "polydem ida: error: " << e.what() << "\n";
    return exit_bad_input;
  }

  // Progress: each run as it finishes, named by its record and IM.
  std::map<std::string, std::string> labels;  // the point's overrides -> "record im=..."
  long done = 0;
  if (!o.quiet)
    setup.finished = [&](const SweepPoint& p, const PointResult& r) {
      ++done;
      std::cerr << fmt::format("  {}: {}{}  ({:.1f} s)  [{} run{}]{}\n", labels[joined(p.overrides())], r.status,
                               r.collapse_mode.empty() ? "" : " (Mode " + r.collapse_mode + ")", r.wall_seconds, done,
                               done == 1 ? "" : "s", r.message.empty() ? "" : "  " + r.message);
    };
  int done_code = exit_success;
  const std::unique_ptr<PointRunner> runner = leader_runner(setup, o.jobs, "ida", done_code);
  if (!runner) return done_code;
  const char* what = stripes ? "multiple-stripe analysis" : factors ? "scaled runs" : "incremental dynamic analysis";
  if (!o.quiet)
    std::cerr << fmt::format("polydem ida: {} of {} under {} record{} of {} (IM {}) on {}\n", what, deck_name,
                             names.size(), names.size() == 1 ? "" : "s", suite.name, im.name(), runner->describe());

  const IdaPointOf point_of = [&](std::size_t r, double x, double factor) {
    SweepPoint p = record_point(suite.records[r], motions[r], factor);
    labels[joined(p.overrides())] = fmt::format("{} im={} (scale {})", names[r], value_text(x), figure(factor));
    return p;
  };
  long reused = 0;
  int batches = 0;
  const BatchRunner run_batch = [&](const std::vector<SweepPoint>& batch) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<PointResult> results = runner->run(batch);
    long batch_reused = 0;
    for (const PointResult& r : results) batch_reused += r.reused ? 1 : 0;
    reused += batch_reused;
    ++batches;
    if (!o.quiet)
      std::cerr << fmt::format("polydem ida: round {}: {} run{}, {} finished before, {:.1f} s\n", batches,
                               batch.size(), batch.size() == 1 ? "" : "s", batch_reused,
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return results;
  };

  IdaReport report;
  try {
    report = stripes || factors ? run_stripes(names, record_ims, levels, factors, point_of, run_batch)
                                : hunt_and_fill(names, record_ims, hunt, point_of, run_batch,
                                                [&](const IdaReport& so_far) { write_ida_tables(o.out_dir, so_far); });
  } catch (const std::exception& e) {
    runner->finish();
    std::cerr << "polydem ida: error: " << e.what() << "\n";
    return exit_bad_input;
  }
  runner->finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  long undetermined = 0;
  double run_seconds = 0;
  for (const IdaRecord& r : report.records) {
    undetermined += r.undetermined;
    for (const IdaRun& run : r.runs) run_seconds += run.result.wall_seconds;
  }
  write_ida_tables(o.out_dir, report);
  Json j = Json::object();
  j.set("suite", suite.path);
  j.set("deck", deck_name);
  j.set("analysis", stripes ? "stripes" : factors ? "scales" : "hunt_and_fill");
  j.set("im", Json::object()
                  .set("measure", o.im)
                  .set("name", im.name())
                  .set("period_s", im.measure == IntensityMeasure::sa ? Json(im.period) : Json())
                  .set("damping", im.measure == IntensityMeasure::sa ? Json(im.damping) : Json())
                  .set("unit", "g (9.80665 m/s2)"));
  if (stripes || factors)
    j.set(stripes ? "stripes" : "scales", Json(levels));
  else
    j.set("hunt", Json::object()
                      .set("first", hunt.first)
                      .set("step", hunt.step)
                      .set("growth", hunt.growth)
                      .set("tolerance", hunt.tolerance)
                      .set("max_runs", static_cast<std::int64_t>(hunt.max_runs)));
  j.set("records", capacities_json(report));
  j.set("runner", runner->describe());
  j.set("runs", report.runs);
  j.set("rounds", report.rounds);
  j.set("ran", report.runs - reused);
  j.set("finished_before", reused);
  j.set("undetermined", undetermined);
  j.set("run_seconds_total", run_seconds);
  j.set("wall_seconds", wall);
  write_file_atomic(o.out_dir + "/ida.json", j.dump(2) + "\n");

  std::cout << fmt::format("{} of {} under {} ({} records), IM {} in g\n", what, deck_name, suite.name, names.size(),
                           im.name());
  std::cout << fmt::format("{:<24} {:>9} {:>9} {:>9} {:>9} {:>10} {:>9} {:>5}\n", "record", "record IM", "damage",
                           "stones", "collapse", "below", "scale", "runs");
  for (const IdaRecord& r : report.records)
    std::cout << fmt::format("{:<24} {:>9} {:>9} {:>9} {:>9} {:>10} {:>9} {:>5}\n", r.name, figure(r.record_im),
                             figure(r.damage_im), figure(r.stones_im), figure(r.collapse_im),
                             figure(r.below_collapse_im), figure(r.collapse_im / r.record_im), r.runs.size());
  std::cout << fmt::format("{} runs ({} finished before) in {} round{}; {:.1f} s\n", report.runs, reused,
                           report.rounds, report.rounds == 1 ? "" : "s", wall);
  if (undetermined > 0)
    std::cerr << fmt::format("polydem ida: warning: {} run{} undetermined (unstable, failed or undecided): "
                             "state undetermined in ida.csv, left out of a fragility fit\n",
                             undetermined, undetermined == 1 ? "" : "s");
  std::cout << "results in " << o.out_dir << "/ida.csv, capacities.csv and ida.json\n";
  return exit_success;
}

}  // namespace polydem
