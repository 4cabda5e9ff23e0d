// Warping what shows: the whole warp against the visible-only warp on shipped scenes
// (dissertation section 7.5.3; experiments_visible_warp.h).
#include "experiments/experiments_visible_warp.h"

#include <memory>
#include <numeric>
#include <stdexcept>

#include "experiments/experiments_runs.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

// The script's frames first .. first + frames - 1 (to its end with frames -1), its camera
// shrunk by `divisor` about the same view.
ViewerScript source_script(const VisibleWarpSource& source, int divisor) {
  ViewerScript v = read_viewer_script_file(resolve_viewer_script_path(source.viewer));
  const Camera& c = v.camera;
  v.camera = make_camera(c.focal_px / divisor, c.width / divisor, c.height / divisor);
  const int available = int(v.frames.size()) - source.first_frame;
  if (source.first_frame < 0 || available < 1) {
    throw std::invalid_argument("viewer script " + source.viewer + " has no frame " +
                                std::to_string(source.first_frame));
  }
  v.frames.erase(v.frames.begin(), v.frames.begin() + source.first_frame);
  if (source.frames > 0 && source.frames < available) v.frames.resize(size_t(source.frames));
  return v;
}

// Plays `source` whole and visible-only side by side, frame by frame.
VisibleWarpRun play_source(const VisibleWarpSource& source, const VisibleWarpSpec& spec) {
  const auto scene =
      std::make_shared<const Scene>(read_scene_file(resolve_scene_path(source.scene)));
  const ViewerScript script = source_script(source, spec.camera_divisor);
  SceneSettings settings;
  settings.engine.policy = &reuse_policy(spec.policy);
  settings.engine.warp_area = WarpArea::kWhole;
  auto whole = make_scene_animator(scene, script, settings);
  settings.engine.warp_area = WarpArea::kVisible;
  auto visible = make_scene_animator(scene, script, settings);
  VisibleWarpRun run;
  run.source = source;
  run.width = script.camera.width;
  run.height = script.camera.height;
  for (size_t k = 0; k < script.frames.size(); ++k) {
    const AnimationFrame w = k == 0 ? whole->start() : whole->advance();
    const AnimationFrame v = k == 0 ? visible->start() : visible->advance();
    run.written.push_back(w.pixels_written);
    run.whole.push_back(w.pixels_written - w.pixels_not_warped);
    run.visible.push_back(v.pixels_written - v.pixels_not_warped);
    run.whole_ms.push_back(w.time_ms);
    run.visible_ms.push_back(v.time_ms);
    run.differing_frames += whole->image().pixels() != visible->image().pixels();
  }
  return run;
}

std::string source_name(const VisibleWarpRun& r) {
  const int last = r.source.first_frame + int(r.written.size()) - 1;
  return r.source.scene + " under " + r.source.viewer + " (frames " +
         std::to_string(r.source.first_frame) + " to " + std::to_string(last) + ", " +
         std::to_string(r.width) + " x " + std::to_string(r.height) + ")";
}

Chart visible_warp_chart(const VisibleWarpResult& result) {
  Chart chart;
  for (const VisibleWarpRun& r : result.runs) {
    ChartPanel panel;
    panel.title = source_name(r);
    panel.x_label = "frame";
    panel.y_label = "pixels warped";
    ChartSeries whole{"whole", {}, {}, SeriesStyle::kLine, chart_palette(0)};
    ChartSeries visible{"visible-only", {}, {}, SeriesStyle::kLine, chart_palette(1)};
    ChartSeries left_out{"whole - visible", {}, {}, SeriesStyle::kLine, chart_palette(2)};
    for (size_t k = 0; k < r.written.size(); ++k) {
      const double frame = r.source.first_frame + int(k);
      for (ChartSeries* s : {&whole, &visible, &left_out}) s->x.push_back(frame);
      whole.y.push_back(double(r.whole[k]));
      visible.y.push_back(double(r.visible[k]));
      left_out.y.push_back(double(r.whole[k] - r.visible[k]));
    }
    panel.series = {whole, visible, left_out};
    chart.panels.push_back(std::move(panel));
  }
  return chart;
}

ReportTable visible_warp_table(const VisibleWarpResult& result) {
  ReportTable t;
  t.caption =
      "Pixels the warps computed over every frame, the whole warp against the "
      "visible-only warp (" +
      result.spec.policy + " policy), the frames compared byte for byte, and the median frame time";
  t.header = {"scene, viewer script", "frames",           "pixels written",
              "warped, whole",        "warped, visible",  "drop",
              "frames that differ",   "median ms, whole", "median ms, visible"};
  for (const VisibleWarpRun& r : result.runs) {
    t.rows.push_back(
        {r.source.scene + ", " + r.source.viewer, std::to_string(r.written.size()),
         std::to_string(std::accumulate(r.written.begin(), r.written.end(), std::int64_t{0})),
         std::to_string(r.total_whole()), std::to_string(r.total_visible()), percent(r.drop()),
         std::to_string(r.differing_frames), fixed(median_of(r.whole_ms), 3),
         fixed(median_of(r.visible_ms), 3)});
  }
  return t;
}

}  // namespace

std::int64_t VisibleWarpRun::total_whole() const {
  return std::accumulate(whole.begin(), whole.end(), std::int64_t{0});
}

std::int64_t VisibleWarpRun::total_visible() const {
  return std::accumulate(visible.begin(), visible.end(), std::int64_t{0});
}

double VisibleWarpRun::drop() const {
  const std::int64_t w = total_whole();
  return w > 0 ? 1.0 - double(total_visible()) / double(w) : 0.0;
}

VisibleWarpSpec visible_warp_spec(bool quick) {
  VisibleWarpSpec spec;
  // Quick: the frames of the street where most of its drop falls (a wall layer reaching past
  // the frame's edge, frames 65 to 89), at a quarter of the size.
  spec.sources = {{"four-cubes", "compound", 0, quick ? 60 : -1},
                  {"street", "walk", quick ? 60 : 0, quick ? 30 : -1}};
  spec.camera_divisor = quick ? 4 : 1;
  return spec;
}

VisibleWarpResult run_visible_warp_experiment(
    const VisibleWarpSpec& spec, const std::function<void(const std::string&)>& progress) {
  if (!find_reuse_policy(spec.policy)) {
    throw std::invalid_argument("'" + spec.policy + "' is not a reuse policy");
  }
  VisibleWarpResult result;
  result.spec = spec;
  for (const VisibleWarpSource& source : spec.sources) {
    if (progress) progress(source.scene + " under " + source.viewer + ", whole and visible-only");
    result.runs.push_back(play_source(source, spec));
  }
  return result;
}

std::vector<std::string> visible_warp_summary_lines(const VisibleWarpResult& result) {
  std::vector<std::string> lines;
  for (const VisibleWarpRun& r : result.runs) {
    lines.push_back(source_name(r) + ": " + std::to_string(r.total_whole()) +
                    " pixels warped whole, " + std::to_string(r.total_visible()) +
                    " visible-only (" + signed_fixed(-100.0 * r.drop(), 1) + " %); " +
                    std::to_string(r.differing_frames) + " of " + std::to_string(r.written.size()) +
                    " frames differ");
  }
  return lines;
}

ReportSection visible_warp_section(const VisibleWarpResult& result, ExperimentContext& context) {
  ReportSection s;
  s.id = "visible-warp";
  s.title = "Warping what shows: visible-only warps (7.5.3)";
  s.paragraph(
      "The dissertation's compositing warps every polygon in the frustum, \"even if that "
      "polygon turns out to be partially or totally occluded\" (section 7.5.3). The "
      "visible-only warp (--warp visible) computes of each layer only the pixels the frame "
      "will show: not those under an opaque layer in front, nor those beyond the frame. Each "
      "source below is played twice under the " +
      result.spec.policy +
      " policy, whole and visible-only, with every other setting the default; the policy's "
      "choices, and so the pixels it writes, are the same, and only the pixels computed drop.");
  for (const std::string& line : visible_warp_summary_lines(result)) s.paragraph(line + ".");
  s.figure(context.add_chart(
      "visible-warp-pixels", visible_warp_chart(result),
      "Pixels the warps computed per frame, the whole warp against the visible-only warp, and "
      "their difference: the pixels left out, negative in a frame where a reused layer "
      "computes pixels it left out before and shows now. One panel per source."));
  s.table(visible_warp_table(result));
  s.paragraph(
      "Frame times depend on the machine and its load: the visible-only warp's bookkeeping "
      "(the shown pixels as runs per row, cut by each occluder) is paid every frame, the pixels "
      "it saves only where layers hide each other or leave the frame.");
  return s;
}

}  // namespace oflab
