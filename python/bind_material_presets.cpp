// The named published materials (include/puncture/material_presets.hpp): MaterialPreset,
// material_presets() and material_preset(name).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "puncture/material_presets.hpp"

namespace puncture::python {

void bind_material_presets(py::module_& m) {
  py::class_<MaterialPreset>(
      m, "MaterialPreset", "A material from a published fit, with its source")
      .def_readonly("name", &MaterialPreset::name)
      .def_readonly("description", &MaterialPreset::description)
      .def_readonly("source", &MaterialPreset::source, "the publication and where in it")
      .def_readonly("material", &MaterialPreset::material, "the Material (law and parameters)")
      .def("__repr__", [](const MaterialPreset& p) { return "MaterialPreset('" + p.name + "')"; });
  m.def("material_presets",
        &material_presets,
        "Every named material (docs/materials.md cites their sources).");
  m.def(
      "material_preset",
      [](const std::string& name) {
        return raising_value_error([&] { return material_preset(name); });
      },
      py::arg("name"),
      "The named material, e.g. material_preset('ogden-1972-treloar').material; ValueError\n"
      "naming the presets for another name.");
}

}  // namespace puncture::python
