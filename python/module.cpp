// polydem._polydem: errors, scenes (parsed by the deck reader), deck keys.
// Runs are in run.cpp, studies in studies.cpp, the analytical models in
// analytical.cpp.
#include "python/bindings.hpp"

#include "io/deck.hpp"
#include "run/scene_error.hpp"
#include "integrators/simulation.hpp"

#include <pybind11/stl.h>

namespace polydem::python {

namespace {

void set_python_error(const char* cls, const std::string& message) {
  py::object type = py::module_::import("polydem.errors").attr(cls);
  PyErr_SetString(type.ptr(), message.c_str());
}

// The library's exceptions as polydem.errors classes. A SceneError gets here
// only where no spec was at hand to locate it in the deck (run.cpp locates
// those of a run).
void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const DeckError& e) {
    set_python_error("DeckError", e.what());
  } catch (const SceneError& e) {
    set_python_error("SceneError", e.what());
  } catch (const GeometryError& e) {
    set_python_error("GeometryError", e.what());
  } catch (const InstabilityError& e) {
    set_python_error("InstabilityError", e.what());
  } catch (const StateFormatError& e) {
    set_python_error("PolydemError", e.what());
  }
}

}  // namespace

void raise_python(const char* cls, const std::string& message) {
  set_python_error(cls, message);
  throw py::error_already_set();
}

}  // namespace polydem::python

PYBIND11_MODULE(_polydem, m) {
  using namespace polydem;
  using namespace polydem::python;
  m.doc() = "polydem's C++ half; import polydem instead (docs/python.md)";
  py::register_exception_translator(&translate);
  m.attr("version") = POLYDEM_VERSION;
  m.attr("default_deck_name") = kDefaultDeckName;

  py::class_<Scene>(m, "ParsedScene", "A deck read and validated (core/scene_spec.hpp SceneSpec)")
      .def_property_readonly("deck_text", [](const Scene& s) { return s.spec.deck_text; })
      .def_property_readonly("deck_path", [](const Scene& s) { return s.spec.deck_path; })
      .def_property_readonly("name", [](const Scene& s) { return s.name; })
      .def_property_readonly("overrides", [](const Scene& s) { return s.overrides; })
      .def_property_readonly("warnings", [](const Scene& s) { return s.spec.warnings; })
      .def_property_readonly("end_time", [](const Scene& s) { return s.spec.simulation.end_time; })
      .def_property_readonly("block_names", [](const Scene& s) {
        std::vector<std::string> names;
        for (const BlockSpec& b : s.spec.blocks) names.push_back(b.name);
        return names;
      });

  // Reading is pure C++ on the caller's data: the GIL is released (a large
  // [spire] takes a while to build).
  m.def(
      "parse_deck",
      [](const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
        Scene s;
        {
          py::gil_scoped_release nogil;
          s.spec = parse_deck(text, name, overrides);
        }
        s.name = name;
        s.overrides = overrides;
        return s;
      },
      py::arg("text"), py::arg("name"), py::arg("overrides") = std::vector<std::string>{});
  m.def(
      "read_deck",
      [](const std::string& path, const std::vector<std::string>& overrides) {
        Scene s;
        {
          py::gil_scoped_release nogil;
          s.spec = read_deck(path, overrides);
        }
        s.name = path;
        s.overrides = overrides;
        return s;
      },
      py::arg("path"), py::arg("overrides") = std::vector<std::string>{});
  m.def("default_deck_text", []() { return default_deck_text(); });
  m.def("deck_keys", &deck_keys, "Every deck key, as 'section.key' (arrays of tables unindexed)");

  bind_run(m);
  bind_studies(m);
  bind_analytical(m);
  bind_spectra(m);
}
