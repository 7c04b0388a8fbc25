// Response spectra of record files and suites (analytical/response_spectrum.hpp
// on records read by io/ground_motion_record.hpp and io/record_suite.hpp),
// and the CSV tables `polydem analytic spectrum` writes (docs/records.md,
// "Response spectra").
#pragma once

#include "analytical/response_spectrum.hpp"
#include "core/record_suite.hpp"

#include <optional>
#include <string>
#include <vector>

namespace polydem {

// One acceleration history with a name: m/s², already scaled.
struct NamedRecord {
  std::string name;
  std::vector<double> time, acceleration;
};

// Record files, each one record named after its file stem (a repeated stem
// gets "-2", "-3", ...), baseline-corrected (order ≥ 0) and time-scaled as
// asked. Throws RecordError for a record the readers refuse.
std::vector<NamedRecord> records_of_files(const std::vector<std::string>& paths, int baseline_order = -1,
                                          double length_scale = 1.0);

// Every component of every record of the suite, times its scale; a record
// of several components gives "NAME.1", "NAME.2", ...
std::vector<NamedRecord> records_of_suite(const RecordSuite& suite);

// A named period drawn on the spectrum's plot and tabulated (the spire's,
// the tower's).
struct PeriodMark {
  std::string name;
  double period = 0.0;  // s, > 0
};

struct SpectraTable {
  std::vector<std::string> names;                         // one per record
  std::vector<analytical::ResponseSpectrum> spectra;      // one per record
  std::optional<analytical::SuiteSpectrum> suite;         // with two records or more
};

// The spectra of every record at `periods` with damping ξ (and the suite's
// median and dispersion with two records or more). Throws
// std::invalid_argument for a bad period or damping.
SpectraTable record_spectra(const std::vector<NamedRecord>& records, const std::vector<double>& periods,
                            double damping);

// spectra.csv: period_s, then per record NAME.psa_g, NAME.psv_m_s, NAME.sd_m
// (pseudo-acceleration in g = 9.80665 m/s², pseudo-velocity, displacement),
// then median.psa_g, median.psv_m_s, median.sd_m, dispersion for a suite.
std::string spectra_csv(const SpectraTable& table);

// marks.csv: mark, period_s, then NAME.psa_g per record and median.psa_g,
// dispersion for a suite: `table` computed at the marks' periods.
std::string marks_csv(const std::vector<PeriodMark>& marks, const SpectraTable& table);

}  // namespace polydem
