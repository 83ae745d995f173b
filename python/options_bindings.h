// The option table in Python (options_bindings.cc): scbt.TrackerOptions, scbt.option_table(),
// and the keyword-argument reading Tracker(...) shares with them.
#pragma once

#include <pybind11/pybind11.h>

#include <set>
#include <string>

#include "scbt/tracker/tracker_options.h"

namespace scbt {

// `base` (None or a TrackerOptions) with the keyword arguments set, but for the keywords in `own`
// (the caller's). TypeError for an unknown keyword or a value of the wrong type, ValueError for a
// bad value, both in the option table's words.
TrackerOptions options_from_python(const pybind11::object& base, const pybind11::kwargs& kwargs,
                                   const char* function, const std::set<std::string>& own);
pybind11::dict options_as_dict(const TrackerOptions& options);
// Sets one option from a Python value (TypeError, ValueError as above).
void set_option_from_python(TrackerOptions* options, const std::string& name,
                            const pybind11::handle& value);

void register_options(pybind11::module_& m);

}  // namespace scbt
