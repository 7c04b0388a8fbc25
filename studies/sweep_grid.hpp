// The points of a sweep: deck keys and the values each takes.
//
//   --vary ground_motion.period=0.5:2.0:7       7 values, both ends included
//   --vary ground_motion.direction_deg=0,22.5,45 a list
//
// A full grid is the Cartesian product of the axes, the first axis varying
// slowest. Each point becomes `--set key=value` overrides of the deck, with
// values written in their shortest round-trip form so that the same point
// always gets the same text (and so the same directory on a resumed sweep).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace polydem {

struct SweepAxis {
  std::string key;             // deck key, e.g. "ground_motion.acceleration_g"
  std::vector<double> values;  // in the order given
};

// Parses "KEY=START:STOP:N" or "KEY=V1,V2,...". Throws std::invalid_argument
// naming the argument and what is wrong with it.
SweepAxis parse_axis(const std::string& arg, const std::string& option = "--vary");

// START + (STOP − START)·i/(N − 1) rounded to 12 significant digits: the
// ends exactly, decimal steps as written, the same bits every time.
double lattice_value(double start, double stop, long i, long n);

struct SweepPoint {
  std::vector<std::pair<std::string, double>> values;  // key, value
  // Overrides set before the values, as written ("key=value"): what is not
  // one number, e.g. an IDA's ground motion (studies/ida.hpp). Usually none.
  std::vector<std::string> fixed = {};

  std::vector<std::string> overrides() const;  // fixed, then "key=value"
  std::string label() const;                   // "period=0.5 acceleration_g=0.6" (last part of each key)
  SweepPoint with(const std::string& key, double value) const;
};

// The point's value of `key` (NaN when it has none).
double value_of(const SweepPoint& p, const std::string& key);

// The Cartesian product of the axes (one point with no values when empty).
std::vector<SweepPoint> grid_points(const std::vector<SweepAxis>& axes);

// Shortest text that reads back to the same double.
std::string value_text(double x);

}  // namespace polydem
