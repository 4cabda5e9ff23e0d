// The trial loop of a threshold study (manual/study.md): a small state machine that the
// desktop window, the page and `oflab-cli study simulate` drive alike. It says what to show
// next (a condition, the error the method requests, which clip of the pair is the distorted
// one) and takes the observer's answer with the error the engine actually showed and whether
// the clips' frames were late. Conditions are interleaved in a random order; a late trial is
// recorded (late = true), not given to the method, and shown again. Deterministic for a seed
// (study/study_random.h): the same study, method, seed and answers give the same trials on
// every platform. Plain C++.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "study/adaptive_methods.h"
#include "study/psychometric.h"
#include "study/study_file.h"
#include "study/study_random.h"

namespace oflab {

// What to show next.
struct TrialRequest {
  int condition = 0;             // index into Study::conditions
  int trial = 0;                 // the condition's answered (not late) trials before this one
  double requested_px = 0.0;     // the error the method asks for, pixels
  bool distorted_first = false;  // the reused (distorted) clip plays first
};

// One presentation as recorded.
struct StudyTrial {
  TrialRequest request;
  double measured_px = 0.0;  // the engine's measured error of the frames shown, pixels
  bool correct = false;
  bool late = false;  // frames were late: not counted, shown again
};

class StudySession {
 public:
  // A session of `study` with the method called `method` (one of adaptive_methods(); throws
  // std::invalid_argument naming it otherwise), seeded by `seed`.
  StudySession(const Study& study, const std::string& method, std::uint64_t seed);

  // True when every condition has study.trials answered trials.
  bool finished() const;
  // What to show now. Precondition: !finished().
  const TrialRequest& request() const { return request_; }
  // The answer to request(): correct or not, the error shown (pixels, finite, >= 0) and
  // whether its frames were late. Throws std::invalid_argument for a bad measured error or
  // when finished().
  void answer(bool correct, double measured_px, bool late);

  const Study& study() const { return study_; }
  const std::string& method_name() const { return method_name_; }
  const AdaptiveMethod& method(int condition) const { return *methods_[size_t(condition)]; }
  const std::vector<StudyTrial>& trials() const { return trials_; }
  int late_trials() const { return late_; }
  // Answered (not late) trials so far, over every condition.
  int answered_trials() const { return int(trials_.size()) - late_; }

 private:
  Study study_;
  std::string method_name_;
  StudyRandom random_;
  std::vector<std::unique_ptr<AdaptiveMethod>> methods_;
  std::vector<int> answered_;
  std::vector<StudyTrial> trials_;
  TrialRequest request_;
  int late_ = 0;
  void draw_request();
};

// How a requested error becomes the error shown, for one condition: pixels to pixels. The
// engine's (study/engine_display.h) plays the condition's motion with the policy and
// returns its measured error.
using ErrorDisplay = std::function<double(int condition, double requested_px)>;

// A simulated observer: answers drawn from `function` with its own generator seeded from
// `seed` (so its answers never shift a session's draws); a fraction `late_fraction` of
// presentations is flagged late (drawn first, only when late_fraction > 0). The desktop
// window's simulated runs and simulate_answers draw through it, so one seed gives one trial
// sequence everywhere.
class SimulatedObserver {
 public:
  SimulatedObserver(std::uint64_t seed, const PsychometricFunction& function,
                    double late_fraction = 0.0);
  struct Answer {
    bool correct = false;
    bool late = false;
  };
  // The answer to a presentation showing `shown_px` (pixels, >= 0).
  Answer answer(double shown_px);

 private:
  StudyRandom random_;
  PsychometricFunction function_;
  double late_fraction_ = 0.0;
};

// Plays `session` to its end with SimulatedObserver(seed, observer, late_fraction) answering
// each request shown at display()'s error.
void simulate_answers(StudySession& session, std::uint64_t seed,
                      const PsychometricFunction& observer, const ErrorDisplay& display,
                      double late_fraction = 0.0);

}  // namespace oflab
