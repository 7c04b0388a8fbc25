#include "studies/sweep_grid.hpp"

#include "core/number_text.hpp"


#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace polydem {
namespace {

double parse_number(const std::string& text, const std::string& arg, const std::string& option) {
  double x = 0;
  const char* first = text.data();
  const char* last = first + text.size();
  const auto r = std::from_chars(first, last, x);
  if (text.empty() || r.ec != std::errc() || r.ptr != last || !std::isfinite(x))
    throw std::invalid_argument(option + " " + arg + ": '" + text + "' is not a finite number");
  return x;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t at = s.find(sep, from);
    out.push_back(s.substr(from, at - from));
    if (at == std::string::npos) return out;
    from = at + 1;
  }
}

}  // namespace

double value_of(const SweepPoint& p, const std::string& key) {
  for (const auto& [k, v] : p.values)
    if (k == key) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

std::string value_text(double x) { return std::isfinite(x) ? shortest_text(x) : "null"; }

double lattice_value(double start, double stop, long i, long n) {
  if (n <= 1 || i == 0) return start;
  if (i == n - 1) return stop;
  const double x = start + (stop - start) * static_cast<double>(i) / static_cast<double>(n - 1);
  // Rounded to 12 significant digits, so 0.4:1.6:4 gives 1.2 and not
  // 1.2000000000000002 (in tables and in the deck the run sees).
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return std::strtod(buf, nullptr);
}

SweepAxis parse_axis(const std::string& arg, const std::string& option) {
  const std::size_t eq = arg.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == arg.size())
    throw std::invalid_argument(option + " " + arg + ": expected KEY=START:STOP:N or KEY=V1,V2,...");
  SweepAxis axis;
  axis.key = arg.substr(0, eq);
  const std::string spec = arg.substr(eq + 1);
  if (axis.key.find('.') == std::string::npos)
    throw std::invalid_argument(option + " " + arg + ": the key must name its section, e.g. ground_motion.period");
  if (spec.find(':') != std::string::npos) {
    const auto parts = split(spec, ':');
    if (parts.size() != 3)
      throw std::invalid_argument(option + " " + arg + ": a range is START:STOP:N (three parts)");
    const double start = parse_number(parts[0], arg, option);
    const double stop = parse_number(parts[1], arg, option);
    long n = 0;
    const auto r = std::from_chars(parts[2].data(), parts[2].data() + parts[2].size(), n);
    if (r.ec != std::errc() || r.ptr != parts[2].data() + parts[2].size() || n < 1 || n > 100000)
      throw std::invalid_argument(option + " " + arg + ": N must be a whole number from 1 to 100000");
    if (n > 1 && !(stop > start))
      throw std::invalid_argument(option + " " + arg + ": STOP must be above START");
    for (long i = 0; i < n; ++i) axis.values.push_back(lattice_value(start, stop, i, n));
  } else {
    for (const auto& v : split(spec, ',')) axis.values.push_back(parse_number(v, arg, option));
  }
  return axis;
}

std::vector<std::string> SweepPoint::overrides() const {
  std::vector<std::string> out = fixed;
  for (const auto& [key, value] : values) out.push_back(key + "=" + value_text(value));
  return out;
}

std::string SweepPoint::label() const {
  std::string out;
  for (const auto& [key, value] : values) {
    if (!out.empty()) out += ' ';
    out += key.substr(key.rfind('.') + 1) + "=" + value_text(value);
  }
  return out;
}

SweepPoint SweepPoint::with(const std::string& key, double value) const {
  SweepPoint p = *this;
  p.values.emplace_back(key, value);
  return p;
}

std::vector<SweepPoint> grid_points(const std::vector<SweepAxis>& axes) {
  std::vector<SweepPoint> points{SweepPoint{}};
  for (const SweepAxis& axis : axes) {
    std::vector<SweepPoint> next;
    next.reserve(points.size() * axis.values.size());
    for (const SweepPoint& p : points)
      for (double v : axis.values) next.push_back(p.with(axis.key, v));
    points = std::move(next);
  }
  return points;
}

}  // namespace polydem
