// The Python module's parts, one register_* per area (depth: depth_bindings.h).
#pragma once

#include <pybind11/pybind11.h>

namespace scbt {

// Tracker, FrameStats, BoundaryEvidence (tracker_bindings.cc).
void register_tracker(pybind11::module_& m);
// The pipeline's stages one by one (stages_bindings.cc).
void register_stages(pybind11::module_& m);
// Polygon area and checks, shape distance, E_AL (geometry_bindings.cc).
void register_geometry(pybind11::module_& m);

}  // namespace scbt
