// The Python module's C++ half (polydem._polydem), shared by its sources.
//
// The module is thin: scenes are parsed by the deck reader (io/deck.hpp),
// runs are run/run_scene.hpp's SceneRun, outputs io/run_outputs.hpp, studies
// studies/, the models of `polydem analytic` analytical/ and studies/. The Python half (python/polydem/) adds the scene builder, the
// loop with callbacks and progress, and the exception classes; it is what
// users import (docs/python.md).
//
// Errors reach Python as the classes of polydem/errors.py: raise_python()
// raises one by name, translate_errors() maps the library's exceptions
// (DeckError, GeometryError, InstabilityError, StateFormatError) to them.
#pragma once

#include "core/scene_spec.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace polydem::python {

namespace py = pybind11;

// Raises polydem.errors.<cls>(message) and throws py::error_already_set.
[[noreturn]] void raise_python(const char* cls, const std::string& message);

// A parsed scene: the SceneSpec and what it was parsed from (the deck text,
// the name messages give it, the overrides), so that studies can apply
// their own overrides to the same text.
struct Scene {
  SceneSpec spec;
  std::string name;                    // the deck's path, or a name for text
  std::vector<std::string> overrides;  // "key=value", as --set
};

void bind_run(py::module_& m);
void bind_studies(py::module_& m);
void bind_analytical(py::module_& m);
void bind_spectra(py::module_& m);

}  // namespace polydem::python
