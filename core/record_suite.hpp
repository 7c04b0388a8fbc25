// A suite of ground-motion records, as an analysis of many runs uses it
// (response spectra, incremental dynamic analysis): each record one or more
// components, each component a file, a direction and a scale factor. Plain
// data: io/record_suite.hpp reads it from a suite file (docs/records.md,
// "Record suites"), with every record's samples, so a run never opens a
// file.
#pragma once

#include "geometry/polyhedron.hpp"

#include <string>
#include <vector>

namespace polydem {

struct SuiteComponent {
  std::string record_path;  // the record file, resolved against the suite file's directory
  Vec3 direction{1.0, 0.0, 0.0};  // unit
  double scale = 1.0;             // > 0, multiplies the acceleration
  // The record as read and processed (baseline correction, time scaling):
  // time (s) and acceleration (m/s², before `scale`).
  std::vector<double> time, acceleration;
  int line = 0;  // where the component is given in the suite file
};

struct SuiteRecord {
  std::string name;  // unique in the suite; the first component's file stem by default
  std::vector<SuiteComponent> components;
  int line = 0;
};

struct RecordSuite {
  std::string name;
  std::string path;         // the suite file
  int baseline_order = -1;  // polynomial baseline correction of every record; -1: none
  double length_scale = 1.0;  // λ: times multiplied by √λ
  std::vector<SuiteRecord> records;
};

}  // namespace polydem
