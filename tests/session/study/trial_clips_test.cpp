// The pictures of a trial (session/study/trial_clips.h): the reused clip is the ladder's run
// (its measured error is the rung's, exactly), the clips come in the request's order, and the
// plane drawn in the reused clip's last frame is off the exact one's by no more than the
// measured error says, and by about as much, read from the images alone.
#include "study/trial_clips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};

// The bounding box of the pixels that are not the background grey.
Box drawn_box(const Image& frame) {
  Box b;
  for (int y = 0; y < frame.height(); ++y) {
    for (int x = 0; x < frame.width(); ++x) {
      if (frame.at(x, y) == Pixel{128, 128, 128, 255}) continue;
      b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
      b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
    }
  }
  return b;
}

int largest_edge_shift(const Box& a, const Box& b) {
  return std::max(
      {std::abs(a.x0 - b.x0), std::abs(a.y0 - b.y0), std::abs(a.x1 - b.x1), std::abs(a.y1 - b.y1)});
}

Study one_condition_study() {
  Study s;
  s.name = "t";
  s.min_px = 0.5;
  s.max_px = 8.0;
  s.conditions = {{"p", StudyPolicy::kPerspective, 30.0, StudyTexture::kButterfly, 60.0}};
  return s;
}

TEST(TrialClips, TheReusedClipShowsTheLaddersErrorInTheRequestsOrder) {
  const Study study = one_condition_study();
  const std::vector<ErrorLadder> ladders = {
      play_error_ladder(study.conditions[0], study.min_px, study.max_px, 3)};
  const Image texture = study_texture(StudyTexture::kButterfly);
  TrialRequest request;
  request.requested_px = ladders[0].measured_px[2];
  request.distorted_first = true;
  const TrialClips clips = make_trial_clips(study, ladders, request, texture);
  EXPECT_EQ(clips.measured_px, ladders[0].measured_px[2]);
  EXPECT_EQ(clips.threshold_px, ladders[0].thresholds_px[2]);
  ASSERT_EQ(clips.first.size(), size_t(kClipSeconds * kClipFrameRate));
  ASSERT_EQ(clips.second.size(), clips.first.size());
  EXPECT_EQ(clips.first.front().width(), kClipWidth);
  EXPECT_EQ(clips.first.front().height(), kClipHeight);
  // Frame 0 is rendered in both; the last frames differ by the reused clip's error.
  EXPECT_TRUE(clips.first.front().pixels() == clips.second.front().pixels());
  const int shift =
      largest_edge_shift(drawn_box(clips.first.back()), drawn_box(clips.second.back()));
  EXPECT_GT(clips.measured_px, 2.0);
  EXPECT_LE(shift, int(std::ceil(clips.measured_px)) + 1);
  EXPECT_GE(shift, 1);

  request.distorted_first = false;
  const TrialClips swapped = make_trial_clips(study, ladders, request, texture);
  EXPECT_TRUE(swapped.first.back().pixels() == clips.second.back().pixels());
  EXPECT_TRUE(swapped.second.back().pixels() == clips.first.back().pixels());
}

TEST(TrialClips, TheTexturesAreTheClipsSizeAndTheGratingHasBarsFourTexelsWide) {
  const Image butterfly = study_texture(StudyTexture::kButterfly);
  EXPECT_EQ(butterfly.width(), kClipTextureWidth);
  EXPECT_EQ(butterfly.height(), kClipTextureHeight);
  const Image grating = study_texture(StudyTexture::kGrating);
  ASSERT_EQ(grating.width(), kClipTextureWidth);
  for (int x = 0; x < 16; ++x) {
    EXPECT_EQ(grating.at(x, 7).r, (x / 4) % 2 ? 0 : 255) << x;
  }
  EXPECT_THROW(make_trial_clips(one_condition_study(), {ErrorLadder{{1.0}, {1.0}}}, TrialRequest{},
                                Image(8, 8)),
               std::invalid_argument);
}

// The front-ends' loop (TrialRunner, pictures made for every request) answered by a simulated
// observer gives the trials of simulate_answers over the engine's shown error, late ones too.
TEST(TrialRunner, ASimulatedRunThroughThePicturesIsTheHeadlessSimulation) {
  Study study = one_condition_study();
  study.trials = 3;
  study.method = "staircase";
  const PsychometricFunction observer{1.0, 3.5, 0.02};
  TrialRunner runner(study, study.method, 11);
  SimulatedObserver answers(11, observer, 0.5);
  run_simulated(runner, answers);
  StudySession headless(study, study.method, 11);
  simulate_answers(headless, 11, observer, engine_error_display(study), 0.5);
  const std::vector<StudyTrial>& a = runner.session().trials();
  const std::vector<StudyTrial>& b = headless.trials();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(runner.session().late_trials(), 0);
  EXPECT_EQ(runner.session().answered_trials(), 3);  // one condition, three trials
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].request.requested_px, b[i].request.requested_px) << i;
    EXPECT_EQ(a[i].request.distorted_first, b[i].request.distorted_first) << i;
    EXPECT_EQ(a[i].measured_px, b[i].measured_px) << i;
    EXPECT_EQ(a[i].correct, b[i].correct) << i;
    EXPECT_EQ(a[i].late, b[i].late) << i;
  }
  EXPECT_THROW(TrialRunner(study, "guess", 1), std::invalid_argument);
}

}  // namespace
}  // namespace oflab
