#include "apps/synthetic_command.hpp"

#include "apps/option_number.hpp"
#include "io/synthetic_suite.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace polydem {

namespace pa = analytical;

namespace {

struct SyntheticArgs {
  std::string magnitude, distance, vs30, count = "20", seed = "1", out, fault = "strike-slip";
  std::string dt = "0.01", high_pass = "0.2", prefix = "synthetic";
  bool json = false;
};

void report(const SyntheticSuiteRun& run, const std::string& dir) {
  const pa::SyntheticMotionParameters m = pa::median_parameters(run.scenario);
  std::cout << fmt::format(
      "Rezaeian & Der Kiureghian (2010) synthetic records: M {:g}, R_rup {:g} km, Vs30 {:g} m/s, {}; seed {}\n"
      "median parameters: Ia {:.4g} m/s, D5-95 {:.3g} s, t_mid {:.3g} s, f_mid {:.3g} Hz, f' {:.3g} Hz/s, "
      "zeta_f {:.3g}\n",
      run.scenario.magnitude, run.scenario.distance, run.scenario.vs30, run.scenario.reverse ? "reverse" : "strike-slip",
      run.seed, m.arias_intensity, m.d5_95, m.t_mid, m.f_mid, m.f_slope, m.zeta_f);
  std::cout << fmt::format("{:<16} {:>10} {:>10} {:>8} {:>8} {:>7} {:>8} {:>9} {:>8}\n", "record", "Ia m/s",
                           "(measured)", "D5-95 s", "t_mid s", "f_mid", "zeta_f", "PGA m/s2", "length s");
  for (const pa::SyntheticRecord& r : run.records) {
    const pa::RecordMeasures x = pa::record_measures(r.dt, r.acceleration, run.options.g);
    const pa::SyntheticMotionParameters& p = r.parameters;
    std::cout << fmt::format("{:<16} {:>10.4g} {:>10.4g} {:>8.3g} {:>8.3g} {:>7.3g} {:>8.3g} {:>9.3g} {:>8.3g}\n", r.name,
                             p.arias_intensity, x.arias_intensity, p.d5_95, p.t_mid, p.f_mid, p.zeta_f, x.pga,
                             r.dt * static_cast<double>(r.acceleration.size() - 1));
  }
  std::cout << "wrote " << run.records.size() << " records, suite.toml and records.csv to " << dir << "\n";
}

int run(const SyntheticArgs& a) {
  SyntheticSuiteRun run;
  pa::EarthquakeScenario& s = run.scenario;
  s.magnitude = read_positive_option("magnitude", a.magnitude);
  s.distance = read_positive_option("distance", a.distance);
  s.vs30 = read_positive_option("vs30", a.vs30);
  s.reverse = a.fault == "reverse";
  const int count = static_cast<int>(read_whole_option("count", a.count, 1, 100000));
  run.seed = static_cast<std::uint64_t>(read_whole_option("seed", a.seed, 0, 1LL << 53));
  run.options.dt = read_positive_option("dt", a.dt);
  if (run.options.dt > 0.1) throw std::invalid_argument("--dt must be <= 0.1 s");
  run.options.high_pass = read_option_number("high-pass", a.high_pass);
  if (!(run.options.high_pass >= 0.0)) throw std::invalid_argument("--high-pass must be >= 0 (0: none)");
  if (a.prefix.empty() || a.prefix.find_first_of("/\\\"") != std::string::npos)
    throw std::invalid_argument("--prefix must be a file name without '/', '\\' or '\"'");
  run.records = pa::synthetic_suite(s, count, run.seed, run.options, a.prefix);
  if (s.distance < 10.0)
    std::cerr << "polydem analytic synthetic: note: the predictive equations were fitted to far-field records "
                 "(R_rup > 10 km); at " << s.distance << " km they extrapolate\n";
  write_synthetic_suite(a.out, run);
  if (a.json) std::cout << synthetic_suite_json(run, false).dump(0) << "\n";
  else report(run, a.out);
  return 0;
}

}  // namespace

std::function<int()> add_synthetic_command(CLI::App& analytic) {
  auto a = std::make_shared<SyntheticArgs>();
  auto* c = analytic.add_subcommand(
      "synthetic",
      "A suite of synthetic ground motions for a magnitude, distance and site: the stochastic model of Rezaeian & "
      "Der Kiureghian (2010), written as two-column CSVs in m/s2 and a record-suite TOML (docs/fragility.md)");
  c->add_option("--magnitude", a->magnitude, "Moment magnitude")->required()->option_text("NUMBER");
  c->add_option("--distance", a->distance, "Closest distance to the rupture, km")->required()->option_text("NUMBER");
  c->add_option("--vs30", a->vs30, "Shear-wave velocity of the top 30 m, m/s")->required()->option_text("NUMBER");
  c->add_option("--fault", a->fault, "Faulting style")->check(CLI::IsMember({"strike-slip", "reverse"}))
      ->option_text("{strike-slip,reverse}=strike-slip");
  c->add_option("--count", a->count, "Records, 1 to 100000")->option_text("N=20");
  c->add_option("--seed", a->seed, "Seed of the suite: record i draws from mix_seed(seed, i)")->option_text("N=1");
  c->add_option("--out", a->out, "Directory for the records, suite.toml and records.csv")->required()->option_text("DIR");
  c->add_option("--dt", a->dt, "Time step, s")->option_text("NUMBER=0.01");
  c->add_option("--high-pass,--high_pass", a->high_pass, "Corner of the high-pass post-filter, Hz (0: none)")->option_text("NUMBER=0.2");
  c->add_option("--prefix", a->prefix, "Records are named PREFIX_01, PREFIX_02, ...")->option_text("TEXT=synthetic");
  c->add_flag("--json", a->json, "Print one JSON object (targets and measures, no histories)");
  return [a] { return run(*a); };
}

}  // namespace polydem
