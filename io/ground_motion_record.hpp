// Ground-motion records: base accelerations read from PEER NGA .AT2 files,
// ESM/ITACA ASCII files and two-column CSV, converted to m/s². The formats,
// units and error messages are described in docs/records.md.
//
// Units: a PEER file holds acceleration in units of standard gravity g; an
// ESM file names its unit in the header (UNITS: cm/s^2); a two-column file
// must declare its unit (g, m/s² or cm/s²) in its header or in a comment,
// and one that does not is refused rather than guessed. g is converted with
// kRecordG = 9.80665 m/s² (core/units.hpp) (the conventional value, CGPM
// 1901, the one PEER and most strong-motion agencies use), times the
// caller's `scale` (e.g. 2.0 to double the record).
//
// Every input error throws RecordError with "FILE:LINE: what".
#pragma once

#include "core/units.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace polydem {


struct GroundMotionRecord {
  std::vector<double> time;          // s, strictly increasing
  std::vector<double> acceleration;  // m/s², already scaled
  double dt = 0;                     // s: AT2 DT, ESM SAMPLING_INTERVAL_S, or the smallest CSV step
  std::string source;                // the file (or name) it came from
};

// Bad input. line is 1-based; 0 when the error is about the whole file
// (cannot open, unknown extension): the message is then "FILE: what".
struct RecordError : std::runtime_error {
  RecordError(const std::string& file, int line, const std::string& what);
  std::string file;
  int line = 0;
};

// The acceleration units a record may declare, and their size in m/s².
enum class AccelerationUnit { g, m_per_s2, cm_per_s2 };
double metres_per_second_squared(AccelerationUnit unit);
// "g"; "m/s2", "m/s^2", "m/s²", "m/s/s", "m_s2"; "cm/s2", "cm/s^2", "cm/s²",
// "cm/s/s", "cm_s2", "gal" (any case); nullopt for anything else.
std::optional<AccelerationUnit> acceleration_unit_named(std::string_view text);

// Reads a record, picking the format by extension (any case): ".AT2" = PEER
// NGA, ".ASC" = ESM/ITACA ASCII, ".csv" = two columns with a declared unit.
GroundMotionRecord read_record(const std::string& path, double scale = 1.0);

// PEER NGA .AT2 text: four header lines (the fourth gives NPTS and DT, as
// "NPTS=  1560, DT= 0.02000 SEC" or "1560  0.0200  NPTS, DT"), then NPTS
// values in g, any number per line. time[i] = i·DT.
GroundMotionRecord parse_at2(const std::string& text, const std::string& name_for_messages, double scale = 1.0);

// ESM/ITACA ASCII (the Engineering Strong-Motion database's .ASC): header
// lines "KEY: value" (EVENT_NAME, ..., USER5), then NDATA values, any number
// per line. Read from the header: SAMPLING_INTERVAL_S (> 0), NDATA (> 0) and
// UNITS (cm/s^2, m/s^2 or g); a DATA_TYPE other than ACCELERATION is refused.
// time[i] = i·SAMPLING_INTERVAL_S.
GroundMotionRecord parse_esm(const std::string& text, const std::string& name_for_messages, double scale = 1.0);

// Two columns time (s), acceleration, separated by a comma or whitespace;
// blank lines and lines starting with '#' are skipped. The acceleration's
// unit must be declared, in an optional header line naming the columns
// ("time_s,acceleration_g", "time_s,acceleration_m_s2",
// "time (s), acceleration (cm/s2)") or in a comment before the data
// ("# units: g"); both may be given if they agree. Times strictly
// increasing, at least two rows; dt = smallest step.
GroundMotionRecord parse_csv_record(const std::string& text, const std::string& name_for_messages,
                                    double scale = 1.0);

// Acceleration (m/s²) at time t by linear interpolation; 0 before the first
// and after the last sample (the ground is at rest outside the record).
double sample(const GroundMotionRecord& record, double t);

// Largest |acceleration| in m/s² (0 for an empty record).
double peak_acceleration(const GroundMotionRecord& record);

}  // namespace polydem
