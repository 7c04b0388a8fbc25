#include "benchmarks/bench_util.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace polydem::bench {

namespace {

std::string first_line_of(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const auto start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? std::string() : line.substr(start);
  }
  return "unknown";
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

}  // namespace

Machine this_machine() {
  Machine m;
  m.logical_cpus = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  m.cpu_model = cpu_model();
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  m.date_utc = buf;
  m.compiler = __VERSION__;
#ifdef NDEBUG
  m.build = "Release (NDEBUG)";
#else
  m.build = "assertions on (not Release)";
#endif
  m.load_average = first_line_of("/proc/loadavg");
  return m;
}

std::string engine_version(int argc, char** argv) {
  std::string label = option(argc, argv, "--engine", "");
  if (!label.empty()) return label;
  const std::string cmd = std::string("git -C '") + POLYDEM_SOURCE_DIR + "' describe --always --dirty 2>/dev/null";
  if (FILE* pipe = popen(cmd.c_str(), "r")) {
    char buf[128];
    while (std::fgets(buf, sizeof buf, pipe)) label += buf;
    pclose(pipe);
  }
  while (!label.empty() && (label.back() == '\n' || label.back() == ' ')) label.pop_back();
  return label.empty() ? "unknown" : label;
}

std::string csv_header_comment(const Machine& m, const std::string& what) {
  std::ostringstream o;
  o << "# " << what << "\n"
    << "# machine: nproc = " << m.logical_cpus << ", CPU: " << m.cpu_model << "\n"
    << "# polydem: " << m.engine << "\n"
    << "# date: " << m.date_utc << ", compiler: g++ " << m.compiler << ", build: " << m.build << "\n"
    << "# load average at start (/proc/loadavg): " << m.load_average
    << " (other work on the machine makes wall times noisy)\n";
  return o.str();
}

Table::Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void Table::add_row(std::vector<std::string> cells) {
  if (cells.size() != columns_.size()) throw std::logic_error("Table::add_row: wrong number of cells");
  rows_.push_back(std::move(cells));
}

std::string Table::markdown() const {
  std::vector<std::size_t> width(columns_.size(), 3);
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    width[c] = std::max(width[c], columns_[c].size());
    for (const auto& r : rows_) width[c] = std::max(width[c], r[c].size());
  }
  std::ostringstream o;
  auto line = [&](const std::vector<std::string>& cells) {
    o << "|";
    for (std::size_t c = 0; c < cells.size(); ++c) {
      o << " " << cells[c] << std::string(width[c] - cells[c].size(), ' ') << " |";
    }
    o << "\n";
  };
  line(columns_);
  o << "|";
  for (std::size_t c = 0; c < columns_.size(); ++c) o << std::string(width[c] + 2, '-') << "|";
  o << "\n";
  for (const auto& r : rows_) line(r);
  return o.str();
}

std::string Table::csv() const {
  std::ostringstream o;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) o << (c ? "," : "") << csv_cell(cells[c]);
    o << "\n";
  };
  line(columns_);
  for (const auto& r : rows_) line(r);
  return o.str();
}

std::string fmt(double value, int significant) {
  if (std::isnan(value)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, value);
  return buf;
}

std::string fmt_fixed(double value, int decimals) {
  if (std::isnan(value)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0) || !std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++n;
  }
  if (n < 2) return std::nan("");
  const double den = n * sxx - sx * sx;
  return den != 0 ? (n * sxy - sx * sy) / den : std::nan("");
}

std::string option(int argc, char** argv, const std::string& name, const std::string& fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (name == argv[i]) return argv[i + 1];
  return fallback;
}

bool flag(int argc, char** argv, const std::string& name) {
  for (int i = 1; i < argc; ++i)
    if (name == argv[i]) return true;
  return false;
}

}  // namespace polydem::bench
