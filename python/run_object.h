// The Python module's runs (python/run_object.cpp): oflab.run and oflab.compare, the Run and
// Comparison objects with their numpy views, and what every binding shares: JSON as Python
// objects, keyword settings as the CLI's options, and the project's refusals as Python
// exceptions (manual/python.md).
#pragma once

#include <pybind11/pybind11.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace oflab {

namespace py = pybind11;

// `j` as Python objects (dict, list, str, int, float, bool, None), a NaN or infinite number as
// None, as the CLI's JSON writes it, so a summary equals json.loads of the CLI's output.
py::object to_python(const nlohmann::json& j);
py::object to_python(const nlohmann::ordered_json& j);

// The keyword settings `settings` as a command's options (`options`: name with "--" ->
// number of values, the command's own table): a setting `a_b` is the option --a-b; True gives
// a flag, False the option --no-a-b where the table has it (warm_up=False: --no-warm-up);
// a number or text one value, a sequence as many as the option takes; None leaves it out.
// Throws TypeError naming the setting for a name outside the table or in `refused` (with the
// names accepted), or a value of the wrong type; ValueError for a wrong count of values.
std::vector<std::string> settings_args(const py::dict& settings,
                                       const std::map<std::string, int>& options,
                                       const std::set<std::string>& refused);
// A real number (not a bool) as text for the CLI's readers; TypeError naming `field` otherwise.
std::string number_text(py::handle value, const std::string& field);
// `count` numbers of a sequence; TypeError / ValueError naming `field`.
std::vector<std::string> number_texts(py::handle value, const std::string& field,
                                      std::size_t count);
// A whole number (not a bool); TypeError naming `field` otherwise.
int checked_integer(py::handle value, const std::string& field);

// Rethrows the exception being handled as a Python exception: the CLI's UsageError and the
// readers' errors (scripts, scenes, viewer scripts, images, lessons) and std::invalid_argument
// as ValueError, their options named as settings ("--thresholds" as "thresholds", "--mode" as
// "policy", "--script" as "source"); an interrupt (Ctrl-C seen between frames) as the
// pending KeyboardInterrupt; anything else as RuntimeError. Call only inside a catch block.
[[noreturn]] void rethrow_as_python();

// Runs `body` and rethrows what it throws as rethrow_as_python does.
template <class Body>
auto translate_errors(Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const py::error_already_set&) {
    throw;
  } catch (...) {
    rethrow_as_python();
  }
}

// oflab.run(source, policy, **settings) and oflab.compare(source, policies, **settings).
py::object run_source(py::object source, const std::string& policy, py::kwargs settings);
py::object compare_source(py::object source, py::object policies, py::kwargs settings);

// Registers the Run and Comparison classes on `m`.
void bind_run_objects(py::module_& m);

}  // namespace oflab
