// scbt.TrackerOptions and scbt.option_table(): the option table (scbt/tracker/option_table.h)
// in Python, one property and keyword argument per user option.
#include "options_bindings.h"

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "scbt/tracker/option_table.h"

namespace py = pybind11;

namespace scbt {
namespace {

py::object to_python(const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return py::bool_(*b);
  if (const auto* i = std::get_if<long long>(&value)) return py::int_(*i);
  if (const auto* d = std::get_if<double>(&value)) return py::float_(*d);
  return py::str(std::get<std::string>(value));
}

// The Python value as the table takes it: bools, whole numbers (also numpy's), numbers, and text
// for a choice. Anything else is a TypeError in the table's words.
OptionValue from_python(const OptionSpec& spec, const py::handle& value) {
  const auto wrong = [&] {
    return py::type_error(spec.name + " must be " + spec.expected() + ", got " +
                          py::repr(value).cast<std::string>());
  };
  const std::string type = py::type::of(value).attr("__name__").cast<std::string>();
  if (py::isinstance<py::bool_>(value) || type == "bool_") return value.cast<bool>();
  if (py::isinstance<py::str>(value)) {
    if (spec.type != OptionType::kChoice) throw wrong();
    return value.cast<std::string>();
  }
  if (py::hasattr(value, "__index__")) {
    try {
      return value.cast<long long>();
    } catch (const py::cast_error&) {
      return py::float_(py::reinterpret_borrow<py::object>(value))
          .cast<double>();  // beyond 64 bits: out of every range
    }
  }
  if (py::isinstance<py::float_>(value) || py::hasattr(value, "__float__")) {
    return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  }
  throw wrong();
}

std::vector<std::string> option_names() {
  std::vector<std::string> names;
  for (const OptionSpec& spec : tracker_option_table()) names.push_back(spec.name);
  return names;
}

std::string options_doc() {
  std::string doc =
      "The tracker options a user tunes, each a property and a keyword argument of\n"
      "TrackerOptions(...) and Tracker(...), named as the CLI's flags with underscores\n"
      "(--shape-weight: shape_weight), ROS's parameters and a config file's keys.\n"
      "A bad value raises ValueError, a value of the wrong type TypeError, an unknown name\n"
      "TypeError.\n";
  std::string group;
  const TrackerOptions defaults;
  for (const OptionSpec& spec : tracker_option_table()) {
    if (spec.group != group) {
      group = spec.group;
      doc += "\n" + group + ":\n";
    }
    doc += "  " + spec.name + " (" + spec.type_name() + ", " +
           py::repr(to_python(spec.get(defaults))).cast<std::string>();
    if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
      doc += "; " + spec.range_text();
    }
    doc += "): " + spec.help + "\n";
  }
  return doc;
}

}  // namespace

void set_option_from_python(TrackerOptions* options, const std::string& name,
                            const py::handle& value) {
  const OptionSpec* spec = find_tracker_option(name);
  if (!spec) throw py::type_error("unknown option '" + name + "'");
  try {
    spec->set(options, check_option_value(*spec, from_python(*spec, value)));
  } catch (const OptionTypeError& e) {
    throw py::type_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

TrackerOptions options_from_python(const py::object& base, const py::kwargs& kwargs,
                                   const char* function, const std::set<std::string>& own) {
  TrackerOptions options;
  if (!base.is_none()) {
    if (!py::isinstance<TrackerOptions>(base)) {
      throw py::type_error(std::string(function) + "() options must be a TrackerOptions, got " +
                           py::repr(base).cast<std::string>());
    }
    options = base.cast<TrackerOptions>();
  }
  for (auto item : kwargs) {
    const std::string key = py::str(item.first).cast<std::string>();
    if (own.count(key)) continue;
    if (!find_tracker_option(key)) {
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key +
                           "'");
    }
    set_option_from_python(&options, key, item.second);
  }
  try {
    options.check();
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return options;
}

py::dict options_as_dict(const TrackerOptions& options) {
  py::dict d;
  for (const OptionSpec& spec : tracker_option_table())
    d[spec.name.c_str()] = to_python(spec.get(options));
  return d;
}

void register_options(py::module_& m) {
  py::class_<TrackerOptions> options(m, "TrackerOptions", options_doc().c_str());
  options
      .def(py::init([](const py::kwargs& kwargs) {
             return options_from_python(py::none(), kwargs, "TrackerOptions", {});
           }),
           "TrackerOptions(**options): the defaults with the options given set.")
      .def_static(
          "from_file",
          [](const std::string& path) {
            TrackerOptions read;
            read_tracker_options_file(path, &read);
            read.check();
            return read;
          },
          py::arg("path"),
          "The options of a YAML or JSON config file (option names as keys), the others at their\n"
          "defaults, as `scbt track --config FILE` reads it. Raises ValueError naming the file.")
      .def(
          "to_text",
          [](const TrackerOptions& o, bool json) { return tracker_options_text(o, json); },
          py::kw_only(), py::arg("json") = false,
          "Every option as a config file's text (YAML, or JSON with json=True).")
      .def("as_dict", &options_as_dict, "The options as a dict, name to value.")
      .def(
          "__getitem__",
          [](const TrackerOptions& o, const std::string& name) {
            const OptionSpec* spec = find_tracker_option(name);
            if (!spec) throw py::key_error(name);
            return to_python(spec->get(o));
          },
          py::arg("name"), "The option's value by name, as options['shape_weight'].")
      .def(
          "keys", [](const TrackerOptions&) { return option_names(); },
          "The option names, in the table's order.")
      .def("__repr__", &tracker_options_repr)
      .def("__eq__",
           [](const TrackerOptions& a, const TrackerOptions& b) {
             return tracker_options_text(a) == tracker_options_text(b);
           })
      .def("__copy__", [](const TrackerOptions& o) { return o; })
      .def("__deepcopy__", [](const TrackerOptions& o, const py::dict&) { return o; });
  options.attr("__hash__") = py::none();
  const TrackerOptions defaults;
  for (const OptionSpec& spec : tracker_option_table()) {
    const std::string name = spec.name;
    std::string doc = spec.help + " (" + spec.type_name() + ", default " +
                      py::repr(to_python(spec.get(defaults))).cast<std::string>();
    if (spec.type != OptionType::kBool) doc += "; " + spec.range_text();
    doc += ")";
    options.def_property(
        name.c_str(),
        [name](const TrackerOptions& o) { return to_python(find_tracker_option(name)->get(o)); },
        [name](TrackerOptions& o, const py::object& value) {
          TrackerOptions changed = o;
          set_option_from_python(&changed, name, value);
          try {
            changed.check();
          } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
          }
          o = changed;
        },
        doc.c_str());
  }

  m.def(
      "option_table",
      [] {
        py::list rows;
        const TrackerOptions defaults;
        for (const OptionSpec& spec : tracker_option_table()) {
          py::dict row;
          row["name"] = spec.name;
          row["flag"] = spec.flag();
          row["type"] = spec.type_name();
          row["default"] = to_python(spec.get(defaults));
          row["range"] = spec.range_text();
          row["expected"] = spec.expected();
          row["group"] = spec.group;
          row["help"] = spec.help;
          if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
            row["min"] = spec.min;
            row["max"] = spec.max;
            row["min_open"] = spec.min_open;
            row["max_open"] = spec.max_open;
          }
          if (spec.type == OptionType::kChoice) row["choices"] = spec.choices;
          rows.append(row);
        }
        return rows;
      },
      "The user options as the CLI, Python, ROS and config files all take them: a list of dicts\n"
      "with name, flag (the CLI's), type, default, range, expected, group and help (and min,\n"
      "max, min_open, max_open for numbers, choices for a choice).");
}

}  // namespace scbt
