// polydem._polydem: records and their response spectra (docs/records.md) --
// read_record (a record file as arrays), record_suite (a suite file with
// every record's samples), response_spectrum (one record given as arrays)
// and spectra (record files or a suite, with the suite's median and
// dispersion): the numbers `polydem analytic spectrum` writes, as numpy
// arrays. polydem/analytical.py re-exports them. A record or suite the
// readers refuse raises polydem.errors.DeckError with the file and line.
#include "python/bindings.hpp"

#include "analytical/response_spectrum.hpp"
#include "io/deck.hpp"
#include "io/ground_motion_record.hpp"
#include "io/record_processing.hpp"
#include "io/record_spectra.hpp"
#include "io/record_suite.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>

namespace polydem::python {

namespace pa = analytical;

namespace {

py::array_t<double> array(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }

// The readers' and the spectra's bad input as polydem.errors.DeckError.
template <class F>
auto checked(F&& f) {
  try {
    return f();
  } catch (const RecordError& e) {
    raise_python("DeckError", e.what());
  } catch (const std::invalid_argument& e) {
    raise_python("DeckError", e.what());
  }
}

py::dict spectrum_dict(const pa::ResponseSpectrum& s) {
  py::dict d;
  d["period"] = array(s.period);
  d["psa"] = array(s.pseudo_acceleration);
  d["psv"] = array(s.pseudo_velocity);
  d["sd"] = array(s.displacement);
  d["pga"] = s.peak_ground_acceleration;
  d["damping"] = s.damping;
  return d;
}

std::vector<double> periods_or_default(const std::optional<std::vector<double>>& periods) {
  return periods ? *periods : pa::default_spectrum_periods();
}

}  // namespace

void bind_spectra(py::module_& m) {
  m.def(
      "read_record",
      [](const std::string& path, double scale, std::optional<int> baseline_order, double length_scale) {
        return checked([&] {
          GroundMotionRecord r = read_record(path, scale);
          if (length_scale != 1.0) scale_record_time(r.time, length_scale);
          if (baseline_order) correct_baseline(r.time, r.acceleration, *baseline_order);
          return py::make_tuple(array(r.time), array(r.acceleration));
        });
      },
      "A record file (PEER .AT2, ESM .ASC, two-column .csv with its unit) as (time [s], acceleration [m/s²]) arrays, "
      "times scale; baseline_order (0-4) corrects it, length_scale (lambda) multiplies its times by sqrt(lambda).",
      py::arg("path"), py::arg("scale") = 1.0, py::arg("baseline_order") = py::none(), py::arg("length_scale") = 1.0);

  m.def(
      "record_suite",
      [](const std::string& path) {
        const RecordSuite s = read_record_suite(path);
        py::list records;
        for (const SuiteRecord& r : s.records) {
          py::list components;
          for (const SuiteComponent& c : r.components) {
            py::dict d;
            d["file"] = c.record_path;
            d["direction"] = py::make_tuple(c.direction.x(), c.direction.y(), c.direction.z());
            d["scale"] = c.scale;
            d["time"] = array(c.time);
            d["acceleration"] = array(c.acceleration);
            components.append(d);
          }
          py::dict d;
          d["name"] = r.name;
          d["components"] = components;
          records.append(d);
        }
        py::dict d;
        d["name"] = s.name;
        d["records"] = records;
        return d;
      },
      "A record suite file (TOML) as a dict: name, records[i] with name and components[j] (file, direction, scale, "
      "time, acceleration in m/s² before scale).",
      py::arg("path"));

  m.def(
      "response_spectrum",
      [](const std::vector<double>& time, const std::vector<double>& acceleration,
         const std::optional<std::vector<double>>& periods, double damping) {
        return checked([&] {
          return spectrum_dict(pa::response_spectrum(time, acceleration, periods_or_default(periods), damping));
        });
      },
      "The elastic spectra of one record given as arrays (s, m/s²): a dict of period, psa (m/s²), psv (m/s), sd (m), "
      "pga, damping. periods: default 100 from 0.01 to 5 s.",
      py::arg("time"), py::arg("acceleration"), py::arg("periods") = py::none(), py::arg("damping") = 0.05);

  m.def(
      "spectra",
      [](const std::vector<std::string>& records, const std::optional<std::string>& suite,
         const std::optional<std::vector<double>>& periods, double damping, std::optional<int> baseline_order,
         double length_scale) {
        if (records.empty() == !suite) raise_python("DeckError", "give record files or suite= (one of the two)");
        return checked([&] {
          const std::vector<NamedRecord> named =
              suite ? records_of_suite(read_record_suite(*suite))
                    : records_of_files(records, baseline_order.value_or(-1), length_scale);
          const SpectraTable t = record_spectra(named, periods_or_default(periods), damping);
          py::dict d;
          d["names"] = t.names;
          py::list spectra;
          for (const auto& s : t.spectra) spectra.append(spectrum_dict(s));
          d["spectra"] = spectra;
          if (t.suite) {
            d["median_psa"] = array(t.suite->median_pseudo_acceleration);
            d["median_psv"] = array(t.suite->median_pseudo_velocity);
            d["median_sd"] = array(t.suite->median_displacement);
            d["dispersion"] = array(t.suite->dispersion);
          }
          return d;
        });
      },
      "The spectra of record files or of suite=FILE, as polydem analytic spectrum computes them: a dict of names, "
      "spectra (one response_spectrum dict each) and, for two records or more, median_psa, median_psv, median_sd "
      "and dispersion (of ln PSA).",
      py::arg("records") = std::vector<std::string>{}, py::arg("suite") = py::none(), py::arg("periods") = py::none(),
      py::arg("damping") = 0.05, py::arg("baseline_order") = py::none(), py::arg("length_scale") = 1.0);
}

}  // namespace polydem::python
