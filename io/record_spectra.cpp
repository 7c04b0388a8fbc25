#include "io/record_spectra.hpp"

#include "core/units.hpp"
#include "io/ground_motion_record.hpp"
#include "io/record_processing.hpp"

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string_view>

namespace polydem {
namespace {

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// A name as a CSV column prefix: no commas, quotes or line breaks.
std::string column(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '_';
  return out;
}

// Appends the pieces (one call, no temporaries of temporaries).
void append(std::string& text, std::initializer_list<std::string_view> pieces) {
  for (const std::string_view p : pieces) text.append(p);
}

}  // namespace

std::vector<NamedRecord> records_of_files(const std::vector<std::string>& paths, int baseline_order,
                                          double length_scale) {
  std::vector<NamedRecord> out;
  std::map<std::string, int> seen;
  for (const std::string& path : paths) {
    GroundMotionRecord rec = read_record(path, 1.0);
    if (length_scale != 1.0) scale_record_time(rec.time, length_scale);
    if (baseline_order >= 0) correct_baseline(rec.time, rec.acceleration, baseline_order);
    std::string name = std::filesystem::path(path).stem().string();
    const int n = ++seen[name];
    if (n > 1) name.append("-").append(std::to_string(n));
    out.push_back({name, std::move(rec.time), std::move(rec.acceleration)});
  }
  return out;
}

std::vector<NamedRecord> records_of_suite(const RecordSuite& suite) {
  std::vector<NamedRecord> out;
  for (const SuiteRecord& r : suite.records) {
    for (std::size_t k = 0; k < r.components.size(); ++k) {
      const SuiteComponent& c = r.components[k];
      NamedRecord n{r.components.size() == 1 ? r.name : r.name + "." + std::to_string(k + 1), c.time, c.acceleration};
      for (double& a : n.acceleration) a *= c.scale;
      out.push_back(std::move(n));
    }
  }
  return out;
}

SpectraTable record_spectra(const std::vector<NamedRecord>& records, const std::vector<double>& periods,
                            double damping) {
  SpectraTable t;
  for (const NamedRecord& r : records) {
    t.names.push_back(r.name);
    t.spectra.push_back(analytical::response_spectrum(r.time, r.acceleration, periods, damping));
  }
  if (t.spectra.size() > 1) t.suite = analytical::suite_spectrum(t.spectra);
  return t;
}

std::string spectra_csv(const SpectraTable& t) {
  std::string text = "period_s";
  for (const std::string& name : t.names)
    for (const char* quantity : {".psa_g", ".psv_m_s", ".sd_m"}) append(text, {",", column(name), quantity});
  if (t.suite) text += ",median.psa_g,median.psv_m_s,median.sd_m,dispersion";
  text += "\n";
  const std::vector<double>& periods = t.spectra.front().period;
  for (std::size_t j = 0; j < periods.size(); ++j) {
    text += number(periods[j]);
    for (const analytical::ResponseSpectrum& s : t.spectra)
      append(text, {",", number(s.pseudo_acceleration[j] / kRecordG), ",", number(s.pseudo_velocity[j]), ",",
                    number(s.displacement[j])});
    if (t.suite)
      append(text, {",", number(t.suite->median_pseudo_acceleration[j] / kRecordG), ",",
                    number(t.suite->median_pseudo_velocity[j]), ",", number(t.suite->median_displacement[j]), ",",
                    number(t.suite->dispersion[j])});
    text += "\n";
  }
  return text;
}

std::string marks_csv(const std::vector<PeriodMark>& marks, const SpectraTable& t) {
  std::string text = "mark,period_s";
  for (const std::string& name : t.names) append(text, {",", column(name), ".psa_g"});
  if (t.suite) text += ",median.psa_g,dispersion";
  text += "\n";
  for (std::size_t j = 0; j < marks.size(); ++j) {
    append(text, {column(marks[j].name), ",", number(marks[j].period)});
    for (const analytical::ResponseSpectrum& s : t.spectra)
      append(text, {",", number(s.pseudo_acceleration[j] / kRecordG)});
    if (t.suite)
      append(text,
             {",", number(t.suite->median_pseudo_acceleration[j] / kRecordG), ",", number(t.suite->dispersion[j])});
    text += "\n";
  }
  return text;
}

}  // namespace polydem
