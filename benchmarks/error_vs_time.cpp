// Error against run time for the verification cases (DESIGN/STYLE item 9):
// each case's deck from examples/verification/ is run at several time steps
// (simulation.safety_factor, a fraction of the critical step) or loading
// rates, and every run's error against the exact or analytical value is
// tabulated with its step, step count and wall time. A least-squares slope on
// log-log axes gives the observed order of convergence of each error.
//
//   case 2  slope_slide          slide acceleration g(sin θ − cos θ tan φ)   vs dt
//   case 3  rocking_onset        a/g at heel opening = b/h                   vs rate_g (and vs dt)
//   case 4  free_rocking         time to first impact (eq. 7), Housner ratio vs dt
//   case 5  energy_conservation  energy-balance drift (no damping, no slip)  vs dt
//   the free rocking and the four-drum column under a pulse with each damping
//   scheme (simulation.damping_scheme "explicit" and "split")     vs dt
//
// One thread (the scenes have one free block). Output: a markdown table on
// stdout and CSV at --csv (default benchmarks/results/error_vs_time.csv).
//
//   polydem_error_vs_time [--csv PATH] [--quick] [--no-csv] [--engine LABEL]
#include "run/run_scene.hpp"
#include "benchmarks/bench_util.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"

#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace polydem::bench {
namespace {

std::string deck_path(const std::string& name) {
  return std::string(POLYDEM_SOURCE_DIR) + "/examples/verification/" + name;
}

// One sweep: a deck, the checks it measures, and the values of one parameter.
struct Sweep {
  std::string label;                 // "case 2 slope_slide"
  std::string deck;                  // file in examples/verification/
  std::vector<std::string> checks;   // CheckResult::name values to tabulate
  std::string parameter;             // "safety_factor" or "rate_g"
  std::vector<double> values;
  // Deck overrides for one value of the parameter.
  std::function<std::vector<std::string>(double)> overrides;
  bool against_dt = true;            // convergence variable: dt (else the parameter itself)
};

struct Point {
  double x = 0;      // dt or the parameter
  double error = 0;  // |error| used for the fit
};

std::string kv(const std::string& key, double v) { return key + "=" + fmt(v, 17); }

std::vector<Sweep> sweeps(bool quick) {
  const std::vector<double> factors =
      quick ? std::vector<double>{0.8, 0.4, 0.2} : std::vector<double>{0.8, 0.4, 0.2, 0.1, 0.05};
  const std::vector<double> rates =
      quick ? std::vector<double>{0.2, 0.1, 0.05} : std::vector<double>{0.2, 0.1, 0.05, 0.02, 0.01};
  auto by_factor = [](double f) { return std::vector<std::string>{kv("simulation.safety_factor", f)}; };
  auto by_factor_split = [](double f) {
    return std::vector<std::string>{kv("simulation.safety_factor", f), "simulation.damping_scheme=\"split\""};
  };
  // The onset (0.25 g) must come before the end: run to 0.3 g.
  auto by_rate = [](double r) {
    return std::vector<std::string>{kv("ground_motion.rate_g", r), kv("simulation.end_time", 0.3 / r)};
  };
  auto onset_by_factor = [](double f) {
    return std::vector<std::string>{kv("simulation.safety_factor", f), kv("ground_motion.rate_g", 0.05),
                                    kv("simulation.end_time", 0.3 / 0.05)};
  };
  return {
      {"2 slope_slide", "slope_slide.toml", {"slide_acceleration:stone"}, "safety_factor", factors, by_factor, true},
      {"3 rocking_onset", "rocking_onset.toml", {"rocking_onset:pillar"}, "rate_g", rates, by_rate, false},
      {"3 rocking_onset", "rocking_onset.toml", {"rocking_onset:pillar"}, "safety_factor (rate_g 0.05)",
       std::vector<double>(factors.begin(), factors.end() - (quick ? 0 : 1)), onset_by_factor, true},
      {"4 free_rocking", "free_rocking.toml", {"rocking_first_impact:pillar", "housner_restitution:pillar"},
       "safety_factor", factors, by_factor, true},
      {"5 energy_conservation", "energy_conservation.toml", {"energy_conservation"}, "safety_factor", factors,
       by_factor, true},
      // The two damping schemes (simulation.damping_scheme) on the rocking
      // cases whose impacts the dashpots shape: the single pillar and the
      // stack of four drums under a pulse.
      {"4 free_rocking, split damping", "free_rocking.toml",
       {"rocking_first_impact:pillar", "housner_restitution:pillar"}, "safety_factor", factors, by_factor_split, true},
      {"column_rocking", "column_rocking.toml", {"stack_pulse_peak_rotation:column_drum00"}, "safety_factor", factors,
       by_factor, true},
      {"column_rocking, split damping", "column_rocking.toml", {"stack_pulse_peak_rotation:column_drum00"},
       "safety_factor", factors, by_factor_split, true},
  };
}

int run(int argc, char** argv) {
  const bool quick = flag(argc, argv, "--quick");
  const std::string csv_path =
      option(argc, argv, "--csv", std::string(POLYDEM_SOURCE_DIR) + "/benchmarks/results/error_vs_time.csv");
  Machine machine = this_machine();
  machine.engine = engine_version(argc, argv);

  Table table({"case", "check", "parameter", "value", "dt (s)", "steps", "wall (s)", "measured", "expected",
               "error"});
  // Series for the convergence fit, keyed by (sweep index, check).
  std::map<std::pair<std::size_t, std::string>, std::vector<Point>> series;
  bool failed = false;

  const std::vector<Sweep> all = sweeps(quick);
  for (std::size_t s = 0; s < all.size(); ++s) {
    const Sweep& sw = all[s];
    for (double value : sw.values) {
      RunReport rep;
      try {
        SceneSpec spec = read_deck(deck_path(sw.deck), sw.overrides(value));
        RunControl control;
        control.threads = 1;
        rep = run_scene(spec, control);
      } catch (const std::exception& e) {
        std::cerr << sw.deck << " " << sw.parameter << "=" << value << ": " << e.what() << "\n";
        failed = true;
        continue;
      }
      for (const std::string& name : sw.checks) {
        const CheckResult* c = nullptr;
        for (const CheckResult& r : rep.checks)
          if (r.name == name) c = &r;
        if (!c) {
          std::cerr << sw.deck << ": no check " << name << "\n";
          failed = true;
          continue;
        }
        // Signed relative error; for a check whose exact value is 0 (the
        // energy drift, already relative to the energy in play) the measured
        // value itself.
        const double err = c->expected != 0 ? (c->measured - c->expected) / std::abs(c->expected) : c->measured;
        table.add_row({sw.label, name, sw.parameter, fmt(value, 3), fmt(rep.time_step, 4), std::to_string(rep.steps),
                       fmt_fixed(rep.wall_seconds, 3), fmt(c->measured, 10), fmt(c->expected, 10), fmt(err, 3)});
        series[{s, name}].push_back({sw.against_dt ? rep.time_step : value, std::abs(err)});
        std::cerr << "  " << sw.label << " " << name << " " << sw.parameter << "=" << value << ": error " << fmt(err, 3)
                  << " (" << fmt_fixed(rep.wall_seconds, 2) << " s)\n";
      }
    }
  }

  // Observed orders: least squares over all points, and between the two
  // finest points (where the asymptotic order shows, if there is one).
  Table orders({"case", "check", "varied", "errors (coarse to fine)", "order (fit)", "order (finest pair)"});
  for (const auto& [key, pts] : series) {
    const Sweep& sw = all[key.first];
    std::vector<double> x, y;
    std::string errs;
    for (const Point& p : pts) {
      x.push_back(p.x);
      y.push_back(p.error);
      if (!errs.empty()) errs += ", ";
      errs += fmt(p.error, 2);
    }
    const std::size_t n = x.size();
    const double last = n >= 2 ? loglog_slope({x[n - 2], x[n - 1]}, {y[n - 2], y[n - 1]}) : std::nan("");
    orders.add_row({sw.label, key.second, sw.against_dt ? "dt" : sw.parameter, errs, fmt(loglog_slope(x, y), 2),
                    fmt(last, 2)});
  }

  std::cout << "Error against time step / loading rate (1 thread)\n"
            << "machine: nproc " << machine.logical_cpus << ", " << machine.cpu_model << ", " << machine.date_utc
            << ", polydem " << machine.engine
            << ", load " << machine.load_average << "\n\n"
            << table.markdown() << "\nerror: (measured − expected)/|expected|; for energy_conservation the drift "
            << "itself (relative to the energy in play; expected 0)\n\nObserved order of convergence "
            << "(slope of log|error| against log dt or log rate)\n\n"
            << orders.markdown();

  if (!flag(argc, argv, "--no-csv")) {
    std::filesystem::create_directories(std::filesystem::path(csv_path).parent_path());
    write_file_atomic(csv_path, csv_header_comment(machine, "polydem_error_vs_time: verification error against "
                                                            "time step or loading rate, 1 thread") +
                                    table.csv());
    std::cout << "\nwrote " << csv_path << "\n";
  }
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace polydem::bench

int main(int argc, char** argv) {
  try {
    return polydem::bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "polydem_error_vs_time: " << e.what() << "\n";
    return 2;
  }
}
