#include "apps/fragility_command.hpp"

#include "apps/option_number.hpp"
#include "io/fragility_tables.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace polydem {

namespace pa = analytical;

namespace {

struct FragilityArgs {
  std::string input, out, method = "auto", bootstrap = "1000", seed = "1", confidence = "0.9", points = "101";
  std::string im_label = "IM";
  bool no_plot = false, json = false;
};

// The plot: scripts/plot_fragility.py run by Debian's python3 (or
// $POLYDEM_PYTHON), as docs/plots.md's scripts are.
int draw(const std::string& dir, const std::string& label) {
  auto quoted = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  const char* env = std::getenv("POLYDEM_PYTHON");
  const std::string python = env && *env ? env : "/usr/bin/python3";
  const std::string script = POLYDEM_FRAGILITY_PLOT;
  if (!std::filesystem::exists(script)) {
    std::cerr << "polydem analytic fragility: no PNG: " << script << " not found\n";
    return 1;
  }
  const std::string cmd = quoted(python) + " " + quoted(script) + " " + quoted(dir) + " --im-label " + quoted(label);
  if (std::system(cmd.c_str()) != 0) {
    std::cerr << "polydem analytic fragility: no PNG: `" << cmd << "` failed (needs matplotlib)\n";
    return 1;
  }
  return 0;
}

std::string band(double lo, double hi) {
  return std::isnan(lo) ? std::string("-") : fmt::format("[{:.4g}, {:.4g}]", lo, hi);
}

void report(const pa::FragilityResult& r) {
  const pa::FragilityOptions& o = r.options;
  std::cout << fmt::format("Lognormal fragility, {} fit; bootstrap {} (seed {}), {:g} % bands\n",
                           o.method == pa::FragilityMethod::ida ? "IDA (censored MLE)" : "multiple-stripe (binomial MLE)",
                           o.bootstrap, o.seed, 100.0 * o.confidence);
  std::cout << fmt::format("{:<12} {:<15} {:>10} {:>22} {:>8} {:>22} {:>9}\n", "state", "status", "theta", "band", "beta",
                           "band", "reached");
  for (const pa::FragilityCurveFit& s : r.states)
    std::cout << fmt::format("{:<12} {:<15} {:>10.4g} {:>22} {:>8.3g} {:>22} {:>9}\n", pa::to_string(s.state),
                             pa::to_string(s.status), s.curve.theta, band(s.theta_low, s.theta_high), s.curve.beta,
                             band(s.beta_low, s.beta_high), std::to_string(s.reached) + "/" + std::to_string(s.observations));
}

int run(const FragilityArgs& a) {
  pa::FragilityOptions o;
  o.bootstrap = static_cast<int>(read_whole_option("bootstrap", a.bootstrap, 0, 1000000));
  o.seed = static_cast<std::uint64_t>(read_whole_option("seed", a.seed, 0, 1LL << 53));
  o.confidence = read_option_number("confidence", a.confidence);
  if (!(o.confidence > 0.0 && o.confidence < 1.0)) throw std::invalid_argument("--confidence must be in (0, 1)");
  o.points = static_cast<int>(read_whole_option("points", a.points, 2, 100000));
  const FragilityInput in = read_fragility_runs(a.input);
  if (in.undetermined > 0)
    std::cerr << "polydem analytic fragility: warning: " << in.undetermined << " run" << (in.undetermined == 1 ? "" : "s")
              << " of state undetermined left out of the fit\n";
  if (a.method == "ida" && !in.has_records)
    throw std::invalid_argument(a.input + ": --method ida needs a record column (or use --method stripes)");
  o.method = a.method == "stripes" || (a.method == "auto" && !in.has_records) ? pa::FragilityMethod::stripes
                                                                               : pa::FragilityMethod::ida;
  const pa::FragilityResult r = pa::fit_fragility(in.runs, o);
  write_fragility_tables(a.out, r);
  if (a.json) {
    std::cout << fragility_json(r).dump(0) << "\n";
  } else {
    report(r);
    std::cout << "wrote fragility_parameters.csv, fragility_curves.csv, fragility_points.csv to " << a.out << "\n";
  }
  std::cout.flush();
  return a.no_plot ? 0 : draw(a.out, a.im_label);
}

}  // namespace

std::function<int()> add_fragility_command(CLI::App& analytic) {
  auto a = std::make_shared<FragilityArgs>();
  auto* c = analytic.add_subcommand(
      "fragility",
      "Lognormal fragility curves P(DS >= ds | IM) = Phi(ln(IM/theta)/beta) for damaged, stones lost and collapsed, "
      "fitted by maximum likelihood to IDA or multiple-stripe runs, with bootstrap bands (docs/fragility.md)");
  c->add_option("input", a->input, "CSV of runs: a header naming im, state and (IDA) record")->required()->option_text("FILE");
  c->add_option("--out", a->out, "Directory for fragility_{parameters,curves,points}.csv and fragility.png")
      ->required()
      ->option_text("DIR");
  c->add_option("--method", a->method, "ida (records' capacities, censored MLE), stripes (binomial MLE); "
                                       "auto: ida if the file has a record column")
      ->check(CLI::IsMember({"auto", "ida", "stripes"}))
      ->option_text("{auto,ida,stripes}=auto");
  c->add_option("--bootstrap", a->bootstrap, "Bootstrap resamples, 0 to 1e6 (0: no band)")->option_text("N=1000");
  c->add_option("--seed", a->seed, "Seed of the resamples")->option_text("N=1");
  c->add_option("--confidence", a->confidence, "Two-sided level of the bands, in (0, 1)")->option_text("NUMBER=0.9");
  c->add_option("--points", a->points, "Points of the curves, from IM 0 to 1.25 x the largest")->option_text("N=101");
  c->add_option("--im-label,--im_label", a->im_label, "The IM's name and unit on the plot, e.g. 'PGA [g]'")->option_text("TEXT=IM");
  c->add_flag("--no-plot,--no_plot", a->no_plot, "No PNG");
  c->add_flag("--json", a->json, "Print one JSON object");
  return [a] { return run(*a); };
}

}  // namespace polydem
