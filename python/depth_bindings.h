// Registration of the depth (boundary -> 3-D) bindings in the scbt module.
#pragma once

#include <pybind11/pybind11.h>

namespace scbt {

void register_depth(pybind11::module_& m);

}  // namespace scbt
