#include "apps/spectrum_command.hpp"

#include "analytical/beam_modes.hpp"
#include "core/units.hpp"
#include "io/atomic_file.hpp"
#include "io/record_processing.hpp"
#include "io/record_spectra.hpp"
#include "io/record_suite.hpp"

#include <CLI/CLI.hpp>

#include <spawn.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace pa = polydem::analytical;

// The paper's two periods: the spire's first bending mode (analytical/
// beam_modes, `polydem analytic beam` with its defaults) and the tower's
// fundamental mode at 6.8 Hz (paper 3.4).
constexpr double kTowerFrequencyHz = 6.8;

std::vector<polydem::PeriodMark> default_marks() {
  const double spire_hz = pa::spire_beam_modes(pa::SpireBeam{}).modes.front().f_hz;
  return {{"spire", 1.0 / spire_hz}, {"tower", 1.0 / kTowerFrequencyHz}};
}

struct SpectrumArgs {
  std::vector<std::string> records, periods_text, marks_text;
  std::string suite, out, damping_text = "0.05", baseline_text, length_scale_text;
  bool no_plot = false;
};

double number(const std::string& option, const std::string& text) {
  try {
    std::size_t pos = 0;
    const double v = std::stod(text, &pos);
    if (pos == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(option + " expects a number, got '" + text + "'");
}

// "0.1,0.2" (and the option given several times) -> periods, each > 0.
std::vector<double> periods_of(const std::vector<std::string>& texts) {
  std::vector<double> out;
  for (const std::string& text : texts) {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      const double T = number("--periods", text.substr(start, comma - start));
      if (!(T > 0))
        throw std::invalid_argument("--periods: a period must be > 0 s, got " + text.substr(start, comma - start));
      out.push_back(T);
      start = comma + 1;
    }
  }
  return out;
}

std::vector<polydem::PeriodMark> marks_of(const std::vector<std::string>& texts) {
  if (texts.empty()) return default_marks();
  std::vector<polydem::PeriodMark> out;
  for (const std::string& text : texts) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--mark-period expects NAME=PERIOD (s), got '" + text + "'");
    const double T = number("--mark-period " + text.substr(0, eq), text.substr(eq + 1));
    if (!(T > 0)) throw std::invalid_argument("--mark-period " + text + ": the period must be > 0 s");
    out.push_back({text.substr(0, eq), T});
  }
  return out;
}

// Runs the plotting script on the written tables; true when it drew.
bool plot(const std::string& dir, double damping, const std::string& title) {
  const std::string script = std::string(POLYDEM_SCRIPTS_DIR) + "/plot_spectrum.py";
  std::vector<std::string> words = {"/usr/bin/python3", script, dir + "/spectra.csv", "--marks", dir + "/marks.csv",
                                    "--damping", std::to_string(damping), "--title", title,
                                    "--out", dir + "/spectrum.png"};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int run(const SpectrumArgs& a) {
  // Everything is read and checked before anything is written.
  if (a.out.empty()) throw std::invalid_argument("--out DIR is required");
  if (a.records.empty() == a.suite.empty())
    throw std::invalid_argument("give record files or --suite FILE (one of the two)");
  const double damping = number("--damping", a.damping_text);
  if (!(damping >= 0 && damping < 1)) throw std::invalid_argument("--damping must be in [0, 1), got " + a.damping_text);
  int baseline_order = -1;
  double length_scale = 1.0;
  if (!a.suite.empty() && !(a.baseline_text.empty() && a.length_scale_text.empty()))
    throw std::invalid_argument("--baseline-order and --length-scale apply to record files; a suite sets "
                                "baseline_order and length_scale in its file");
  if (!a.baseline_text.empty()) {
    const double order = number("--baseline-order", a.baseline_text);
    if (order != std::floor(order) || order < 0 || order > polydem::kMaxBaselineOrder)
      throw std::invalid_argument("--baseline-order must be an integer in [0, " +
                                  std::to_string(polydem::kMaxBaselineOrder) + "]");
    baseline_order = static_cast<int>(order);
  }
  if (!a.length_scale_text.empty()) {
    length_scale = number("--length-scale", a.length_scale_text);
    if (!(length_scale > 0)) throw std::invalid_argument("--length-scale must be > 0");
  }
  const std::vector<double> periods =
      a.periods_text.empty() ? pa::default_spectrum_periods() : periods_of(a.periods_text);
  const std::vector<polydem::PeriodMark> marks = marks_of(a.marks_text);

  std::string title;
  std::vector<polydem::NamedRecord> records;
  if (!a.suite.empty()) {
    const polydem::RecordSuite suite = polydem::read_record_suite(a.suite);
    records = polydem::records_of_suite(suite);
    title = suite.name;
  } else {
    records = polydem::records_of_files(a.records, baseline_order, length_scale);
    title = records.size() == 1 ? records.front().name : std::to_string(records.size()) + " records";
  }
  const polydem::SpectraTable table = polydem::record_spectra(records, periods, damping);
  std::vector<double> mark_periods;
  for (const auto& m : marks) mark_periods.push_back(m.period);
  const polydem::SpectraTable at_marks = polydem::record_spectra(records, mark_periods, damping);

  std::filesystem::create_directories(a.out);
  polydem::write_file_atomic(a.out + "/spectra.csv", polydem::spectra_csv(table));
  polydem::write_file_atomic(a.out + "/marks.csv", polydem::marks_csv(marks, at_marks));

  std::printf("%s: %zu record%s, damping %g, %zu periods %g to %g s\n", title.c_str(), records.size(),
              records.size() == 1 ? "" : "s", damping, periods.size(), periods.front(), periods.back());
  // One row per record: PGA and the pseudo-acceleration at each mark, in g.
  std::vector<std::string> heads;
  for (const auto& m : marks) {
    char period[32];
    std::snprintf(period, sizeof period, "%.3g", m.period);
    heads.push_back("Sa(" + m.name + ", " + period + " s) [g]");
  }
  std::printf("%-24s %10s", "record", "PGA [g]");
  for (const std::string& h : heads) std::printf("  %s", h.c_str());
  std::printf("\n");
  const auto row = [&](const std::string& name, const std::string& pga, const std::vector<std::string>& cells) {
    std::printf("%-24s %10s", name.c_str(), pga.c_str());
    for (std::size_t j = 0; j < cells.size(); ++j)
      std::printf("  %*s", static_cast<int>(heads[j].size()), cells[j].c_str());
    std::printf("\n");
  };
  const auto g = [](double x, const char* format = "%.4f") {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, x / polydem::kRecordG);
    return std::string(buf);
  };
  for (std::size_t i = 0; i < records.size(); ++i) {
    std::vector<std::string> cells;
    for (std::size_t j = 0; j < marks.size(); ++j) cells.push_back(g(at_marks.spectra[i].pseudo_acceleration[j]));
    row(table.names[i], g(table.spectra[i].peak_ground_acceleration), cells);
  }
  if (at_marks.suite) {
    std::vector<std::string> cells;
    for (std::size_t j = 0; j < marks.size(); ++j) {
      char beta[32];
      std::snprintf(beta, sizeof beta, " (beta %.3f)", at_marks.suite->dispersion[j]);
      cells.push_back(g(at_marks.suite->median_pseudo_acceleration[j]) + beta);
    }
    row("median", "", cells);
  }
  std::printf("wrote %s/spectra.csv, %s/marks.csv\n", a.out.c_str(), a.out.c_str());
  if (a.no_plot) return 0;
  std::fflush(stdout);
  if (!plot(a.out, damping, title)) {
    std::cerr << "polydem analytic spectrum: the plot was not drawn (scripts/plot_spectrum.py with /usr/bin/python3 "
                 "and matplotlib); the CSV files are written\n";
    return 1;
  }
  std::printf("wrote %s/spectrum.png\n", a.out.c_str());
  return 0;
}

}  // namespace

AnalyticModel add_spectrum_model(CLI::App& app) {
  auto args = std::make_shared<SpectrumArgs>();
  auto* c = app.add_subcommand("spectrum",
                               "Elastic response spectra (PSA, PSV, Sd) of records or a record suite, exact for "
                               "piecewise-linear acceleration (Nigam & Jennings 1969; docs/records.md)");
  c->add_option("records", args->records, "Record files (PEER .AT2, ESM .ASC, two-column .csv with its unit)");
  c->add_option("--suite", args->suite, "A record suite file (TOML, docs/records.md)")->option_text("FILE");
  c->add_option("--damping", args->damping_text, "Damping ratio in [0, 1)")->option_text("NUMBER=0.05");
  c->add_option("--periods", args->periods_text, "Periods, s, e.g. 0.05,0.1,0.2 (default: 100 from 0.01 to 5 s)")
      ->allow_extra_args(false)
      ->option_text("T[,T...]");
  c->add_option("--mark-period,--mark_period", args->marks_text,
                "Mark NAME=T (s) on the plot and tabulate it; repeatable (default: spire and tower)")
      ->allow_extra_args(false)
      ->option_text("NAME=T");
  c->add_option("--baseline-order,--baseline_order", args->baseline_text,
                "Polynomial baseline correction of the record files, order 0 to 4 (default: none)")
      ->option_text("N");
  c->add_option("--length-scale,--length_scale", args->length_scale_text,
                "Length scale lambda of a reduced model: record times times sqrt(lambda)")
      ->option_text("NUMBER");
  c->add_option("--out", args->out, "Directory for spectra.csv, marks.csv and spectrum.png")->option_text("DIR");
  c->add_flag("--no-plot,--no_plot", args->no_plot, "Write the CSV files only");
  return {c, [args] { return run(*args); }};
}
