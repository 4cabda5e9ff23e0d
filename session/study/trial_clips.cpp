#include "study/trial_clips.h"

#include <stdexcept>

#include "engine/exact_render.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "image/composite.h"
#include "image/layer.h"
#include "image/warp.h"

namespace oflab {
namespace {

constexpr Pixel kBackground{128, 128, 128, 255};

Image grating() {
  Image image(kClipTextureWidth, kClipTextureHeight, Pixel{255, 255, 255, 255});
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      if ((x / 4) % 2 == 1) image.at(x, y) = Pixel{0, 0, 0, 255};
    }
  }
  return image;
}

// `source` resampled to the clip texture's size: one bilinear warp scaling its rectangle onto
// the target's.
Image resampled(const Image& source) {
  const Mat3 scale(double(kClipTextureWidth) / source.width(), 0.0, 0.0, 0.0,
                   double(kClipTextureHeight) / source.height(), 0.0, 0.0, 0.0, 1.0);
  Image out(kClipTextureWidth, kClipTextureHeight, Pixel{});
  WarpOptions options;
  options.sampling = Sampling::kBilinear;
  warp_layer_into(make_layer(source), scale, out, 0, 0, options);
  return out;
}

// A clip's frame: `shown` over the background, or the background alone when nothing is shown.
Image frame_of(const PlacedLayer* shown) {
  Image frame(kClipWidth, kClipHeight, kBackground);
  if (shown && !shown->layer.empty()) {
    composite_over(frame, shown->layer, shown->offset_x, shown->offset_y);
  }
  return frame;
}

}  // namespace

Image study_texture(StudyTexture texture) {
  if (texture == StudyTexture::kGrating) return grating();
  return resampled(read_image(default_texture_path()));
}

TrialClips make_trial_clips(const Study& study, const std::vector<ErrorLadder>& ladders,
                            const TrialRequest& request, const Image& texture) {
  if (texture.width() != kClipTextureWidth || texture.height() != kClipTextureHeight) {
    throw std::invalid_argument("a study texture must be 256 x 192 texels");
  }
  const StudyCondition& condition = study.conditions.at(size_t(request.condition));
  const ErrorLadder& ladder = ladders.at(size_t(request.condition));
  TrialClips clips;
  clips.threshold_px = ladder.thresholds_px[size_t(shown_rung(ladder, request.requested_px))];
  std::vector<Image> reused, exact;
  clips.measured_px =
      play_reused_clip(condition, clips.threshold_px, make_layer(texture),
                       [&](const PlaneEngine& engine, const FrameReport& report) {
                         reused.push_back(frame_of(report.visible ? &engine.displayed() : nullptr));
                       });
  const Layer layer = make_layer(texture);
  const Sampling sampling = EngineSettings{}.sampling;
  for (const ScriptFrame& f : clip_script(condition)) {
    if (!plane_visibility_problem(f.pose).empty()) {
      exact.push_back(frame_of(nullptr));
      continue;
    }
    const PlacedLayer shown = render_exact(clip_camera(), layer, f.pose, sampling);
    exact.push_back(frame_of(&shown));
  }
  clips.first = request.distorted_first ? std::move(reused) : std::move(exact);
  clips.second = request.distorted_first ? std::move(exact) : std::move(reused);
  return clips;
}

TrialRunner::TrialRunner(const Study& study, const std::string& method, std::uint64_t seed)
    : session_(study, method, seed), ladders_(study_ladders(study)) {}

const TrialClips& TrialRunner::clips() {
  if (!clips_) {
    const TrialRequest& r = request();
    const StudyTexture texture = session_.study().conditions.at(size_t(r.condition)).texture;
    Image& image = textures_[size_t(texture)];
    if (image.empty()) image = study_texture(texture);
    clips_ = std::make_unique<TrialClips>(make_trial_clips(session_.study(), ladders_, r, image));
  }
  return *clips_;
}

void TrialRunner::answer(int chosen, bool late) {
  if (chosen != 1 && chosen != 2) throw std::invalid_argument("the answer must be clip 1 or 2");
  const double measured = clips().measured_px;
  const bool correct = (chosen == 1) == request().distorted_first;
  session_.answer(correct, measured, late);
  if (!late) clips_.reset();  // a late trial is shown again as it was
}

int TrialRunner::chosen_for(bool correct) const {
  return (correct == request().distorted_first) ? 1 : 2;
}

void run_simulated(TrialRunner& runner, SimulatedObserver& observer) {
  while (!runner.finished()) {
    const SimulatedObserver::Answer a = observer.answer(runner.clips().measured_px);
    runner.answer(runner.chosen_for(a.correct), a.late);
  }
}

}  // namespace oflab
