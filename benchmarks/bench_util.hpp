// Small helpers shared by the benchmark runners: the machine a result came
// from, markdown tables on stdout, CSV files with a commented header, and the
// least-squares slope on log-log axes used for observed orders of convergence.
//
// The runners are plain programs rather than Google Benchmark fixtures: each
// "benchmark" is a whole scene whose interesting output is an error or a rate
// (not a per-iteration time); the CSV they write is what docs/benchmarks.md
// shows (scripts/doc_tables.py).
#pragma once

#include <string>
#include <vector>

namespace polydem::bench {

// Where and when a result was measured.
struct Machine {
  int logical_cpus = 0;      // what `nproc` reports
  std::string cpu_model;     // first "model name" of /proc/cpuinfo
  std::string date_utc;      // ISO 8601
  std::string compiler;      // __VERSION__
  std::string build;         // "Release (NDEBUG)" or "assertions on"
  std::string load_average;  // /proc/loadavg at the time of the call (other work on the machine)
  std::string engine;        // which polydem was measured (commit), see engine_version()
};
Machine this_machine();

// The polydem version measured: `--engine LABEL` if given, else
// `git describe --always --dirty` of the source tree, else "unknown".
std::string engine_version(int argc, char** argv);

// The "# ..." lines that open every CSV: machine, date, and `what`.
std::string csv_header_comment(const Machine& m, const std::string& what);

// A table printed as GitHub markdown (so it can be pasted into docs) and
// written as CSV.
class Table {
 public:
  explicit Table(std::vector<std::string> columns);
  void add_row(std::vector<std::string> cells);  // as many cells as columns
  std::string markdown() const;
  std::string csv() const;                        // header row then rows; cells quoted when needed
  std::size_t rows() const { return rows_.size(); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

// Number formatting for the tables: `significant` significant digits in %g
// style; "nan" for NaN.
std::string fmt(double value, int significant = 4);
std::string fmt_fixed(double value, int decimals);

// Least-squares slope of log(y) against log(x) over the points with x, y > 0
// and finite (NaN when fewer than two such points).
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

// The value of "--name VALUE" in argv, or `fallback`.
std::string option(int argc, char** argv, const std::string& name, const std::string& fallback);
bool flag(int argc, char** argv, const std::string& name);

}  // namespace polydem::bench
