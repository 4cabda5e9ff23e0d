// Option readers shared by the two forms of `oflab-cli animate`.
#include "cli/animate_options.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <tuple>

#include "content/layer_content.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/obj_scene.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"

namespace oflab {

namespace fs = std::filesystem;

namespace {

constexpr int kDefaultVideoFps = 30;

// --video FILE at --fps N: the writer, checked before the run (format, frame rate, an
// existing file without --force). Empty without --video.
std::shared_ptr<VideoWriter> read_video_option(const CliArgs& a) {
  if (!a.has("--video")) {
    if (a.has("--fps")) throw UsageError("--fps: needs --video FILE");
    return nullptr;
  }
  const int fps = a.has("--fps") ? a.integer_in("--fps", limits::kVideoFps) : kDefaultVideoFps;
  const std::string path = a.values("--video").at(0);
  try {
    video_format_of(path);
  } catch (const VideoFileError& e) {
    throw UsageError(std::string("--video: ") + e.what());
  }
  const Overwrite overwrite = check_out_file("--video", path, a.has("--force"));
  try {
    return std::make_shared<VideoWriter>(path, fps, overwrite == Overwrite::kReplace);
  } catch (const VideoFileError& e) {
    throw UsageError(std::string("--video: ") + e.what());
  }
}

// --frames, --repeat, --repeat-timing and --no-warm-up into `out`.
void read_timing_options(const CliArgs& a, RunOutput& out) {
  if (a.has("--frames")) out.max_frames = a.integer_in("--frames", limits::kPlayedFrames);
  // A long run (--repeat) is timed in one pass unless --repeat-timing asks for more: its
  // records are then streamed, and its memory does not grow with its length.
  if (a.has("--repeat")) out.timing_repetitions = 1;
  if (a.has("--repeat-timing")) {
    out.timing_repetitions = a.integer_in("--repeat-timing", limits::kTimingPasses);
  }
  out.warm_up = !a.has("--no-warm-up");
}

// The names of --out DIR and --vtk-series DIR into `out`, each checked (a name given, the two
// not the same directory, --frames-png only with --out, a non-empty --vtk-series DIR only
// with --force) before anything is created.
void check_output_dirs(const CliArgs& a, RunOutput& out) {
  out.dir = a.text_or("--out", "");
  if (a.has("--out") && out.dir.empty()) throw UsageError("--out: needs a directory name");
  if (a.has("--frames-png") && out.dir.empty()) throw UsageError("--frames-png: needs --out DIR");
  out.vtk_series_dir = a.text_or("--vtk-series", "");
  if (a.has("--vtk-series") && out.vtk_series_dir.empty()) {
    throw UsageError("--vtk-series: needs a directory name");
  }
  if (!out.vtk_series_dir.empty()) {
    if (!out.dir.empty() &&
        fs::weakly_canonical(out.dir) == fs::weakly_canonical(out.vtk_series_dir))
      throw UsageError("--vtk-series: '" + out.vtk_series_dir + "' is also --out");
    check_out_dir("--vtk-series", out.vtk_series_dir, a.has("--force"));
  }
}

// The temporary directories of --out DIR (with its frames.csv stream, opened later by
// RunOutput::apply_to) and --vtk-series DIR (with its series writer), for those given.
void open_output_dirs(const CliArgs& a, RunOutput& out) {
  if (!out.dir.empty()) {
    out.out = open_out_dir(out.dir, a.has("--force"));
    out.csv = std::make_shared<std::ofstream>();  // opened by apply_to, which knows the kind
  }
  if (!out.vtk_series_dir.empty()) {
    out.vtk_series_out = open_out_dir(out.vtk_series_dir, a.has("--force"), "--vtk-series");
    out.vtk_series =
        std::make_shared<VtkSeriesWriter>(out.vtk_series_out->path(), out.vtk_series_dir);
  }
}

// Each frame as DIR/frame_NNNNN.png (with `png`) and into the --video file (when `out` has
// one); a failed video write throws UsageError naming --video.
std::function<void(int, const Image&)> frame_writer(const RunOutput& out, bool png) {
  return [dir = out.dir, into = out.out, png, video = out.video](int i, const Image& frame) {
    if (png) {
      std::ostringstream name;
      name << "frame_" << std::setw(5) << std::setfill('0') << i << ".png";
      write_file_inside((fs::path(into->path()) / name.str()).string(), encode_png(frame),
                        (fs::path(dir) / name.str()).string());
    }
    if (!video) return;
    try {
      video->add_frame(frame);
    } catch (const VideoFileError& e) {
      throw UsageError(std::string("--video: ") + e.what());
    }
  };
}

// The progress lines on `err`: every tenth frame of each pass of a run of 200 frames or more,
// nothing when `quiet`. `err` must outlive the returned function.
std::function<void(int, int)> progress_reporter(const RunOutput& out, bool quiet,
                                                std::ostream& err) {
  const int passes = out.timing_repetitions + (out.warm_up ? 1 : 0);
  const char* what = out.warm_up ? " (a warm-up, then the timed passes)\n" : " (timed passes)\n";
  return [quiet, passes, what, &err](int done, int total) {
    const int frames = total / passes;
    if (quiet || frames < 200) return;
    const int frame = (done - 1) % frames + 1;
    if (frame % std::max(1, frames / 10) == 0 || frame == frames) {
      err << "animate: frame " << frame << "/" << frames << " of pass " << (done - 1) / frames + 1
          << "/" << passes << what << std::flush;
    }
  };
}

bool is_obj_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj";
}

}  // namespace

FrameBudget read_frame_budget(const CliArgs& a) {
  if (a.has("--budget-pixels") && a.has("--budget-ms")) {
    throw UsageError("--budget-ms: give either --budget-pixels or --budget-ms, not both");
  }
  FrameBudget budget;
  const std::tuple<const char*, FrameBudget::Unit, const Limit&> options[] = {
      {"--budget-pixels", FrameBudget::Unit::kPixels, limits::kBudgetPixels},
      {"--budget-ms", FrameBudget::Unit::kMilliseconds, limits::kBudgetMs}};
  for (const auto& [name, unit, limit] : options) {
    if (a.has(name)) budget = {unit, a.number_in(name, limit)};
  }
  return budget;
}

EngineSettings read_engine_settings(const CliArgs& a) {
  EngineSettings s;
  const std::string mode = a.text_or("--mode", default_reuse_policy().name);
  s.policy = find_reuse_policy(mode);
  if (!s.policy) {
    throw UsageError("--mode: '" + mode + "' is not one of " + reuse_policy_names() + ", " +
                     source_kind_modes());
  }
  if (a.has("--threshold") && a.has("--thresholds")) {
    throw UsageError("--thresholds: give either --threshold or --thresholds, not both");
  }
  if (a.has("--threshold")) s.thresholds.fill(a.number_in("--threshold", limits::kThreshold));
  if (a.has("--thresholds")) {
    const std::vector<double> t = a.numbers_in("--thresholds", limits::kThreshold);
    std::copy(t.begin(), t.end(), s.thresholds.begin());  // kTermCount values (the arity)
  }
  const std::string delta = a.text_or("--delta", delta_policy_name(s.delta));
  if (!parse_delta_policy(delta, &s.delta)) {
    throw UsageError("--delta: '" + delta + "' is not one of " + delta_policy_name_list());
  }
  s.sampling = read_sampling(a);
  const std::string content = a.text_or("--content", content_name(s.content.kind));
  if (!parse_content(content, &s.content.kind)) {
    throw UsageError("--content: '" + content + "' is not one of " + content_name_list());
  }
  if (a.has("--quality")) s.content.quality = a.integer_in("--quality", limits::kContentQuality);
  s.budget = read_frame_budget(a);
  if (a.has("--cadence")) {
    s.cadence = a.integer_in("--cadence", limits::kCadence);
    if (s.policy->schedule != Schedule::kCadence && !a.has("--policies")) {
      std::string on_cadence;
      for (const ReusePolicy& p : reuse_policies()) {
        if (p.schedule == Schedule::kCadence)
          on_cadence += (on_cadence.empty() ? "" : ", ") + std::string(p.name);
      }
      throw UsageError("--cadence: needs a policy on a fixed cadence (" + on_cadence + "), not '" +
                       mode + "'");
    }
  }
  if (a.has("--stabilization-plane")) {
    const std::vector<double> v =
        a.numbers_in("--stabilization-plane", limits::kStabilizationPlane);
    s.stabilization.automatic = false;
    s.stabilization.point = Vec3(v[0], v[1], v[2]);
    s.stabilization.normal = Vec3(v[3], v[4], v[5]);
    if (!(glm::length(s.stabilization.normal) > 0.0)) {
      throw UsageError("--stabilization-plane: the normal NX NY NZ must not be zero");
    }
  }
  // compare checks its --policies list itself (analysis/cli/compare_command.cpp).
  if (s.budget.unit != FrameBudget::Unit::kNone && !s.policy->shares_budget &&
      !a.has("--policies")) {
    throw UsageError(std::string(a.has("--budget-ms") ? "--budget-ms" : "--budget-pixels") +
                     ": needs --mode budget (the only policy with a frame budget), not '" + mode +
                     "'");
  }
  return s;
}

RunSource read_plane_source(const CliArgs& a) {
  std::string path;
  try {
    path = resolve_script_path(a.values("--script").at(0));
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--script: ") + e.what());
  }
  RunSource source;
  source.script = read_script_file(path);
  source.texture = read_image(a.text_or("--texture", default_texture_path()));
  source.settings.engine = read_engine_settings(a);
  const std::string samples =
      plane_shaded_samples_problem(source.settings.engine.content, source.script.camera);
  if (!samples.empty()) throw UsageError("--quality: " + samples);
  return source;
}

Sampling read_sampling(const CliArgs& a) {
  Sampling sampling = Sampling::kNearest;
  const std::string text = a.text_or("--sampling", sampling_name(sampling));
  if (!parse_sampling(text, &sampling)) {
    throw UsageError("--sampling: '" + text + "' is not one of " + sampling_name_list());
  }
  return sampling;
}

RunOutput read_run_output(const CliArgs& a, std::ostream& err) {
  RunOutput out;
  read_timing_options(a, out);
  check_output_dirs(a, out);
  out.video = read_video_option(a);  // checked before --out DIR's temporary is created
  open_output_dirs(a, out);
  const bool png = a.has("--frames-png");
  if (png || out.video) out.on_frame = frame_writer(out, png);
  out.progress = progress_reporter(out, a.has("--quiet"), err);
  return out;
}

void RunOutput::apply_timing_to(RunOptions& options) const {
  options.max_frames = max_frames;
  options.warm_up = warm_up;
  options.timing_repetitions = timing_repetitions;
  options.progress = progress;
}

void RunOutput::apply_to(RunOptions& options, const SourceKind& kind) const {
  apply_timing_to(options);
  options.on_frame = on_frame;
  options.keep_frames = false;
  if (vtk_series) {
    options.on_animators = [series = vtk_series](int i, const Animator& shown,
                                                 const Animator* exact) {
      if (!exact) throw std::logic_error("--vtk-series: the run has no exact baseline");
      series->add_frame({i, &shown.camera(), &shown.image(), &exact->image(), shown.outlines()});
    };
  }
  if (!csv) return;
  const std::string shown = (fs::path(dir) / "frames.csv").string();
  csv->open(fs::path(out->path()) / "frames.csv");
  if (!*csv) throw FileWriteError("'" + shown + "': cannot create the file");
  // The header waits for the first frame, which says whether the rows carry hole pixels.
  options.on_record = [csv = csv, shown, header = kind.write_csv_header, row = kind.write_csv_row,
                       extra = kind.hole_extra_columns,
                       first = true](const FrameRecord& record) mutable {
    if (first) write_csv_header_for(*csv, header, record.frame.reports_holes, extra);
    first = false;
    row(*csv, record);
    // A full disk shows when the stream's buffer is written: the run stops there.
    if (!*csv) throw FileWriteError("'" + shown + "': cannot write the file");
  };
}

void RunOutput::finish() const {
  if (vtk_series) {
    vtk_series->finish();
    vtk_series_out->commit();
  }
  if (!video) return;
  try {
    video->finish();
  } catch (const VideoFileError& e) {
    throw UsageError(std::string("--video: ") + e.what());
  }
}

void RunOutput::write_summary(const nlohmann::json& summary) const {
  if (dir.empty()) return;
  csv->close();
  if (!*csv)
    throw FileWriteError("'" + (fs::path(dir) / "frames.csv").string() +
                         "': cannot write the file");
  write_file_inside((fs::path(out->path()) / "summary.json").string(), summary.dump(2) + "\n",
                    (fs::path(dir) / "summary.json").string());
  out->commit();
}

int report_scene_input_errors(const std::function<int()>& body, std::ostream& err,
                              const char* command) {
  try {
    return body();
  } catch (const SceneError& e) {
    err << "oflab-cli " << command << ": --scene: " << e.what() << "\n";
  } catch (const ViewerScriptError& e) {
    err << "oflab-cli " << command << ": --script: " << e.what() << "\n";
  } catch (const ImageFileError& e) {
    err << "oflab-cli " << command << ": " << e.what() << "\n";
  } catch (const std::invalid_argument& e) {
    err << "oflab-cli " << command << ": --scene: " << e.what() << "\n";
  }
  return 2;
}

Scene read_scene_option(const CliArgs& a) {
  const std::string arg = a.values("--scene").at(0);
  Image replacement;
  if (a.has("--texture")) {
    try {
      replacement = read_image(a.values("--texture").at(0));
    } catch (const ImageFileError& e) {
      throw UsageError(std::string("--texture: ") + e.what());
    }
  }
  Scene scene;
  if (is_obj_file(arg)) {
    Image texture = replacement;
    if (texture.empty()) texture = read_image(tile_texture_path());
    return read_obj_scene(arg, texture, a.has("--texture") ? "texture" : "tile");
  }
  std::string path;
  try {
    path = resolve_scene_path(arg);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--scene: ") + e.what());
  }
  scene = read_scene_file(path);
  if (!replacement.empty()) {
    for (Image& t : scene.textures) t = replacement;
  }
  if (a.has("--content")) {
    for (ScenePolygon& p : scene.polygons) p.content = read_engine_settings(a).content.kind;
  }
  return scene;
}

ViewerScript read_viewer_script_option(const CliArgs& a) {
  if (!a.has("--script")) throw UsageError("--script: a viewer script is needed with --scene");
  std::string path;
  try {
    path = resolve_viewer_script_path(a.values("--script").at(0));
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--script: ") + e.what());
  }
  return read_viewer_script_file(path);
}

const std::map<std::string, int>& run_options() {
  static const std::map<std::string, int> options = {
      {"--script", 1},        {"--scene", 1},
      {"--texture", 1},       {"--frames", 1},
      {"--threshold", 1},     {"--thresholds", 4},
      {"--delta", 1},         {"--sampling", 1},
      {"--content", 1},       {"--quality", 1},
      {"--budget-pixels", 1}, {"--budget-ms", 1},
      {"--cadence", 1},       {"--stabilization-plane", 6},
      {"--hole-fill", 1},     {"--cache-angle", 1},
      {"--node-polygons", 1}, {"--safety-radius", 1},
      {"--mesh-grid", 1},     {"--mesh-split", 1},
      {"--mesh-rebuild", 1},  {"--mesh-jump", 1},
      {"--rubber-sheets", 1}, {"--near", 1},
      {"--guard-band", 1},    {"--no-skip-hidden", 0},
      {"--repeat-timing", 1}, {"--out", 1},
      {"--force", 0},         {"--json", 0},
      {"--quiet", 0}};
  return options;
}

}  // namespace oflab
