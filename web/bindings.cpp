// The page's JavaScript interface to core (manual/web.md): WebSession (web/web_session.h)
// as the class `Session`, and the shipped data's listings. Number arrays are returned as
// Float64Array copies; frame pixels as Uint8Array views into the module's memory, valid
// until the next call into the module (the page copies them into ImageData at once).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "display/palette.h"
#include "engine/decision.h"
#include "frame_pixels.h"
#include "web_explorer.h"
#include "web_session.h"
#include "web_slices.h"
#include "web_study.h"
#include "world_json.h"

namespace oflab {
namespace {

emscripten::val float64_copy(const std::vector<double>& values) {
  return emscripten::val::global("Float64Array")
      .new_(emscripten::typed_memory_view(values.size(), values.data()));
}

emscripten::val arrows(const WebSession& s, const std::string& part, double spacing) {
  return float64_copy(s.flow_arrows(part, spacing));
}

emscripten::val streamlines(const WebSession& s, const std::string& part, double spacing,
                            double duration_s, int steps) {
  return float64_copy(s.flow_streamlines(part, spacing, duration_s, steps));
}

emscripten::val run_pixels(const WebSession& s, int index) {
  const std::vector<std::uint8_t>& pixels = s.run(index).pixels;
  return emscripten::val(emscripten::typed_memory_view(pixels.size(), pixels.data()));
}

emscripten::val run_heat(const WebSession& s, int index) {
  const std::vector<std::uint8_t>& heat = s.run(index).heat;
  return emscripten::val(emscripten::typed_memory_view(heat.size(), heat.data()));
}

emscripten::val rgb_array(const Rgb8& c) {
  emscripten::val out = emscripten::val::array();
  for (std::uint8_t channel : {c.r, c.g, c.b}) out.call<void>("push", static_cast<int>(channel));
  return out;
}

// placeLabels: the world view's label boxes (world_json.h placed_labels_json), or
// {"error": message} for a request not of its form.
std::string place_labels_answer(const std::string& request) {
  try {
    return placed_labels_json(request);
  } catch (const std::exception& e) {
    return std::string("{\"error\": \"") + e.what() + "\"}";
  }
}

// The colour of every update level as {"name": [r, g, b]}, in the levels' order.
emscripten::val level_colours() {
  emscripten::val out = emscripten::val::object();
  for (int k = 0; k < kLevelCount; ++k) {
    const Level level = static_cast<Level>(k);
    out.set(level_name(level), rgb_array(level_colour(level)));
  }
  return out;
}

// The flow colour wheel (palette.h flow_wheel_colour) sampled for the page: `angles`
// directions (angle k * 360 / angles degrees, image coordinates, Y down) times `levels`
// magnitudes (m / (levels - 1) of the largest), r, g, b bytes, direction-major.
emscripten::val wheel_table(int angles, int levels) {
  static std::vector<std::uint8_t> table;
  angles = std::clamp(angles, 1, 720);
  levels = std::clamp(levels, 2, 256);
  table.assign(std::size_t(angles) * std::size_t(levels) * 3, 0);
  for (int a = 0; a < angles; ++a) {
    const double angle = 2.0 * std::acos(-1.0) * a / angles;
    for (int m = 0; m < levels; ++m) {
      const double r = double(m) / (levels - 1);
      const Rgb8 c = flow_wheel_colour(Vec2(r * std::cos(angle), r * std::sin(angle)), 1.0);
      const std::size_t i = (std::size_t(a) * std::size_t(levels) + std::size_t(m)) * 3;
      table[i] = c.r;
      table[i + 1] = c.g;
      table[i + 2] = c.b;
    }
  }
  return emscripten::val(emscripten::typed_memory_view(table.size(), table.data()));
}

// A study clip's frame as RGBA bytes (a view into the module's memory; empty when there is
// no such frame).
emscripten::val study_frame(WebStudy& s, int clip, int frame) {
  const std::vector<Pixel>& pixels = s.clip_frame(clip, frame);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(pixels.data());
  return emscripten::val(emscripten::typed_memory_view(pixels.size() * 4, bytes));
}

emscripten::val study_curve(const WebStudy& s, double threshold_px, int n) {
  return float64_copy(s.curve(threshold_px, n));
}

// The plane's texture for the world view's plane: {width, height, pixels}, the texture
// flattened over light grey (225) into opaque RGBA8 rows, top row first, at most 512 pixels
// on its longer side (nearest neighbour); pixels is a view into the module's memory.
emscripten::val world_texture(const WebSession& s) {
  static std::vector<std::uint8_t> pixels;
  const Image& texture = s.plane_texture();
  const double k = std::min(1.0, 512.0 / std::max(texture.width(), texture.height()));
  const int width = std::max(1, int(std::lround(k * texture.width())));
  const int height = std::max(1, int(std::lround(k * texture.height())));
  const std::uint8_t grey[3] = {225, 225, 225};
  flatten_into(texture, display_sampling(texture.width(), texture.height(), width, height), grey,
               pixels);
  emscripten::val out = emscripten::val::object();
  out.set("width", width);
  out.set("height", height);
  out.set("pixels", emscripten::val(emscripten::typed_memory_view(pixels.size(), pixels.data())));
  return out;
}

// The frame on the world view's image plane, as the desktop's: a scene's engine frame
// (WebSession::scene_animator), else the plane's exact frame (exact_plane_image), flattened over
// the world's image grey (150, 156, 165) into opaque RGBA8 rows, top row first, at most 256
// pixels on its longer side (nearest neighbour): {width, height, pixels}, pixels a view into
// the module's memory. Null when there is no frame (a source that cannot be played).
emscripten::val world_frame(WebSession& s) {
  static std::vector<std::uint8_t> pixels;
  const std::uint8_t grey[3] = {150, 156, 165};
  const Animator* scene = s.scene_animator();
  const PlaneImage* plane = scene ? nullptr : &s.exact_plane_image();
  const int frame_width = scene ? scene->image().width() : plane->width;
  const int frame_height = scene ? scene->image().height() : plane->height;
  if (frame_width < 1 || frame_height < 1 || (plane && plane->placed.layer.empty()))
    return emscripten::val::null();
  const double k = std::min(1.0, 256.0 / std::max(frame_width, frame_height));
  const int width = std::max(1, int(std::lround(k * frame_width)));
  const int height = std::max(1, int(std::lround(k * frame_height)));
  if (scene) {
    flatten_into(scene->image(), display_sampling(frame_width, frame_height, width, height), grey,
                 pixels);
  } else {
    const Layer& layer = plane->placed.layer;
    DisplaySampling sampling = display_sampling(frame_width, frame_height, width, height);
    shift_sampling(sampling, plane->placed.offset_x, plane->placed.offset_y, layer.image.width(),
                   layer.image.height());
    flatten_into(layer.image, sampling, grey, pixels);
  }
  emscripten::val out = emscripten::val::object();
  out.set("width", width);
  out.set("height", height);
  out.set("pixels", emscripten::val(emscripten::typed_memory_view(pixels.size(), pixels.data())));
  return out;
}

// The flow view's texture (WebSession::exact_plane_image) as display pixels: {width, height,
// pixels} with pixels opaque RGBA8 rows (a view into the module's memory), display pixel
// (x, y) showing the camera pixel under (x0 + (x + 0.5) * pixel, y0 + (y + 0.5) * pixel)
// (top-left camera pixels; frame_pixels.h region_sampling) over the page's background
// #111315 (also off the camera image), faded towards it by `opacity` in [0, 1]. Width and
// height are clamped to 1 .. 4096, pixel to at least 1e-6. Null when no texture is drawn
// (an empty layer).
emscripten::val flow_texture(WebSession& s, double x0, double y0, double pixel, int width,
                             int height, double opacity) {
  static std::vector<std::uint8_t> pixels;
  const PlaneImage& image = s.exact_plane_image();
  const Layer& layer = image.placed.layer;
  if (layer.empty()) return emscripten::val::null();
  width = std::clamp(width, 1, 4096);
  height = std::clamp(height, 1, 4096);
  pixel = std::max(1e-6, pixel);
  DisplaySampling sampling =
      region_sampling(image.width, image.height, x0, y0, pixel, width, height);
  shift_sampling(sampling, image.placed.offset_x, image.placed.offset_y, layer.image.width(),
                 layer.image.height());
  const std::uint8_t background[3] = {0x11, 0x13, 0x15};
  flatten_into(layer.image, sampling, background, pixels, opacity);
  emscripten::val out = emscripten::val::object();
  out.set("width", width);
  out.set("height", height);
  out.set("pixels", emscripten::val(emscripten::typed_memory_view(pixels.size(), pixels.data())));
  return out;
}

// The scene-shifting view's frame (WebSlices::pixels): a view into the module's memory.
emscripten::val slice_pixels(WebSlices& s, bool exact, int width, int height) {
  const std::vector<std::uint8_t>& pixels = s.pixels(exact, width, height);
  return emscripten::val(emscripten::typed_memory_view(pixels.size(), pixels.data()));
}

// The colour of compared policy or study condition `index` (palette.h policy_colour).
emscripten::val policy_rgb(int index) { return rgb_array(policy_colour(index)); }

// The one sequential ramp (palette.h magnitude_colour) at t in [0, 1] as [r, g, b]: the
// heat map's colour bar and the flow arrows' magnitudes.
emscripten::val heat_colour(double t) { return rgb_array(magnitude_colour(t)); }

}  // namespace
}  // namespace oflab

EMSCRIPTEN_BINDINGS(oflab_web) {
  using oflab::WebSession;
  emscripten::class_<WebSession>("Session")
      .constructor<>()
      .function("stateJson", &WebSession::state_json)
      .function("setState", &WebSession::set_state)
      .function("addScript", &WebSession::add_script)
      .function("sessionFileText", &WebSession::session_file_text)
      .function("runCsvJson", &WebSession::run_csv_json)
      .function("openSession", &WebSession::open_session)
      .function("checkClaimsJson", &WebSession::check_claims_json)
      .function("frameCount", &WebSession::frame_count)
      .function("frame", &WebSession::frame)
      .function("seek", &WebSession::seek)
      .function("sceneProblem", &WebSession::scene_problem)
      .function("flowJson", &WebSession::flow_json)
      .function("worldLoopJson", &WebSession::world_loop_json)
      .function("worldFrameJson", &WebSession::world_frame_json)
      .function("worldTexture", &oflab::world_texture)
      .function("worldFrame", &oflab::world_frame)
      .function("arrows", &oflab::arrows)
      .function("streamlines", &oflab::streamlines)
      .function("flowTexture", &oflab::flow_texture)
      .function("basisJson", &WebSession::basis_json)
      .function("explorerJson", &oflab::explorer_json)
      .function("comparisonProblem", &WebSession::comparison_problem)
      .function("updateComparison", &WebSession::update_comparison)
      .function("analysisJson", &WebSession::analysis_json)
      .function("runCount", &WebSession::run_count)
      .function("frameWidth", &WebSession::frame_width)
      .function("frameHeight", &WebSession::frame_height)
      .function("runPixels", &oflab::run_pixels)
      .function("runHeat", &oflab::run_heat)
      .function("goToLessonStep", &WebSession::go_to_lesson)
      .class_function("lessonsJson", &WebSession::lessons_json)
      .class_function("lessonFileJson", &WebSession::lesson_file_json)
      .class_function("scriptRunJson", &WebSession::script_run_json)
      .class_function("scriptNamesJson", &WebSession::script_names_json)
      .class_function("sceneNamesJson", &WebSession::scene_names_json)
      .class_function("stateSchemaJson", &WebSession::state_schema_json);
}

// The palette's colours for the page's drawings (session/display/palette.h).
EMSCRIPTEN_BINDINGS(oflab_web_palette) {
  emscripten::function("heatColour", &oflab::heat_colour);
  emscripten::function("policyColour", &oflab::policy_rgb);
  emscripten::function("levelColours", &oflab::level_colours);
  emscripten::function("wheelTable", &oflab::wheel_table);
}

// The world view's labels, placed by the desktop's rule (session/display/label_layout.h).
EMSCRIPTEN_BINDINGS(oflab_web_labels) {
  emscripten::function("placeLabels", &oflab::place_labels_answer);
}

// The threshold study's loop behind the page's study panel (web/web_study.h).
EMSCRIPTEN_BINDINGS(oflab_web_study) {
  using oflab::WebStudy;
  emscripten::class_<WebStudy>("Study")
      .constructor<>()
      .function("open", &WebStudy::open)
      .function("isOpen", &WebStudy::is_open)
      .function("finished", &WebStudy::finished)
      .function("requestJson", &WebStudy::request_json)
      .function("clipLength", &WebStudy::clip_length)
      .function("clipFrame", &oflab::study_frame)
      .function("answer", &WebStudy::answer)
      .function("simulate", &WebStudy::simulate)
      .function("csv", &WebStudy::csv)
      .function("resultsJson", &WebStudy::results_json)
      .function("useThresholdPx", &WebStudy::use_threshold_px)
      .function("studyJson", &WebStudy::study_json)
      .function("classResultsJson", &WebStudy::class_results_json)
      .function("curve", &oflab::study_curve)
      .class_function("shippedJson", &WebStudy::shipped_json);
}

// The scene-shifting view's walk and diagram (web/web_slices.h).
EMSCRIPTEN_BINDINGS(oflab_web_slices) {
  using oflab::WebSlices;
  emscripten::class_<WebSlices>("Slices")
      .constructor<>()
      .function("update", &WebSlices::update)
      .function("pixels", &oflab::slice_pixels);
}
