// The single-plane animator of core/engine/animator.h: a motion script played through one
// PlaneEngine (core/engine/engine.h), its displayed layer composed into a camera-sized
// frame, and the plane seen as a one-polygon scene (core/scene/scene.h plane_as_scene).
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/animator.h"
#include "image/composite.h"

namespace oflab {

namespace {

class PlaneScriptAnimator final : public Animator {
 public:
  PlaneScriptAnimator(const MotionScript& script, const Image& texture,
                      const EngineSettings& settings, int repeat)
      : script_(script),
        repeat_(repeat),
        texture_(make_layer(texture)),
        settings_(settings),
        scene_(plane_as_scene(script.frames.at(0).pose, texture)),
        image_(script.camera.width, script.camera.height) {
    // The plane's polygon shows the engine's content, so that an exact renderer of scene()
    // draws what a re-render draws.
    scene_.polygons[0].content = settings.content.kind;
    scene_.content_quality = settings.content.quality;
  }

  int frame_count() const override { return static_cast<int>(script_.frames.size()) * repeat_; }
  int frame() const override { return frame_; }

  AnimationFrame start() override {
    engine_ = std::make_unique<PlaneEngine>(script_.camera, texture_, settings_);
    ledger_ = std::make_unique<BudgetLedger>(*settings_.policy, settings_.budget,
                                             script_.camera.width, script_.camera.height);
    frame_ = 0;
    return play(engine_->measure_start(script_.frames[0].pose));
  }

  AnimationFrame advance() override {
    const ScriptFrame& previous = script_frame(frame_);
    ++frame_;
    return play(
        engine_->measure_advance(previous.pose, previous.motion, script_frame(frame_).pose));
  }

  const Image& image() const override {
    if (!image_current_) {
      image_.fill(Pixel{});
      if (visible_ && !engine_->displayed().layer.empty()) {
        const PlacedLayer& shown = engine_->displayed();
        composite_over(image_, shown.layer, shown.offset_x, shown.offset_y);
      }
      image_current_ = true;
    }
    return image_;
  }

  const Camera& camera() const override { return script_.camera; }

  std::vector<LayerOutline> outlines() const override {
    if (!visible_) return {};
    LayerOutline outline;
    outline.level = level_;
    outline.error_px = error_px_;
    outline.points = engine_->displayed_outline();
    if (outline.points.empty()) return {};
    return {outline};
  }

  const Scene& scene() const override { return scene_; }

  ViewerPose view() const override {
    return viewer_for_pose(script_.frames[0].pose, script_frame(std::max(frame_, 0)).pose);
  }

 private:
  // The script frame shown at animation frame k (the script played over and over).
  const ScriptFrame& script_frame(int k) const {
    return script_.frames.at(static_cast<size_t>(k) % script_.frames.size());
  }

  // The allocate and apply phases of the frame measured as `candidates` (the plane is the
  // frame's one layer).
  AnimationFrame play(const LayerCandidates& candidates) {
    const FrameAllocation a = ledger_->allocate(frame_, {candidates});
    const FrameReport r = engine_->apply(a.levels[0], a.shown[0] != 0);
    ledger_->applied(r.level, r.time_ms, r.pixels_written, a.starved[0] != 0);
    AnimationFrame f = report(r);
    f.budget = ledger_->finish();
    return f;
  }

  AnimationFrame report(const FrameReport& r) {
    visible_ = r.visible;
    level_ = r.level;
    error_px_ = r.measured_error_px;
    image_current_ = false;
    AnimationFrame f;
    f.frame = r.frame;
    f.layers = 1;
    f.reports_holes = reports_holes(*settings_.policy);
    if (r.visible) {
      f.levels[static_cast<int>(r.level)] = 1;
      f.max_measured_error_px = r.measured_error_px;
      f.clipped = r.clipped ? 1 : 0;
    }
    f.time_ms = r.time_ms;
    f.update_ms = r.time_ms;
    f.pixels_written = r.pixels_written;
    f.model_work = r.model_work;
    f.render_ms = r.render_ms;
    f.max_photometric_error = r.photometric_error;
    f.layer_reports.push_back(r);
    f.note = r.note;
    return f;
  }

  MotionScript script_;
  int repeat_;
  Layer texture_;
  EngineSettings settings_;
  Scene scene_;
  std::unique_ptr<PlaneEngine> engine_;
  std::unique_ptr<BudgetLedger> ledger_;
  int frame_ = -1;
  bool visible_ = false;
  Level level_ = Level::kNone;
  double error_px_ = 0.0;  // the shown layer's measured error, pixels
  mutable Image image_;    // composed on demand from the engine's displayed layer
  mutable bool image_current_ = false;
};

}  // namespace

std::unique_ptr<Animator> make_plane_animator(const MotionScript& script, const Image& texture,
                                              const EngineSettings& settings, int repeat) {
  if (script.frames.empty()) throw std::invalid_argument("the motion script has no frames");
  if (std::string why; needs_scene(*settings.policy, &why)) {
    throw std::invalid_argument(std::string(settings.policy->name) +
                                " needs a scene (--scene): " + why);
  }
  const long frames = static_cast<long>(script.frames.size());
  if (repeat < 1 || frames * repeat > std::numeric_limits<int>::max()) {
    throw std::invalid_argument("the motion script's " + std::to_string(frames) +
                                " frames cannot be played " + std::to_string(repeat) +
                                " times (1 .. " +
                                std::to_string(std::numeric_limits<int>::max() / frames) + ")");
  }
  return std::make_unique<PlaneScriptAnimator>(script, texture, settings, repeat);
}

}  // namespace oflab
