// The psychometric function of the threshold experiment and its fit (manual/study.md).
//
// Two-alternative forced choice (2AFC): each trial shows an exact clip and a distorted one, and
// the observer says which is distorted, so guessing is right half the time (guess rate
// gamma = 0.5). The probability of a correct answer at a shown error x (pixels, the engine's
// measured error) is a Weibull function written with its 75 %-correct point t as parameter:
//     p(x) = gamma + (1 - gamma - lambda) * (1 - exp(-k * (x / t)^beta)),
//     k = -ln(1 - (0.75 - gamma) / (1 - gamma - lambda)),
// so p(t) = 0.75 whatever the slope beta and the lapse rate lambda (the chance of a wrong
// answer however large the error). The threshold of the study is t, in pixels.
//
// The fit (fit_threshold) is maximum likelihood over t with beta and lambda fixed at assumed
// values (the study's; fitting the slope too needs far more trials than a class session
// has), and the confidence interval is a parametric bootstrap with BCa's corrections (Efron
// 1987): answers drawn again from the fitted function at the same shown errors and refitted;
// the interval's ends are the refits' percentiles moved by the bias correction z0 (the share
// of refits below the fit) and the acceleration a (the skew of the jackknife's
// leave-one-trial-out fits). Plain percentiles covered the truth in 90.5 to 93 % of simulated
// sessions, BCa's in 93.4 to 95.5 % (manual/study.md). Plain C++.
#pragma once

#include <vector>

#include "study/study_random.h"

namespace oflab {

// The guess rate of 2AFC.
constexpr double kGuessRate = 0.5;
// The proportion correct that defines the threshold.
constexpr double kThresholdCorrect = 0.75;

struct PsychometricFunction {
  double threshold_px = 1.0;  // t: the error seen 75 % of the time, pixels (> 0)
  double slope = 3.5;         // beta (> 0): steeper means a sharper change from guess to seen
  double lapse = 0.02;        // lambda, in [0, 0.2]

  // p(x) above for a shown error `error_px` >= 0 pixels.
  double correct(double error_px) const;
};

// One answered trial as the fit sees it.
struct TrialOutcome {
  double error_px = 0.0;  // the shown (measured) error, pixels (> 0)
  bool correct = false;
};

struct ThresholdFit {
  double threshold_px = 0.0;  // the maximum-likelihood t, pixels
  double log_likelihood = 0.0;
  bool at_bound = false;  // the maximum lies at an end of the search range
};

// Where fit_threshold looks: t in [min_px, max_px] (0 < min_px < max_px), with the
// function's assumed slope and lapse.
struct FitSettings {
  double min_px = 0.01;
  double max_px = 100.0;
  double slope = 3.5;
  double lapse = 0.02;
};

// The log-likelihood of `trials` under `f` (natural log; probabilities kept within
// [1e-12, 1 - 1e-12]).
double log_likelihood(const std::vector<TrialOutcome>& trials, const PsychometricFunction& f);

// The maximum-likelihood threshold of `trials` (non-empty, errors > 0): the best of a
// log-spaced grid over [min_px, max_px], refined by golden-section search on log t between
// its neighbours.
ThresholdFit fit_threshold(const std::vector<TrialOutcome>& trials, const FitSettings& settings);

struct ThresholdInterval {
  double low_px = 0.0;
  double high_px = 0.0;
};

// The parametric bootstrap interval of the threshold at `level` (0.95 for 95 %): `replicates`
// (>= 20) sets of answers drawn from the function of threshold `fitted_px` (the maximum-
// likelihood fit of `trials`, with the settings' slope and lapse) at the errors of `trials`,
// each refitted; the BCa percentiles Phi(z0 + (z0 + z) / (1 - a (z0 + z))) of the log refits
// for z the normal quantiles of (1-level)/2 and (1+level)/2 (interpolated between order
// statistics), z0 and a as above (a from len(trials) more fits). Draws from `random`.
ThresholdInterval bootstrap_interval(const std::vector<TrialOutcome>& trials, double fitted_px,
                                     const FitSettings& settings, int replicates, double level,
                                     StudyRandom& random);

// The visual angle of a length of `px` pixels centred in front of the eye, in minutes of arc,
// on a screen of `pixels_per_inch` (> 0) seen from `distance_cm` (> 0) centimetres:
// 2 atan(s / 2d) with s = px / ppi * 2.54 cm.
double arcmin_of_pixels(double px, double pixels_per_inch, double distance_cm);

}  // namespace oflab
