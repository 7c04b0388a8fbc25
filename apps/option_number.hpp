// A number given on the command line: read by std::stod, correctly rounded
// (CLI11 2.1 reads a double through long double, which can round twice),
// the whole word, and finite. Shared by the subcommands of polydem analytic.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace polydem {

// Throws std::invalid_argument "--NAME expects a number, got 'TEXT'".
inline double read_option_number(const std::string& name, const std::string& text) {
  try {
    std::size_t pos = 0;
    const double v = std::stod(text, &pos);
    if (pos != text.size() || !std::isfinite(v)) throw std::invalid_argument("");
    return v;
  } catch (const std::exception&) {
    throw std::invalid_argument("--" + name + " expects a number, got '" + text + "'");
  }
}

// The same, > 0.
inline double read_positive_option(const std::string& name, const std::string& text) {
  const double v = read_option_number(name, text);
  if (!(v > 0.0)) throw std::invalid_argument("--" + name + " must be > 0");
  return v;
}

// The same, an integer in [lo, hi] (read as a number, so "2.5" is refused).
inline long long read_whole_option(const std::string& name, const std::string& text, long long lo, long long hi) {
  const double v = read_option_number(name, text);
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v))
    throw std::invalid_argument("--" + name + " must be an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]");
  return static_cast<long long>(v);
}

}  // namespace polydem
