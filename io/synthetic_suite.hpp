// The files of `polydem analytic synthetic` (docs/fragility.md, "Synthetic
// records"): one two-column CSV per record, in m/s² ("# units: m/s2"), a
// record-suite TOML naming them, and a table of each record's targets and
// measures; the same as JSON for Python.
#pragma once

#include "analytical/synthetic_ground_motion.hpp"
#include "io/json.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace polydem {

struct SyntheticSuiteRun {
  analytical::EarthquakeScenario scenario;
  std::uint64_t seed = 1;
  analytical::SyntheticOptions options;
  std::vector<analytical::SyntheticRecord> records;
};

// Writes DIR/<name>.csv for every record, DIR/suite.toml and
// DIR/records.csv (creating DIR), each atomically.
void write_synthetic_suite(const std::string& dir, const SyntheticSuiteRun& run);

// The scenario, options and per record its name, seed, targets and
// measures; with `histories`, its acceleration samples too.
Json synthetic_suite_json(const SyntheticSuiteRun& run, bool histories);

}  // namespace polydem
