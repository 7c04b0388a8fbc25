// Ground-motion records: base accelerations read from PEER NGA .AT2 files or
// two-column CSV, converted to m/s². The formats, units and error messages are
// described in docs/records.md.
//
// Units: both formats hold acceleration in units of standard gravity g; it is
// converted with kRecordG = 9.80665 m/s² (core/units.hpp) (the conventional value,
// CGPM 1901, the one PEER and most strong-motion agencies use), times the
// caller's `scale` (e.g. 2.0 to double the record).
//
// Every input error throws RecordError with "FILE:LINE: what".
#pragma once

#include "core/units.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace polydem {


struct GroundMotionRecord {
  std::vector<double> time;          // s, strictly increasing
  std::vector<double> acceleration;  // m/s², already scaled
  double dt = 0;                     // s: AT2 DT, or the smallest CSV step
  std::string source;                // the file (or name) it came from
};

// Bad input. line is 1-based; 0 when the error is about the whole file
// (cannot open, unknown extension): the message is then "FILE: what".
struct RecordError : std::runtime_error {
  RecordError(const std::string& file, int line, const std::string& what);
  std::string file;
  int line = 0;
};

// Reads a record, picking the format by extension: ".AT2" (any case) = PEER
// NGA, ".csv" (any case) = two columns time_s, acceleration_g.
GroundMotionRecord read_record(const std::string& path, double scale = 1.0);

// PEER NGA .AT2 text: four header lines (the fourth gives NPTS and DT, as
// "NPTS=  1560, DT= 0.02000 SEC" or "1560  0.0200  NPTS, DT"), then NPTS
// values in g, any number per line. time[i] = i·DT.
GroundMotionRecord parse_at2(const std::string& text, const std::string& name_for_messages, double scale = 1.0);

// Two columns time (s), acceleration (g), separated by a comma or whitespace;
// an optional header line naming them (e.g. "time_s,acceleration_g"); blank
// lines and lines starting with '#' are skipped. Times strictly increasing,
// at least two rows; dt = smallest step.
GroundMotionRecord parse_csv_record(const std::string& text, const std::string& name_for_messages,
                                    double scale = 1.0);

// Acceleration (m/s²) at time t by linear interpolation; 0 before the first
// and after the last sample (the ground is at rest outside the record).
double sample(const GroundMotionRecord& record, double t);

// Largest |acceleration| in m/s² (0 for an empty record).
double peak_acceleration(const GroundMotionRecord& record);

}  // namespace polydem
