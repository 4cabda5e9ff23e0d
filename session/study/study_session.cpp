#include "study/study_session.h"

#include <cmath>
#include <stdexcept>

namespace oflab {

StudySession::StudySession(const Study& study, const std::string& method, std::uint64_t seed)
    : study_(study), method_name_(method), random_(seed) {
  const AdaptiveMethodKind* kind = find_adaptive_method(method);
  if (!kind) {
    throw std::invalid_argument("'" + method + "' is not one of " + adaptive_method_names());
  }
  MethodSettings settings;
  settings.min_px = study.min_px, settings.max_px = study.max_px;
  for (size_t c = 0; c < study.conditions.size(); ++c) methods_.push_back(kind->make(settings));
  answered_.assign(study.conditions.size(), 0);
  if (!finished()) draw_request();
}

bool StudySession::finished() const {
  for (int n : answered_) {
    if (n < study_.trials) return false;
  }
  return true;
}

void StudySession::draw_request() {
  std::vector<int> open;
  for (size_t c = 0; c < answered_.size(); ++c) {
    if (answered_[c] < study_.trials) open.push_back(int(c));
  }
  request_.condition = open[size_t(random_.below(open.size()))];
  request_.trial = answered_[size_t(request_.condition)];
  request_.requested_px = methods_[size_t(request_.condition)]->next_error_px();
  request_.distorted_first = random_.chance(0.5);
}

void StudySession::answer(bool correct, double measured_px, bool late) {
  if (finished()) throw std::invalid_argument("the session has finished");
  if (!std::isfinite(measured_px) || measured_px < 0.0) {
    throw std::invalid_argument("the measured error must be a finite number >= 0 px");
  }
  trials_.push_back({request_, measured_px, correct, late});
  if (late) {
    ++late_;  // shown again as it was: the same level and order
    return;
  }
  methods_[size_t(request_.condition)]->record(request_.requested_px, measured_px, correct);
  ++answered_[size_t(request_.condition)];
  if (!finished()) draw_request();
}

SimulatedObserver::SimulatedObserver(std::uint64_t seed, const PsychometricFunction& function,
                                     double late_fraction)
    : random_(SplitMix64(seed ^ 0x6f626e657276ULL).next()),
      function_(function),
      late_fraction_(late_fraction) {}

SimulatedObserver::Answer SimulatedObserver::answer(double shown_px) {
  Answer a;
  a.late = late_fraction_ > 0.0 && random_.chance(late_fraction_);
  a.correct = random_.chance(function_.correct(shown_px));
  return a;
}

void simulate_answers(StudySession& session, std::uint64_t seed,
                      const PsychometricFunction& observer, const ErrorDisplay& display,
                      double late_fraction) {
  SimulatedObserver simulated(seed, observer, late_fraction);
  while (!session.finished()) {
    const TrialRequest& r = session.request();
    const double shown = display(r.condition, r.requested_px);
    const SimulatedObserver::Answer a = simulated.answer(shown);
    session.answer(a.correct, shown, a.late);
  }
}

}  // namespace oflab
