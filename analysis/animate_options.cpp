// Option readers shared by the two forms of `oflab-cli animate`.
#include "analysis/animate_options.h"

#include <filesystem>

namespace oflab {

namespace fs = std::filesystem;

EngineSettings read_engine_settings(const CliArgs& a) {
  EngineSettings s;
  const std::string mode = a.text_or("--mode", "perspective");
  if (!parse_engine_mode(mode, &s.mode)) {
    throw UsageError("--mode: '" + mode + "' is not one of perspective, affine, rerender, exact");
  }
  if (a.has("--threshold") && a.has("--thresholds")) {
    throw UsageError("--thresholds: give either --threshold or --thresholds, not both");
  }
  if (a.has("--threshold")) s.thresholds.fill(a.number("--threshold"));
  if (a.has("--thresholds")) {
    const auto& v = a.values("--thresholds");
    for (int i = 0; i < kTermCount; ++i) {
      s.thresholds[i] = CliArgs({"--t", v[i]}, {{"--t", 1}}).number("--t");
    }
  }
  for (double t : s.thresholds) {
    if (!(t >= 0.0)) throw UsageError("--threshold: thresholds must be zero or positive pixels");
  }
  const std::string delta = a.text_or("--delta", "dissertation");
  if (!parse_delta_policy(delta, &s.delta)) {
    throw UsageError("--delta: '" + delta +
                     "' is not one of 1, det, sqrt, fourth-root, dissertation");
  }
  const std::string sampling = a.text_or("--sampling", "nearest");
  if (sampling == "nearest") {
    s.sampling = Sampling::kNearest;
  } else if (sampling == "bilinear") {
    s.sampling = Sampling::kBilinear;
  } else {
    throw UsageError("--sampling: '" + sampling + "' is not one of nearest, bilinear");
  }
  return s;
}

void prepare_out_dir(const std::string& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw UsageError("--out: '" + dir + "' is not a directory");
    if (!fs::is_empty(dir, ec) && !force) {
      throw UsageError("--out: '" + dir + "' is not empty (add --force to overwrite its files)");
    }
  } else if (!fs::create_directories(dir, ec)) {
    throw UsageError("--out: cannot create '" + dir + "': " + ec.message());
  }
}

}  // namespace oflab
