// The adaptive methods that choose each trial's error level (manual/study.md), a registry
// (adaptive_methods()) that the study files, `oflab-cli study` and the front-ends read:
//  - "staircase": 3-down-1-up on a log scale (Levitt 1971): three correct answers in a row
//    lower the error by one step, one wrong answer raises it (before the first reversal each
//    correct answer lowers it, to come down fast from the clearly visible first level, 0.8
//    log10 units below the range's top); steps of 0.1 log10 units until
//    the second reversal, 0.05 after (2 dB, then 1 dB of amplitude). It converges on 79.4 %
//    correct. Its own estimate is the geometric mean of the reversal levels after the first two.
//  - "quest+": QUEST+ (Watson 2017, Journal of Vision 17(3):10): a posterior over a grid of
//    threshold t (the 75 %-correct error, study/psychometric.h), slope and lapse rate; each
//    trial shows the error of the stimulus grid whose expected posterior entropy after the
//    answer is least; the answer multiplies the posterior by its likelihood at the error
//    actually shown. Its own estimate is the posterior mean of log t.
// Every method works in pixels of error: it requests a level, and is told the level that was
// shown (the engine's measured error, which can differ from the request) and the answer. A
// method is deterministic: it draws no random numbers. Plain C++.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace oflab {

// What a method knows before the first trial.
struct MethodSettings {
  double min_px = 0.1;  // the error range it may request, pixels (0 < min < max)
  double max_px = 10.0;
  // The staircase's first level (0: 0.8 log10 units below max_px).
  double start_px = 0.0;
};

class AdaptiveMethod {
 public:
  virtual ~AdaptiveMethod() = default;
  // The error to show next, pixels, within [min_px, max_px].
  virtual double next_error_px() const = 0;
  // The trial shown: the requested level, the error actually shown (pixels, > 0) and whether
  // the answer was correct.
  virtual void record(double requested_px, double shown_px, bool correct) = 0;
  // The method's own threshold estimate, pixels (see the file comment).
  virtual double estimate_px() const = 0;
};

struct AdaptiveMethodKind {
  const char* name;     // as written in study files and on the command line
  const char* summary;  // one line for help texts
  std::unique_ptr<AdaptiveMethod> (*make)(const MethodSettings& settings);
};

// Every method, in the order help texts list them.
const std::vector<AdaptiveMethodKind>& adaptive_methods();
// The method called `name`, or null.
const AdaptiveMethodKind* find_adaptive_method(const std::string& name);
// "staircase, quest+" for messages.
std::string adaptive_method_names();

// The 3-down-1-up staircase, public for its tests.
class Staircase : public AdaptiveMethod {
 public:
  explicit Staircase(const MethodSettings& settings);
  double next_error_px() const override;
  void record(double requested_px, double shown_px, bool correct) override;
  double estimate_px() const override;
  // The requested levels (pixels) at which the direction changed, in order.
  const std::vector<double>& reversals() const { return reversals_; }

 private:
  double log_min_, log_max_;
  double log_level_;   // log10 of the next level
  int run_ = 0;        // correct answers in a row since the last change
  int direction_ = 0;  // -1 last change down, +1 up, 0 none yet
  std::vector<double> reversals_;
};

// The QUEST+ grids: thresholds and stimuli log-spaced over [min_px, max_px], these slopes and
// lapse rates, a uniform prior.
struct QuestPlusGrid {
  int thresholds = 80;  // 6 % apart over the shipped studies' 0.1..10 px
  int stimuli = 80;
  std::vector<double> slopes{1.5, 2.5, 3.5, 5.0, 7.0, 10.0};
  std::vector<double> lapses{0.0, 0.02, 0.05};
};

class QuestPlus : public AdaptiveMethod {
 public:
  QuestPlus(const MethodSettings& settings, const QuestPlusGrid& grid = QuestPlusGrid());
  double next_error_px() const override;
  void record(double requested_px, double shown_px, bool correct) override;
  double estimate_px() const override;

  // The grid's parameters, index p = (threshold * slopes + slope) * lapses + lapse.
  struct Parameters {
    double threshold_px, slope, lapse;
  };
  // The grids and the likelihood tables, built once per range and grid and shared by every
  // QUEST+ of them (a study's conditions, a simulation's sessions).
  struct Tables {
    std::vector<Parameters> parameters;
    std::vector<double> stimuli;
    std::vector<double> correct;  // p(correct | stimulus s, parameters p) at s * P + p
    std::vector<double> log_correct, log_wrong;  // log p and log(1 - p) at s * P + p
  };
  const std::vector<Parameters>& parameters() const { return tables_->parameters; }
  // The posterior over parameters() (sums to 1).
  const std::vector<double>& posterior() const { return posterior_; }
  // The stimulus grid, pixels.
  const std::vector<double>& stimuli() const { return tables_->stimuli; }
  // The expected entropy (nats) of the posterior after a trial at stimulus `s` of stimuli().
  double expected_entropy(int s) const;
  // The posterior standard deviation of log10 t.
  double log10_threshold_sd() const;

 private:
  std::shared_ptr<const Tables> tables_;
  std::vector<double> posterior_, log_posterior_;
  int next_ = 0;  // the stimulus of least expected entropy
  void choose_next();
};

}  // namespace oflab
