// A C++ struct as a read-only Python class whose properties are also its as_dict(), in the order
// bound, so that each field is named once.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace scbt {

template <typename T>
class ReadonlyRecord {
 public:
  ReadonlyRecord(pybind11::module_& m, const char* name, const char* doc)
      : class_(m, name, doc), getters_(std::make_shared<Getters>()) {}

  // A data member.
  template <typename V>
  ReadonlyRecord& field(const char* name, V T::*member, const char* doc) {
    class_.def_readonly(name, member, doc);
    return add(name, [member](const T& t) { return pybind11::cast(t.*member); });
  }
  // A value computed from the struct by get(const T&).
  template <typename Get>
  ReadonlyRecord& computed(const char* name, Get get, const char* doc) {
    class_.def_property_readonly(name, get, doc);
    return add(name, [get](const T& t) { return pybind11::cast(get(t)); });
  }
  // Adds as_dict(): every property by name, a record among them as its own dict.
  pybind11::class_<T>& with_as_dict(const char* doc) {
    std::shared_ptr<const Getters> getters = getters_;
    class_.def(
        "as_dict",
        [getters](const T& t) {
          pybind11::dict d;
          for (const auto& [name, get] : *getters) {
            pybind11::object value = get(t);
            if (pybind11::hasattr(value, "as_dict")) value = value.attr("as_dict")();
            d[name] = value;
          }
          return d;
        },
        doc);
    return class_;
  }

 private:
  using Getter = std::function<pybind11::object(const T&)>;
  using Getters = std::vector<std::pair<const char*, Getter>>;

  ReadonlyRecord& add(const char* name, Getter get) {
    getters_->emplace_back(name, std::move(get));
    return *this;
  }

  pybind11::class_<T> class_;
  std::shared_ptr<Getters> getters_;
};

}  // namespace scbt
