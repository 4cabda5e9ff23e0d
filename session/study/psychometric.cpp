#include "study/psychometric.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The fit's view of the trials: log errors and answers, so one evaluation costs two exps.
struct LogTrials {
  std::vector<double> log_error;
  std::vector<char> correct;
};

LogTrials log_trials(const std::vector<TrialOutcome>& trials) {
  LogTrials t;
  for (const TrialOutcome& trial : trials) {
    t.log_error.push_back(std::log(trial.error_px));
    t.correct.push_back(trial.correct ? 1 : 0);
  }
  return t;
}

double weibull_k(double lapse) {
  return -std::log(1.0 - (kThresholdCorrect - kGuessRate) / (1.0 - kGuessRate - lapse));
}

double clamp_probability(double p) { return std::min(std::max(p, 1e-12), 1.0 - 1e-12); }

// log L at log threshold `log_t`.
double log_likelihood_at(const LogTrials& t, double log_t, double slope, double lapse) {
  const double k = weibull_k(lapse), span = 1.0 - kGuessRate - lapse;
  double sum = 0.0;
  for (size_t i = 0; i < t.log_error.size(); ++i) {
    const double seen = 1.0 - std::exp(-k * std::exp(slope * (t.log_error[i] - log_t)));
    const double p = clamp_probability(kGuessRate + span * seen);
    sum += t.correct[i] ? std::log(p) : std::log(1.0 - p);
  }
  return sum;
}

// The best of `n` log thresholds evenly spaced over [lo, hi] (n >= 2); its index.
int best_of_grid(const LogTrials& t, const FitSettings& s, double lo, double hi, int n,
                 double* best_ll) {
  int best = 0;
  *best_ll = -1e300;
  for (int i = 0; i < n; ++i) {
    const double ll = log_likelihood_at(t, lo + i * (hi - lo) / (n - 1), s.slope, s.lapse);
    if (ll > *best_ll) *best_ll = ll, best = i;
  }
  return best;
}

ThresholdFit fit_log_trials(const LogTrials& t, const FitSettings& s) {
  // A coarse grid over the range, a fine grid between the best point's neighbours (a steep
  // function's likelihood can have several local maxima there), then golden-section search
  // between the fine grid's neighbours of its best.
  constexpr int kCoarse = 12, kFine = 16;
  const double lo = std::log(s.min_px), hi = std::log(s.max_px);
  double ll_coarse = 0.0, ll_fine = 0.0;
  const double coarse = (hi - lo) / (kCoarse - 1);
  const int i = best_of_grid(t, s, lo, hi, kCoarse, &ll_coarse);
  const double lo2 = lo + std::max(i - 1, 0) * coarse,
               hi2 = lo + std::min(i + 1, kCoarse - 1) * coarse;
  const double fine = (hi2 - lo2) / (kFine - 1);
  const int j = best_of_grid(t, s, lo2, hi2, kFine, &ll_fine);
  double a = lo2 + std::max(j - 1, 0) * fine, b = lo2 + std::min(j + 1, kFine - 1) * fine;
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = log_likelihood_at(t, c, s.slope, s.lapse),
         fd = log_likelihood_at(t, d, s.slope, s.lapse);
  while (b - a > 1e-5) {
    if (fc > fd) {
      b = d, d = c, fd = fc, c = b - r * (b - a), fc = log_likelihood_at(t, c, s.slope, s.lapse);
    } else {
      a = c, c = d, fc = fd, d = a + r * (b - a), fd = log_likelihood_at(t, d, s.slope, s.lapse);
    }
  }
  ThresholdFit fit;
  double log_fit = 0.5 * (a + b);
  fit.log_likelihood = log_likelihood_at(t, log_fit, s.slope, s.lapse);
  if (ll_fine > fit.log_likelihood) log_fit = lo2 + j * fine, fit.log_likelihood = ll_fine;
  // On a plateau that reaches an end of the range (every answer right, or wrong) the data do
  // not bound the threshold on that side: the fit is that end, flagged.
  for (const double end : {lo, hi}) {
    if (log_likelihood_at(t, end, s.slope, s.lapse) >= fit.log_likelihood - 1e-9) {
      log_fit = end, fit.at_bound = true;
    }
  }
  fit.threshold_px = std::exp(log_fit);
  return fit;
}

// The value at fraction `q` of sorted `v` (non-empty), interpolated between order statistics.
double percentile(const std::vector<double>& v, double q) {
  const double at = q * double(v.size() - 1);
  const size_t i = size_t(std::floor(at));
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (at - double(i)) * (v[i + 1] - v[i]);
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The standard normal quantile of p in (0, 1), by bisection on normal_cdf (to 1e-12).
double normal_quantile(double p) {
  double lo = -40.0, hi = 40.0;
  while (hi - lo > 1e-12) {
    const double mid = 0.5 * (lo + hi);
    (normal_cdf(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// BCa's bias correction z0: the normal quantile of the share of refits below the fit (ties
// counted half), kept within [1/2B, 1 - 1/2B].
double bias_correction(const std::vector<double>& sorted_refits, double fit) {
  const double n = double(sorted_refits.size());
  const double below = double(std::lower_bound(sorted_refits.begin(), sorted_refits.end(), fit) -
                              sorted_refits.begin());
  const double equal = double(std::upper_bound(sorted_refits.begin(), sorted_refits.end(), fit) -
                              sorted_refits.begin()) -
                       below;
  const double share = std::min(std::max((below + 0.5 * equal) / n, 0.5 / n), 1.0 - 0.5 / n);
  return normal_quantile(share);
}

// BCa's acceleration from the jackknife of the log threshold (each trial left out once):
// sum d^3 / (6 (sum d^2)^1.5) with d the mean less each leave-one-out fit; 0 when they agree.
double acceleration(const std::vector<TrialOutcome>& trials, const FitSettings& settings) {
  if (trials.size() < 3) return 0.0;
  std::vector<double> leave_one_out;
  for (size_t i = 0; i < trials.size(); ++i) {
    std::vector<TrialOutcome> rest = trials;
    rest.erase(rest.begin() + long(i));
    leave_one_out.push_back(std::log(fit_log_trials(log_trials(rest), settings).threshold_px));
  }
  double mean = 0.0;
  for (double v : leave_one_out) mean += v / double(leave_one_out.size());
  double square = 0.0, cube = 0.0;
  for (double v : leave_one_out) {
    const double d = mean - v;
    square += d * d, cube += d * d * d;
  }
  return square > 0.0 ? cube / (6.0 * std::pow(square, 1.5)) : 0.0;
}

}  // namespace

double PsychometricFunction::correct(double error_px) const {
  const double seen =
      error_px <= 0.0
          ? 0.0
          : 1.0 - std::exp(-weibull_k(lapse) * std::pow(error_px / threshold_px, slope));
  return kGuessRate + (1.0 - kGuessRate - lapse) * seen;
}

double log_likelihood(const std::vector<TrialOutcome>& trials, const PsychometricFunction& f) {
  double sum = 0.0;
  for (const TrialOutcome& trial : trials) {
    const double p = clamp_probability(f.correct(trial.error_px));
    sum += trial.correct ? std::log(p) : std::log(1.0 - p);
  }
  return sum;
}

ThresholdFit fit_threshold(const std::vector<TrialOutcome>& trials, const FitSettings& settings) {
  return fit_log_trials(log_trials(trials), settings);
}

ThresholdInterval bootstrap_interval(const std::vector<TrialOutcome>& trials, double fitted_px,
                                     const FitSettings& settings, int replicates, double level,
                                     StudyRandom& random) {
  const PsychometricFunction fitted{fitted_px, settings.slope, settings.lapse};
  LogTrials t = log_trials(trials);
  std::vector<double> p;
  for (const TrialOutcome& trial : trials) p.push_back(fitted.correct(trial.error_px));
  std::vector<double> refits;  // log thresholds
  for (int b = 0; b < replicates; ++b) {
    for (size_t i = 0; i < p.size(); ++i) t.correct[i] = random.chance(p[i]) ? 1 : 0;
    refits.push_back(std::log(fit_log_trials(t, settings).threshold_px));
  }
  std::sort(refits.begin(), refits.end());
  const double log_fit = std::log(fitted_px);
  const double z0 = bias_correction(refits, log_fit);
  const double a = acceleration(trials, settings);
  const auto adjusted = [&](double alpha) {
    const double z = normal_quantile(alpha);
    return normal_cdf(z0 + (z0 + z) / (1.0 - a * (z0 + z)));
  };
  return {std::exp(percentile(refits, adjusted((1.0 - level) / 2.0))),
          std::exp(percentile(refits, adjusted((1.0 + level) / 2.0)))};
}

double arcmin_of_pixels(double px, double pixels_per_inch, double distance_cm) {
  const double size_cm = px / pixels_per_inch * 2.54;
  return 2.0 * std::atan(size_cm / (2.0 * distance_cm)) * 180.0 / kPi * 60.0;
}

}  // namespace oflab
