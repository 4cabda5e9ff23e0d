// The Python module's runs and the conversions every binding shares (see python/run_object.h).
// A run is played by its source kind (analysis/runs/source_kinds.h) exactly as `oflab-cli
// animate` plays it; the summary is the CLI's JSON, the records are the kind's per-frame CSV
// read back into numpy columns, and the kept frames live in the run object, which numpy's
// arrays view (no copy; the run object is their base).
#include "run_object.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "cli/animate_options.h"
#include "display/palette.h"
#include "engine/decision.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "report/report.h"
#include "runs/frame_maps.h"
#include "runs/policy_runs.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

template <class Json>
py::object json_to_python(const Json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.template get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.template get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.template get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      const double v = j.template get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string:
      return py::str(j.template get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& e : j) list.append(json_to_python(e));
      return std::move(list);
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (auto it = j.begin(); it != j.end(); ++it) dict[py::str(it.key())] = json_to_python(*it);
      return std::move(dict);
    }
    default:
      return py::none();
  }
}

// Thrown by the frame callback when Python has a signal pending (Ctrl-C): the run stops and
// rethrow_as_python raises the pending exception.
struct Interrupted {};

// The settings' names for the options of the positional arguments.
std::string setting_name(const std::string& option) {
  if (option == "--mode") return "policy";
  if (option == "--script") return "source";
  std::string name = option.substr(2);
  for (char& c : name) c = c == '-' ? '_' : c;
  return name;
}

// `message` with every option (--a-b) written as the setting it came from (a_b).
std::string with_setting_names(const std::string& message) {
  std::string out;
  for (std::size_t i = 0; i < message.size();) {
    if (message.compare(i, 2, "--") == 0 && i + 2 < message.size() &&
        std::islower(static_cast<unsigned char>(message[i + 2]))) {
      std::size_t j = i + 2;
      while (j < message.size() &&
             (std::isalnum(static_cast<unsigned char>(message[j])) || message[j] == '-')) {
        ++j;
      }
      out += setting_name(message.substr(i, j - i));
      i = j;
    } else {
      out += message[i++];
    }
  }
  return out;
}

bool is_number(py::handle v) {
  return !py::isinstance<py::bool_>(v) && !py::isinstance<py::str>(v) && PyNumber_Check(v.ptr()) &&
         py::hasattr(v, "__float__");
}

std::string value_text(py::handle v, const std::string& field) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::hasattr(v, "__fspath__")) return py::str(v.attr("__fspath__")()).cast<std::string>();
  if (is_number(v)) return number_text(v, field);
  throw py::type_error(field + ": a number or text, not " +
                       py::str(py::type::of(v).attr("__name__")).cast<std::string>());
}

std::string accepted_list(const std::map<std::string, int>& options,
                          const std::set<std::string>& refused) {
  std::string names;
  for (const auto& [option, arity] : options) {
    if (refused.count(option)) continue;
    std::string name = setting_name(option);
    if (name.rfind("no_", 0) == 0) name = name.substr(3) + "=False";
    names += (names.empty() ? "" : ", ") + name;
  }
  return names;
}

// ---- the per-frame records: the kind's CSV as numpy columns ----

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

bool parse_double(const std::string& text, double* value) {
  if (text.empty()) {
    *value = std::nan("");
    return true;
  }
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

struct Records {
  std::vector<std::string> names;
  std::vector<std::vector<double>> numbers;     // per column (empty for a text column)
  std::vector<std::vector<std::string>> texts;  // per column (empty for a number column)
  std::vector<char> is_text;
};

// The columns of a kind's CSV (header, then one row per frame), numbers as doubles (empty
// cells as NaN), a column with any other cell as text.
Records read_records(const std::string& csv) {
  Records r;
  std::istringstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return r;
  r.names = csv_cells(line);
  const std::size_t n = r.names.size();
  r.texts.resize(n);
  r.is_text.assign(n, 0);
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = csv_cells(line);
    for (std::size_t c = 0; c < n; ++c) r.texts[c].push_back(c < cells.size() ? cells[c] : "");
  }
  r.numbers.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double>& column = r.numbers[c];
    for (const std::string& cell : r.texts[c]) {
      double v = 0.0;
      if (!parse_double(cell, &v)) {
        r.is_text[c] = 1;
        break;
      }
      column.push_back(v);
    }
    if (r.is_text[c]) {
      column.clear();
    } else {
      r.texts[c].clear();
    }
  }
  return r;
}

std::string kind_csv(const SourceKind& kind, const AnimationRun& run) {
  std::ostringstream csv;
  csv << std::setprecision(17);  // every digit of the records, not the stream's six
  kind.write_csv(csv, run);
  return csv.str();
}

// ---- kept frames ----

static_assert(sizeof(Pixel) == 4, "a Pixel is four bytes, RGBA");

// Every recorded frame's shown and exact images (premultiplied RGBA) and its difference and
// hole maps, one contiguous block per kind, frame after frame.
struct FrameStore {
  int width = 0, height = 0, count = 0;
  std::vector<std::uint8_t> shown, exact, difference, holes;

  void add(const Animator& animator, const Animator* baseline) {
    const Image& image = animator.image();
    if (count == 0) {
      width = image.width();
      height = image.height();
    }
    const Image& truth = baseline ? baseline->image() : image;
    append_image(shown, image);
    append_image(exact, truth);
    const std::vector<std::uint8_t> d = channel_difference_map(image, truth);
    difference.insert(difference.end(), d.begin(), d.end());
    std::vector<std::uint8_t> h = reprojection_hole_map(animator, truth);
    if (h.empty()) h.assign(image.pixel_count(), 0);
    holes.insert(holes.end(), h.begin(), h.end());
    ++count;
  }

  static void append_image(std::vector<std::uint8_t>& to, const Image& image) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(image.pixels().data());
    to.insert(to.end(), bytes, bytes + 4 * image.pixel_count());
  }
};

// What a run leaves: the summary, the records and, with keep_frames, the frames.
struct PyRun {
  nlohmann::json summary;
  Records records;
  std::shared_ptr<FrameStore> frames;  // null without keep_frames
};

struct PyComparison {
  nlohmann::json summary;
  std::vector<std::string> policies;
  std::vector<Records> records;  // per policy, in order
};

// A read-only numpy view of `data` owned by `owner` (the run object), as an oflab.Picture.
py::object picture(py::object owner, const std::uint8_t* data, std::vector<py::ssize_t> shape) {
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t stride = 1;
  for (std::size_t k = shape.size(); k-- > 0;) {
    strides[k] = stride;
    stride *= shape[k];
  }
  py::array array(py::dtype::of<std::uint8_t>(), shape, strides, data, owner);
  array.attr("setflags")(py::arg("write") = false);
  return array.attr("view")(py::module_::import("oflab").attr("Picture"));
}

const FrameStore& kept_frames(const PyRun& run) {
  if (!run.frames) {
    throw py::value_error("keep_frames: the run kept no frames; play it with keep_frames=True");
  }
  return *run.frames;
}

py::object frames_view(py::object self, std::vector<std::uint8_t> FrameStore::*block, int depth) {
  const FrameStore& f = kept_frames(self.cast<const PyRun&>());
  std::vector<py::ssize_t> shape = {f.count, f.height, f.width};
  if (depth > 1) shape.push_back(depth);
  return picture(self, (f.*block).data(), shape);
}

// The records as a dict: a number column as a float64 view of the run's memory, a text
// column as a numpy array of str.
py::dict records_dict(py::object owner, const Records& r) {
  py::dict d;
  for (std::size_t c = 0; c < r.names.size(); ++c) {
    if (r.is_text[c]) {
      d[py::str(r.names[c])] = py::module_::import("numpy").attr("array")(py::cast(r.texts[c]));
    } else {
      py::array column(py::dtype::of<double>(), {static_cast<py::ssize_t>(r.numbers[c].size())},
                       {static_cast<py::ssize_t>(sizeof(double))}, r.numbers[c].data(), owner);
      column.attr("setflags")(py::arg("write") = false);
      d[py::str(r.names[c])] = column;
    }
  }
  return d;
}

// ---- playing ----

const std::set<std::string> kOutputOptions = {"--out",
                                              "--force",
                                              "--frames-png",
                                              "--video",
                                              "--fps",
                                              "--vtk-series",
                                              "--json",
                                              "--quiet",
                                              "--script",
                                              "--mode",
                                              "--compare-conventional",
                                              "--conventional-single-sample",
                                              "--epsilon",
                                              "--policies"};

std::string source_text(py::handle source) {
  if (py::isinstance<py::str>(source)) return source.cast<std::string>();
  if (py::hasattr(source, "__fspath__")) {
    return py::str(source.attr("__fspath__")()).cast<std::string>();
  }
  throw py::type_error("source: a shipped name or a file path, not " +
                       py::str(py::type::of(source).attr("__name__")).cast<std::string>());
}

// Checks for Ctrl-C between frames, with the GIL held only for the check.
void check_signals(int, int) {
  py::gil_scoped_acquire hold;
  if (PyErr_CheckSignals() != 0) throw Interrupted{};
}

// Run options as animate and compare read them (frames, timing passes, warm-up), keeping the
// frames' records, quiet, and checking for Ctrl-C after every frame.
PlayOptions play_options(const CliArgs& a, std::ostream& messages) {
  PlayOptions options;
  const RunOutput output = read_run_output(a, messages);
  output.apply_timing_to(options);
  options.progress = check_signals;
  return options;
}

bool pop_flag(py::kwargs& settings, const char* name) {
  if (!settings.contains(name)) return false;
  py::object v = settings[name];
  if (!py::isinstance<py::bool_>(v)) throw py::type_error(std::string(name) + ": True or False");
  PyDict_DelItemString(settings.ptr(), name);
  return v.cast<bool>();
}

std::string run_html(const PyRun& run, const Records& records);
std::string comparison_html(const PyComparison& c);

}  // namespace

py::object to_python(const nlohmann::json& j) { return json_to_python(j); }
py::object to_python(const nlohmann::ordered_json& j) { return json_to_python(j); }

std::string number_text(py::handle value, const std::string& field) {
  if (!is_number(value)) {
    throw py::type_error(field + ": a number, not " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  return py::repr(py::float_(value.cast<double>())).cast<std::string>();
}

std::vector<std::string> number_texts(py::handle value, const std::string& field,
                                      std::size_t count) {
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value)) {
    throw py::type_error(field + ": a sequence of " + std::to_string(count) + " numbers");
  }
  std::vector<std::string> texts;
  for (py::handle v : value.cast<py::sequence>()) texts.push_back(number_text(v, field));
  if (texts.size() != count) {
    throw py::value_error(field + ": needs " + std::to_string(count) + " numbers, got " +
                          std::to_string(texts.size()));
  }
  return texts;
}

int checked_integer(py::handle value, const std::string& field) {
  if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value)) {
    throw py::type_error(field + ": a whole number");
  }
  return value.cast<int>();
}

std::vector<std::string> settings_args(const py::dict& settings,
                                       const std::map<std::string, int>& options,
                                       const std::set<std::string>& refused) {
  std::vector<std::string> args;
  for (const auto& [key, value] : settings) {
    const std::string name = py::str(key).cast<std::string>();
    std::string option = "--" + name;
    for (char& c : option) c = c == '_' ? '-' : c;
    const bool known = options.count(option) && !refused.count(option);
    const bool negated = options.count("--no-" + option.substr(2)) > 0;
    if (!known && !negated) {
      throw py::type_error("unexpected setting '" + name +
                           "' (accepted: " + accepted_list(options, refused) + ")");
    }
    if (value.is_none()) continue;
    const int arity = known ? options.at(option) : 0;
    if (arity == 0) {
      if (!py::isinstance<py::bool_>(value)) throw py::type_error(name + ": True or False");
      const bool on = value.cast<bool>();
      if (known && on) args.push_back(option);
      if (!known && !on) args.push_back("--no-" + option.substr(2));
      continue;
    }
    if (py::isinstance<py::bool_>(value)) {
      throw py::type_error(name + ": a number or text, not True/False");
    }
    args.push_back(option);
    if (arity == 1) {
      args.push_back(value_text(value, name));
    } else {
      for (const std::string& t : number_texts(value, name, arity)) args.push_back(t);
    }
  }
  return args;
}

void rethrow_as_python() {
  try {
    throw;
  } catch (const py::builtin_exception&) {
    throw;
  } catch (const Interrupted&) {
    throw py::error_already_set();
  } catch (const UsageError& e) {
    throw py::value_error(with_setting_names(e.what()));
  } catch (const SceneError& e) {
    throw py::value_error(std::string("scene: ") + e.what());
  } catch (const ViewerScriptError& e) {
    throw py::value_error(std::string("source: ") + e.what());
  } catch (const ScriptError& e) {
    throw py::value_error(std::string("source: ") + e.what());
  } catch (const ImageFileError& e) {
    throw py::value_error(std::string("texture: ") + e.what());
  } catch (const SessionError& e) {
    throw py::value_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw py::value_error(with_setting_names(e.what()));
  } catch (const std::exception& e) {
    throw std::runtime_error(e.what());
  }
}

py::object run_source(py::object source, const std::string& policy, py::kwargs settings) {
  const bool keep_frames = pop_flag(settings, "keep_frames");
  std::vector<std::string> args = {"--script", source_text(source), "--mode", policy, "--quiet"};
  for (const std::string& a : settings_args(settings, animate_options(), kOutputOptions)) {
    args.push_back(a);
  }
  auto result = std::make_shared<PyRun>();
  translate_errors([&] {
    const CliArgs a(args, animate_options());
    const AnimateInputs inputs = read_animate_inputs(a);
    std::ostringstream messages;
    PlayOptions options = play_options(a, messages);
    if (keep_frames) {
      result->frames = std::make_shared<FrameStore>();
      FrameStore* store = result->frames.get();
      options.on_animators = [store](int, const Animator& animator, const Animator* baseline) {
        store->add(animator, baseline);
      };
    }
    py::gil_scoped_release release;
    const AnimationRun run = inputs.kind->play(inputs.source, options);
    result->summary = animate_json(inputs, run);
    result->records = read_records(kind_csv(*inputs.kind, run));
  });
  return py::cast(result);
}

py::object compare_source(py::object source, py::object policies, py::kwargs settings) {
  std::string list;
  if (py::isinstance<py::str>(policies)) {
    list = policies.cast<std::string>();
  } else if (py::isinstance<py::sequence>(policies)) {
    for (py::handle p : policies.cast<py::sequence>()) {
      if (!py::isinstance<py::str>(p)) throw py::type_error("policies: names (str)");
      list += (list.empty() ? "" : ",") + p.cast<std::string>();
    }
  } else {
    throw py::type_error("policies: a list of policy names, or 'a,b'");
  }
  std::vector<std::string> args = {"--script", source_text(source), "--policies", list, "--quiet"};
  for (const std::string& a : settings_args(settings, compare_options(), kOutputOptions)) {
    args.push_back(a);
  }
  auto result = std::make_shared<PyComparison>();
  translate_errors([&] {
    const CliArgs a(args, compare_options());
    const CompareInputs inputs = read_compare_inputs(a);
    std::ostringstream messages;
    PlayOptions options = play_options(a, messages);
    add_compare_measures(options);
    py::gil_scoped_release release;
    const std::vector<PolicyRun> runs =
        run_policies(*inputs.kind, inputs.source, inputs.policies, options);
    std::vector<PolicyRow> rows;
    for (const PolicyRun& r : runs) {
      rows.push_back(policy_row(r));
      result->policies.push_back(r.policy->name);
      result->records.push_back(read_records(kind_csv(*inputs.kind, r.run)));
    }
    result->summary = compare_json(inputs, rows);
  });
  return py::cast(result);
}

namespace {

std::string colour_css(Level level) {
  const Rgb8 c = level_colour(level);
  std::ostringstream css;
  css << "rgb(" << int(c.r) << "," << int(c.g) << "," << int(c.b) << ")";
  return css.str();
}

// The level strip: one cell per frame in its level's colour (a plane's "level" column), or
// per frame the level that updated most of its polygons (a scene's level count columns).
std::string level_strip(const Records& r) {
  std::vector<Level> levels;
  for (std::size_t c = 0; c < r.names.size(); ++c) {
    if (r.names[c] != "level" || !r.is_text[c]) continue;
    for (const std::string& name : r.texts[c]) {
      Level level = Level::kRerender;
      parse_level(name, &level);
      levels.push_back(level);
    }
  }
  if (levels.empty()) {
    std::vector<const std::vector<double>*> counts;
    for (int l = 0; l < kLevelCount; ++l) {
      for (std::size_t c = 0; c < r.names.size(); ++c) {
        if (r.names[c] == level_name(static_cast<Level>(l)) && !r.is_text[c]) {
          counts.push_back(&r.numbers[c]);
        }
      }
    }
    if (counts.size() != kLevelCount) return "";
    for (std::size_t f = 0; f < counts[0]->size(); ++f) {
      int best = 0;
      for (int l = 1; l < kLevelCount; ++l) best = (*counts[l])[f] > (*counts[best])[f] ? l : best;
      levels.push_back(static_cast<Level>(best));
    }
  }
  std::ostringstream html;
  html << "<div style='display:flex;height:14px;margin:4px 0' title='update level per frame'>";
  for (Level level : levels) {
    html << "<div style='flex:1;background:" << colour_css(level) << "'></div>";
  }
  html << "</div><div style='font-size:smaller'>";
  for (int l = 0; l < kLevelCount; ++l) {
    html << "<span style='color:" << colour_css(static_cast<Level>(l)) << "'>&#9632;</span> "
         << level_name(static_cast<Level>(l)) << " ";
  }
  return html.str() + "</div>";
}

std::string summary_table(const nlohmann::json& summary) {
  std::ostringstream html;
  html << "<table>";
  for (auto it = summary.begin(); it != summary.end(); ++it) {
    if (it->is_structured()) {
      html << "<tr><th style='text-align:left'>" << html_escape(it.key()) << "</th><td><code>"
           << html_escape(it->dump()) << "</code></td></tr>";
    } else {
      html << "<tr><th style='text-align:left'>" << html_escape(it.key()) << "</th><td>"
           << html_escape(it->is_string() ? it->get<std::string>() : it->dump()) << "</td></tr>";
    }
  }
  return html.str() + "</table>";
}

std::string run_html(const PyRun& run, const Records& records) {
  return "<div><b>oflab run</b>" + level_strip(records) + summary_table(run.summary) + "</div>";
}

std::string comparison_html(const PyComparison& c) {
  std::ostringstream html;
  html << "<div><b>oflab comparison</b> of " << html_escape(c.summary.value("script", ""))
       << "<table><tr><th>policy</th><th>work saved</th><th>max error px</th>"
       << "<th>mean PSNR dB</th><th>levels</th></tr>";
  for (std::size_t k = 0; k < c.policies.size(); ++k) {
    const nlohmann::json& row = c.summary.at("policies").at(k);
    html << "<tr><td>" << html_escape(c.policies[k]) << "</td><td>" << row.at("work_saved").dump()
         << "</td><td>" << row.at("max_measured_error_px").dump() << "</td><td>"
         << row.at("mean_psnr_db").dump() << "</td><td style='min-width:200px'>"
         << level_strip(c.records[k]) << "</td></tr>";
  }
  return html.str() + "</table></div>";
}

}  // namespace

void bind_run_objects(py::module_& m) {
  py::class_<PyRun, std::shared_ptr<PyRun>>(
      m, "Run",
      "One run of a source under a policy. summary: animate --json's dict; records: the\n"
      "per-frame CSV's columns (numpy, read-only views); with keep_frames=True frames,\n"
      "exact_frames (count x H x W x 4, premultiplied RGBA uint8), differences and holes\n"
      "(count x H x W uint8): read-only views of the run's memory.")
      .def_property_readonly("summary", [](const PyRun& r) { return to_python(r.summary); })
      .def_property_readonly(
          "records",
          [](py::object self) { return records_dict(self, self.cast<const PyRun&>().records); })
      .def_property_readonly("kept_frames", [](const PyRun& r) { return bool(r.frames); })
      .def_property_readonly(
          "frames", [](py::object self) { return frames_view(self, &FrameStore::shown, 4); })
      .def_property_readonly(
          "exact_frames", [](py::object self) { return frames_view(self, &FrameStore::exact, 4); })
      .def_property_readonly(
          "differences",
          [](py::object self) { return frames_view(self, &FrameStore::difference, 1); })
      .def_property_readonly(
          "holes", [](py::object self) { return frames_view(self, &FrameStore::holes, 1); })
      .def("_repr_html_", [](const PyRun& r) { return run_html(r, r.records); })
      .def("__repr__", [](const PyRun& r) {
        return "<oflab.Run " + r.summary.value("script", std::string()) + " under " +
               r.summary.value("mode", std::string()) + ", " +
               std::to_string(r.summary.value("frames", 0)) + " frames>";
      });
  py::class_<PyComparison, std::shared_ptr<PyComparison>>(
      m, "Comparison",
      "One source under several policies. summary: compare --json's dict; records: per policy\n"
      "the per-frame CSV's columns.")
      .def_property_readonly("summary", [](const PyComparison& c) { return to_python(c.summary); })
      .def_property_readonly("policies", [](const PyComparison& c) { return c.policies; })
      .def_property_readonly("records",
                             [](py::object self) {
                               const auto& c = self.cast<const PyComparison&>();
                               py::dict d;
                               for (std::size_t k = 0; k < c.policies.size(); ++k) {
                                 d[py::str(c.policies[k])] = records_dict(self, c.records[k]);
                               }
                               return d;
                             })
      .def("_repr_html_", &comparison_html)
      .def("__repr__", [](const PyComparison& c) {
        return "<oflab.Comparison of " + c.summary.value("script", std::string()) + ", " +
               std::to_string(c.policies.size()) + " policies>";
      });
}

}  // namespace oflab
