#include "study/adaptive_methods.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "study/psychometric.h"

namespace oflab {
namespace {

constexpr double kLargeStep = 0.1;  // log10 units, until the second reversal
constexpr double kSmallStep = 0.05;
constexpr int kDown = 3;                // correct answers in a row that lower the level
constexpr double kStartBelowMax = 0.8;  // log10 units: the first level, clearly visible

std::vector<double> log_spaced(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(lo * std::pow(hi / lo, double(i) / double(n - 1)));
  return v;
}

double probability_within(double p) { return std::min(std::max(p, 1e-9), 1.0 - 1e-9); }

}  // namespace

// --- Staircase -----------------------------------------------------------------------------

Staircase::Staircase(const MethodSettings& s)
    : log_min_(std::log10(s.min_px)), log_max_(std::log10(s.max_px)) {
  log_level_ = s.start_px > 0.0 ? std::log10(s.start_px) : log_max_ - kStartBelowMax;
  log_level_ = std::min(std::max(log_level_, log_min_), log_max_);
}

double Staircase::next_error_px() const { return std::pow(10.0, log_level_); }

void Staircase::record(double requested_px, double /*shown_px*/, bool correct) {
  int change = 0;
  if (!correct) {
    change = +1;
  } else if (++run_ == (reversals_.empty() ? 1 : kDown)) {
    change = -1;
  }
  if (change == 0) return;
  run_ = 0;
  if (direction_ != 0 && change != direction_) reversals_.push_back(requested_px);
  direction_ = change;
  const double step = reversals_.size() < 2 ? kLargeStep : kSmallStep;
  log_level_ = std::min(std::max(log_level_ + change * step, log_min_), log_max_);
}

double Staircase::estimate_px() const {
  if (reversals_.empty()) return next_error_px();
  const size_t first = reversals_.size() > 2 ? 2 : 0;
  double sum = 0.0;
  for (size_t i = first; i < reversals_.size(); ++i) sum += std::log10(reversals_[i]);
  return std::pow(10.0, sum / double(reversals_.size() - first));
}

// --- QUEST+ --------------------------------------------------------------------------------

static std::shared_ptr<const QuestPlus::Tables> make_tables(const MethodSettings& s,
                                                            const QuestPlusGrid& grid) {
  auto t = std::make_shared<QuestPlus::Tables>();
  for (double threshold : log_spaced(s.min_px, s.max_px, grid.thresholds)) {
    for (double slope : grid.slopes) {
      for (double lapse : grid.lapses) t->parameters.push_back({threshold, slope, lapse});
    }
  }
  t->stimuli = log_spaced(s.min_px, s.max_px, grid.stimuli);
  for (double x : t->stimuli) {
    for (const QuestPlus::Parameters& p : t->parameters) {
      const double pc =
          probability_within(PsychometricFunction{p.threshold_px, p.slope, p.lapse}.correct(x));
      t->correct.push_back(pc);
      t->log_correct.push_back(std::log(pc));
      t->log_wrong.push_back(std::log(1.0 - pc));
    }
  }
  return t;
}

// The tables of one range and grid, built on first use (under a lock: a window may run
// studies on more than one thread).
static std::shared_ptr<const QuestPlus::Tables> shared_tables(const MethodSettings& s,
                                                              const QuestPlusGrid& grid) {
  using Key = std::tuple<double, double, int, int, std::vector<double>, std::vector<double>>;
  static std::mutex lock;
  static std::map<Key, std::shared_ptr<const QuestPlus::Tables>> built;
  const std::lock_guard<std::mutex> hold(lock);
  auto& tables =
      built[Key{s.min_px, s.max_px, grid.thresholds, grid.stimuli, grid.slopes, grid.lapses}];
  if (!tables) tables = make_tables(s, grid);
  return tables;
}

QuestPlus::QuestPlus(const MethodSettings& s, const QuestPlusGrid& grid)
    : tables_(shared_tables(s, grid)) {
  const size_t n = tables_->parameters.size();
  posterior_.assign(n, 1.0 / double(n));
  log_posterior_.assign(n, std::log(posterior_[0]));
  choose_next();
}

double QuestPlus::expected_entropy(int s) const {
  // For outcome r with likelihoods L_p: Z_r = sum q_p L_p, the new posterior q_p L_p / Z_r,
  // whose entropy is log Z_r - sum q_p L_p log(q_p L_p) / Z_r; weighted by Z_r and summed.
  const size_t n = tables_->parameters.size();
  // log(q_p L_p) = log q_p + log L_p from the tables: no logarithm in the loop.
  const size_t at = size_t(s) * n;
  const double* pc = &tables_->correct[at];
  const double* log_pc = &tables_->log_correct[at];
  const double* log_pw = &tables_->log_wrong[at];
  double z[2] = {0.0, 0.0}, m[2] = {0.0, 0.0};
  for (size_t p = 0; p < n; ++p) {
    const double q = posterior_[p], lq = log_posterior_[p];
    const double a = q * pc[p], b = q - a;
    z[0] += a, m[0] += a * (lq + log_pc[p]);
    z[1] += b, m[1] += b * (lq + log_pw[p]);
  }
  double h = 0.0;
  for (int r = 0; r < 2; ++r) {
    if (z[r] > 0.0) h += z[r] * std::log(z[r]) - m[r];
  }
  return h;
}

void QuestPlus::choose_next() {
  double best = 1e300;
  for (int s = 0; s < int(tables_->stimuli.size()); ++s) {
    const double h = expected_entropy(s);
    if (h < best - 1e-12) best = h, next_ = s;
  }
}

double QuestPlus::next_error_px() const { return tables_->stimuli[size_t(next_)]; }

void QuestPlus::record(double /*requested_px*/, double shown_px, bool correct) {
  double sum = 0.0;
  for (size_t p = 0; p < parameters().size(); ++p) {
    const Parameters& k = parameters()[p];
    const double pc = probability_within(
        PsychometricFunction{k.threshold_px, k.slope, k.lapse}.correct(shown_px));
    posterior_[p] *= correct ? pc : 1.0 - pc;
    sum += posterior_[p];
  }
  for (size_t p = 0; p < parameters().size(); ++p) {
    posterior_[p] /= sum;
    // A posterior that underflowed to 0 contributes nothing; its log is kept finite.
    log_posterior_[p] = std::log(std::max(posterior_[p], 1e-300));
  }
  choose_next();
}

double QuestPlus::estimate_px() const {
  double mean = 0.0;
  for (size_t p = 0; p < parameters().size(); ++p)
    mean += posterior_[p] * std::log(parameters()[p].threshold_px);
  return std::exp(mean);
}

double QuestPlus::log10_threshold_sd() const {
  double mean = 0.0, square = 0.0;
  for (size_t p = 0; p < parameters().size(); ++p) {
    const double l = std::log10(parameters()[p].threshold_px);
    mean += posterior_[p] * l, square += posterior_[p] * l * l;
  }
  return std::sqrt(std::max(square - mean * mean, 0.0));
}

// --- The registry --------------------------------------------------------------------------

const std::vector<AdaptiveMethodKind>& adaptive_methods() {
  static const std::vector<AdaptiveMethodKind> all = {
      {"staircase", "3-down-1-up staircase on a log scale (79.4 % correct)",
       [](const MethodSettings& s) -> std::unique_ptr<AdaptiveMethod> {
         return std::make_unique<Staircase>(s);
       }},
      {"quest+", "QUEST+: grid posterior over threshold, slope and lapse; least expected entropy",
       [](const MethodSettings& s) -> std::unique_ptr<AdaptiveMethod> {
         return std::make_unique<QuestPlus>(s);
       }},
  };
  return all;
}

const AdaptiveMethodKind* find_adaptive_method(const std::string& name) {
  for (const AdaptiveMethodKind& kind : adaptive_methods()) {
    if (name == kind.name) return &kind;
  }
  return nullptr;
}

std::string adaptive_method_names() {
  std::string names;
  for (const AdaptiveMethodKind& kind : adaptive_methods())
    names += (names.empty() ? "" : ", ") + std::string(kind.name);
  return names;
}

}  // namespace oflab
