#pragma once
// The module's functions, registered by concern (one file each).
#include <pybind11/pybind11.h>

namespace railstab::python {

void bind_stability(pybind11::module_& m);    // critical_speed, eigen, equilibrium, curving, sensitivity
void bind_time_domain(pybind11::module_& m);  // simulate, speed_ramp, verify, assess
void bind_studies(pybind11::module_& m);      // load_scene, check, contact_geometry, track, study, bifurcation

}  // namespace railstab::python
