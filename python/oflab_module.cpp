// The Python module oflab (manual/python.md): a thin pybind11 binding of the layers. Every
// input is read by the CLI's own readers (settings become the options of `oflab-cli animate`,
// `compare`, `flow` and `explain`, so the same refusals name the same limits), every run is
// played by analysis/runs, every summary is the CLI's JSON (analysis/cli/animate_options.h),
// and the lessons are checked by session/player/engine_claims.h. Nothing is computed here but
// the conversions to Python objects and numpy arrays. The run objects are python/run_object.h.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "basis/basis_catalog.h"
#include "cli/animate_options.h"
#include "cli/commands.h"
#include "cli/explain_report.h"
#include "cli/flow_report.h"
#include "experiments/published_results.h"
#include "formats/image_io.h"
#include "formats/vtk_export.h"
#include "lessons/lessons.h"
#include "player/engine_claims.h"
#include "run_object.h"

namespace py = pybind11;

namespace oflab {
namespace {

// ---- flow and explain ----

py::array matrix_array(const nlohmann::json& rows) {
  py::array_t<double> m({3, 3});
  auto view = m.mutable_unchecked<2>();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) view(r, c) = rows.at(r).at(c).get<double>();
  }
  return std::move(m);
}

// The twelve terms of each basis (session/basis/basis_catalog.h) of the coefficients `c`.
py::dict bases(const PlanarFlowCoefficients& c) {
  const TaylorTerms t = taylor_terms(c);
  py::dict all;
  for (BasisKind kind : {BasisKind::kTaylor, BasisKind::kWaxmanUllman, BasisKind::kPlanar}) {
    py::dict terms;
    for (const BasisTerm& term : basis_terms(kind))
      terms[term.symbol.c_str()] = term.coefficient(t);
    all[basis_key(kind)] = terms;
  }
  return all;
}

// The flow field on the grid of flow_grid (analysis/formats/vtk_export.h): rows x columns x 2.
py::array flow_field(const FlowReport& report, int step, py::dict& out) {
  const FlowGrid grid = flow_grid(report.camera, step);
  py::array_t<double> field({grid.rows, grid.columns, 2});
  py::array_t<double> xs(grid.columns), ys(grid.rows);
  auto f = field.mutable_unchecked<3>();
  for (int i = 0; i < grid.columns; ++i) xs.mutable_at(i) = grid.x0 + double(i) * grid.step;
  for (int j = 0; j < grid.rows; ++j) ys.mutable_at(j) = grid.y0 + double(j) * grid.step;
  for (int j = 0; j < grid.rows; ++j) {
    for (int i = 0; i < grid.columns; ++i) {
      const Vec2 v = flow_at(report.coefficients, Vec2(xs.at(i), ys.at(j)));
      f(j, i, 0) = v.x;
      f(j, i, 1) = v.y;
    }
  }
  out["grid_x"] = xs;
  out["grid_y"] = ys;
  return std::move(field);
}

py::dict flow(py::kwargs settings) {
  int step = kDefaultVtkGridStep;
  if (settings.contains("grid_step")) {
    step = checked_integer(settings["grid_step"], "grid_step");
    PyDict_DelItemString(settings.ptr(), "grid_step");
  }
  const FlowReport report = translate_errors([&] {
    const CliArgs a(settings_args(settings, flow_options(), {}), flow_options());
    return flow_report(a);
  });
  const std::string problem = flow_grid_problem(report.camera, step);
  if (!problem.empty()) throw py::value_error("grid_step: " + problem);
  py::dict out = to_python(report.json);
  for (const char* key : {"homography_taylor", "homography_exact"}) {
    if (report.json.contains(key)) out[key] = matrix_array(report.json.at(key));
  }
  out["bases"] = bases(report.coefficients);
  out["field"] = flow_field(report, step, out);
  out["focal"] = report.camera.focal_px;
  return out;
}

constexpr const char* kCoefficientNames[] = {"tx", "ty", "j11", "j12", "j21", "j22", "px", "py"};

// The eight coefficients of `c`: a flow() result, a dict by name or a sequence of eight.
std::vector<std::string> coefficient_texts(py::handle c) {
  py::handle values = c;
  if (py::isinstance<py::dict>(c) && c.cast<py::dict>().contains("coefficients")) {
    values = c.cast<py::dict>()["coefficients"];
  }
  std::vector<std::string> texts;
  if (py::isinstance<py::dict>(values)) {
    py::dict d = values.cast<py::dict>();
    for (const char* name : kCoefficientNames) {
      if (!d.contains(name)) {
        throw py::value_error(std::string("coefficients: no '") + name +
                              "' (needs tx, ty, j11, j12, j21, j22, px, py)");
      }
      texts.push_back(number_text(d[name], std::string("coefficients.") + name));
    }
    return texts;
  }
  if (!py::isinstance<py::sequence>(values) || py::isinstance<py::str>(values)) {
    throw py::type_error(
        "coefficients: a dict of tx, ty, j11, j12, j21, j22, px, py, a "
        "sequence of eight numbers or a flow() result");
  }
  for (py::handle v : values.cast<py::sequence>()) texts.push_back(number_text(v, "coefficients"));
  if (texts.size() != 8) {
    throw py::value_error(
        "coefficients: needs 8 numbers (tx, ty, j11, j12, j21, j22, px, py), got " +
        std::to_string(texts.size()));
  }
  return texts;
}

py::dict explain(py::handle coefficients, py::object focal, py::object at) {
  std::vector<std::string> args = {"--coefficients"};
  for (const std::string& t : coefficient_texts(coefficients)) args.push_back(t);
  if (focal.is_none() && py::isinstance<py::dict>(coefficients) &&
      coefficients.cast<py::dict>().contains("focal")) {
    focal = coefficients.cast<py::dict>()["focal"];
  }
  if (focal.is_none()) throw py::type_error("focal: needed (pixels), or pass a flow() result");
  args.push_back("--focal");
  args.push_back(number_text(focal, "focal"));
  if (!at.is_none()) {
    args.push_back("--at");
    for (const std::string& t : number_texts(at, "at", 2)) args.push_back(t);
  }
  return translate_errors([&] {
    const CliArgs a(args, explain_options());
    return to_python(explain_report(a));
  });
}

// ---- policies and lessons ----

py::list policies() { return to_python(policies_json().at("policies")); }

py::dict lesson_dict(const Lesson& lesson) {
  py::dict d;
  d["name"] = lesson.name;
  d["title"] = lesson.title;
  d["order"] = lesson.order;
  d["narrative"] = lesson.narrative;
  py::list steps;
  int claims = static_cast<int>(lesson.claims.size());
  for (const LessonStep& step : lesson.steps) {
    steps.append(step.say);
    claims += static_cast<int>(step.claims.size());
  }
  d["steps"] = steps;
  d["claims"] = claims;
  return d;
}

py::list lesson_list() {
  py::list out;
  for (const Lesson& lesson : oflab::lessons()) out.append(lesson_dict(lesson));
  return out;
}

// A lesson of datasets/lessons (or a lesson file) and its headless check.
struct PyLesson {
  std::shared_ptr<const Lesson> lesson;  // a copy: an added lesson may be replaced later

  py::list check() const {
    std::vector<ClaimCheck> checks;
    {
      py::gil_scoped_release release;
      checks = check_engine_claims(*lesson);
    }
    py::list out;
    for (const ClaimCheck& c : checks) {
      py::dict d;
      d["part"] = c.step;
      d["says"] = c.claim.says;
      d["claim"] = c.claim.claim;
      d["of"] = c.claim.of;
      d["measured"] = c.measured;
      d["at_least"] = c.claim.at_least;
      d["at_most"] = c.claim.at_most;
      d["holds"] = c.holds;
      d["text"] = describe(*lesson, c);
      out.append(d);
    }
    return out;
  }
};

PyLesson lesson(const std::string& name) {
  try {
    return PyLesson{std::make_shared<const Lesson>(find_or_read_lesson(name))};
  } catch (const std::runtime_error& e) {
    throw py::value_error(std::string("name: ") + e.what());
  }
}

// Section 6.4.8's published rows (analysis/experiments/published_results.h).
py::list published_rows() {
  py::list rows;
  for (const PublishedScriptResult& r : oflab::published_experiment1()) {
    py::dict levels;
    for (int l = 0; l < kLevelCount; ++l)
      levels[level_name(static_cast<Level>(l))] = r.level_percent[l];
    py::dict row;
    row["script"] = r.script;
    row["title"] = r.title;
    row["levels"] = levels;
    row["time_saved_percent"] = r.time_saved_percent;
    rows.append(row);
  }
  return rows;
}

// The PNG of an image array: H x W x 4 premultiplied RGBA (a frame) or H x W (a map, grey).
py::bytes png_bytes(py::array array) {
  const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> a(array);
  if (a.ndim() != 2 && !(a.ndim() == 3 && a.shape(2) == 4)) {
    throw py::value_error("png: needs H x W (a map) or H x W x 4 (a frame), got " +
                          std::to_string(a.ndim()) + " dimensions");
  }
  const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  Image image(w, h);
  const std::uint8_t* p = a.data();
  for (std::size_t k = 0; k < image.pixel_count(); ++k) {
    Pixel& q = image.pixels()[k];
    if (a.ndim() == 2) {
      q = Pixel{p[k], p[k], p[k], 255};
    } else {
      q = Pixel{p[4 * k], p[4 * k + 1], p[4 * k + 2], p[4 * k + 3]};
    }
  }
  return py::bytes(encode_png(image));
}

}  // namespace
}  // namespace oflab

PYBIND11_MODULE(_oflab, m) {
  using namespace oflab;
  m.doc() = "oflab: optic flow, reuse policies and lessons (manual/python.md)";
  bind_run_objects(m);
  m.def("run", &run_source, py::arg("source"), py::arg("policy") = "perspective",
        "run(source, policy='perspective', *, keep_frames=False, **settings) -> Run\n\n"
        "Plays a motion script (a shipped name or a file; with scene=NAME|FILE a viewer script\n"
        "through a scene) under a reuse policy, as `oflab-cli animate` does. settings are\n"
        "animate's options by name (threshold=1.0, thresholds=[...], delta=, sampling=,\n"
        "content=, quality=, frames=, repeat_timing=, warm_up=False, repeat=, texture=, ...).\n"
        "Run.summary is animate --json's object; Run.records the per-frame CSV as numpy\n"
        "columns; with keep_frames=True the frames, exact frames, difference and hole maps.");
  m.def("compare", &compare_source, py::arg("source"), py::arg("policies"),
        "compare(source, policies, **settings) -> Comparison\n\n"
        "Plays one source under several policies (a list of names or 'a,b'), as `oflab-cli\n"
        "compare` does; Comparison.summary is compare --json's object.");
  m.def("policies", &policies,
        "The reuse policies of the registry, as `oflab-cli policies --json`.");
  m.def("flow", &flow,
        "flow(*, focal, image, plane_point, plane_normal, velocity, omega, plane_up=None,\n"
        "     plane_size=None, motion='instantaneous', dt=None, explain=False, grid_step=4)\n\n"
        "The planar flow of a plane and motion, as `oflab-cli flow --json`, with the eight\n"
        "coefficients by name, 'bases' (the twelve terms of each basis), with dt the Taylor and\n"
        "exact homographies as 3x3 arrays, and 'field', the flow on a grid (rows x columns x 2,\n"
        "pixels per unit time at the centred points grid_x, grid_y).");
  m.def("explain", &explain, py::arg("coefficients"), py::arg("focal") = py::none(),
        py::arg("at") = py::none(),
        "The planes and motions that make eight planar coefficients (both solutions), as\n"
        "`oflab-cli explain --json`. coefficients: a flow() result, a dict or eight numbers.");
  m.def("lessons", &lesson_list,
        "The shipped lessons: name, title, order, narrative, steps, claims.");
  py::class_<PyLesson>(m, "Lesson", "A lesson; check() measures its engine claims headlessly.")
      .def_property_readonly("name", [](const PyLesson& l) { return l.lesson->name; })
      .def_property_readonly("title", [](const PyLesson& l) { return l.lesson->title; })
      .def_property_readonly("narrative", [](const PyLesson& l) { return l.lesson->narrative; })
      .def("info", [](const PyLesson& l) { return lesson_dict(*l.lesson); })
      .def("check", &PyLesson::check,
           "Plays the lesson headlessly and measures its engine claims, as `oflab-cli lesson\n"
           "check`: one dict per claim (part, says, claim, of, measured, at_least, at_most,\n"
           "holds, text).")
      .def("__repr__", [](const PyLesson& l) { return "<oflab.Lesson '" + l.lesson->name + "'>"; });
  m.def("lesson", &lesson, py::arg("name"), "A shipped lesson by name, or a lesson file.");
  m.def("published_experiment1", &published_rows,
        "The dissertation's Experiment 1 table (section 6.4.8): per script its title, the percent\n"
        "of frames per level after the first and the time saved, as oflab's experiments read it.");
  m.def("_png", &png_bytes, py::arg("array"),
        "PNG bytes of a frame (H x W x 4, premultiplied RGBA) or a map (H x W, grey).");
}
