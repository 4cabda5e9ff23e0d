// `oflab-cli experiments`: the deterministic parts of the experiments (level counts, pixel
// counters) against properties of the published results, the report's rendering, and a
// --quick run that writes a report a browser can open. Timings are reported by the
// experiments, never asserted here. Needs an X display for the charts (ctest runs under
// xvfb-run -a).
#include "experiments/experiments.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "cli/animate_options.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli_capture.h"
#include "experiments/experiments_delta.h"
#include "experiments/experiments_policies.h"
#include "experiments/experiments_reprojection.h"
#include "experiments/experiments_runs.h"
#include "experiments/experiments_scenes.h"
#include "experiments/experiments_single_plane.h"
#include "experiments/experiments_warp.h"
#include "experiments/published_results.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "report/charts.h"
#include "report/report.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

const Layer& butterfly() {
  static const Layer texture = make_layer(read_image(default_texture_path()));
  return texture;
}

// Whole scripts, one repetition, no PSNR: only the deterministic parts are used.
const Experiment1Result& experiment1() {
  static const Experiment1Result result = [] {
    RunSpec spec;
    spec.repetitions = 1;
    spec.measure_psnr = false;
    return run_experiment1(butterfly(), spec, {});
  }();
  return result;
}

const Experiment1Script& script(const std::string& name) {
  for (const Experiment1Script& s : experiment1().scripts) {
    if (s.script == name) return s;
  }
  throw std::logic_error("no script " + name);
}

int count_after_first(const MeasuredRun& run, Level level) {
  int n = 0;
  for (size_t i = 1; i < run.reports.size(); ++i) n += run.reports[i].level == level;
  return n;
}

// The attribution of the policies section: distances written out level by level.
TEST(PoliciesExperiment, GapAttributionIsTheShareOfTheDistanceThePrintedRuleRemoves) {
  const std::array<double, kLevelCount> published{10, 20, 30, 40, 0};
  const std::array<double, kLevelCount> corrected{30, 20, 30, 20, 0};  // 20 points away
  const std::array<double, kLevelCount> printed{15, 20, 30, 35, 0};    // 5 points away
  GapAttribution g = attribute_gap(published, corrected, printed);
  EXPECT_DOUBLE_EQ(g.corrected_points, 20.0);
  EXPECT_DOUBLE_EQ(g.printed_points, 5.0);
  EXPECT_DOUBLE_EQ(g.explained, 0.75);
  g = attribute_gap(published, printed, corrected);  // the printed rule further away
  EXPECT_DOUBLE_EQ(g.explained, -3.0);
  EXPECT_TRUE(std::isnan(attribute_gap(published, published, corrected).explained));
}

TEST(Experiment1Published, EveryShippedExperimentScriptHasAPublishedRow) {
  for (const std::string& name : experiment1_scripts()) {
    EXPECT_NE(published_experiment1_row(name), nullptr) << name;
  }
  EXPECT_EQ(experiment1().scripts.size(), published_experiment1().size());
}

TEST(Experiment1Published, OnlyScriptsPublishedWithPerspectiveWarpsUseThem) {
  for (const Experiment1Script& s : experiment1().scripts) {
    const PublishedScriptResult* pub = published_experiment1_row(s.script);
    const int perspective = count_after_first(s.mode("perspective"), Level::kPerspective);
    if (pub->level_percent[static_cast<int>(Level::kPerspective)] > 0) {
      EXPECT_GT(perspective, 0) << s.script;
    } else {
      EXPECT_EQ(perspective, 0) << s.script;
    }
  }
}

TEST(Experiment1Published, ScriptsPublishedWithOnlyNoUpdateOrTranslationNeverRerender) {
  for (const char* name : {"stationary", "translation-1"}) {
    for (const MeasuredRun& run : script(name).modes) {
      EXPECT_EQ(count_after_first(run, Level::kRerender), 0)
          << name << " " << run.settings.policy->name;
      EXPECT_EQ(count_after_first(run, Level::kAffine), 0) << name;
    }
  }
}

TEST(Experiment1Published, StationaryNeedsNoUpdateAndTranslationOneTranslatesEverySecondFrame) {
  const MeasuredRun& still = script("stationary").mode("perspective");
  EXPECT_EQ(level_percent_after_first(still)[static_cast<int>(Level::kNone)], 100.0);
  const auto moving = level_percent_after_first(script("translation-1").mode("perspective"));
  // Within the report's "level mix within 5 points": whole-pixel translations leave a
  // sub-pixel rest, which now and then calls for a second translation in a row.
  EXPECT_NEAR(moving[static_cast<int>(Level::kNone)], 50.0, 5.0);
  EXPECT_NEAR(moving[static_cast<int>(Level::kTranslate)], 50.0, 5.0);
}

TEST(Experiment1Published, ScriptsPublishedWithRerendersWarpAffinelyAndRotationRerendersMost) {
  // Published: re-renders in translation-2, zoom, zoom-rotation and rotation, most of all
  // in rotation; the affine warp is their commonest update.
  for (const char* name : {"translation-2", "zoom", "zoom-rotation", "rotation"}) {
    const MeasuredRun& run = script(name).mode("perspective");
    EXPECT_GT(count_after_first(run, Level::kAffine), 0) << name;
  }
  const auto rerender_share = [](const char* name) {
    return level_percent_after_first(
        script(name).mode("perspective"))[static_cast<int>(Level::kRerender)];
  };
  for (const char* name : {"translation-2", "zoom", "zoom-rotation"}) {
    EXPECT_GT(rerender_share("rotation"), rerender_share(name)) << name;
  }
}

TEST(Experiment1Published, WorkSavingsOrderTheScriptsAsThePublishedTimeSavings) {
  // Published time saved: stationary 100, translation-1 98.5 > translation-2 76.1,
  // zoom 84.0, zoom-rotation 76.3 > rotation 42.7, loop 33.0. Compared here by pixels
  // written (deterministic), group against group.
  const auto work = [](const std::string& name) {
    const Experiment1Script& s = script(name);
    return work_saved(s.mode("perspective"), s.baseline);
  };
  const std::vector<std::vector<std::string>> groups = {{"stationary", "translation-1"},
                                                        {"translation-2", "zoom", "zoom-rotation"},
                                                        {"rotation", "loop"}};
  for (size_t g = 0; g + 1 < groups.size(); ++g) {
    for (const std::string& higher : groups[g]) {
      for (const std::string& lower : groups[g + 1]) {
        EXPECT_GT(work(higher), work(lower)) << higher << " vs " << lower;
      }
    }
  }
  for (const std::string& name : experiment1_scripts()) {
    if (name == "loop") continue;
    EXPECT_GT(work(name), work("loop")) << "the loop saves least: " << name;
  }
}

TEST(Experiment1Published, AffineOnlyLoopDoesLessWorkThanThePerspectiveLoop) {
  // Section 6.5.1: the affine-only loop took about a third of the full algorithm's time.
  const Experiment1Script& loop = script("loop");
  const MeasuredRun& affine = loop.mode("affine");
  EXPECT_EQ(count_after_first(affine, Level::kPerspective), 0);
  EXPECT_LT(affine.summary.pixels, loop.mode("perspective").summary.pixels);
}

TEST(Experiment1Published, RunsWithTheCliDefaultsSoAnAnimateCommandReproducesARow) {
  // The report's paragraph promises that `oflab-cli animate --script S --mode M` reproduces
  // a row: the same engine settings (beyond the policy) and the same number of timed passes.
  const CliArgs none({}, {});
  const EngineSettings cli = read_engine_settings(none);
  const EngineSettings report;  // what run_experiment1 gives each mode
  EXPECT_EQ(cli.thresholds, report.thresholds);
  EXPECT_EQ(cli.delta, report.delta);
  EXPECT_EQ(cli.sampling, report.sampling);
  EXPECT_EQ(cli.max_magnification, report.max_magnification);
  EXPECT_EQ(cli.near, report.near);
  EXPECT_EQ(cli.policy, &default_reuse_policy());
  std::ostringstream err;
  EXPECT_EQ(read_run_output(none, err).timing_repetitions, experiment1_spec(false).repetitions);
}

TEST(Experiment1Published, LevelPercentagesCoverEveryFrameAfterTheFirst) {
  for (const Experiment1Script& s : experiment1().scripts) {
    for (const MeasuredRun& run : s.modes) {
      const auto p = level_percent_after_first(run);
      double sum = 0.0;
      for (double v : p) sum += v;
      EXPECT_NEAR(sum, 100.0, 1e-9) << s.script;
      EXPECT_EQ(run.frame_ms.size(), run.reports.size());
    }
  }
}

TEST(DeltaComparison, CachePixelsOrderThePoliciesAsThePublishedFrameTimes) {
  // Published: Delta = 1 slowest (cache at texture size), det fastest, sqrt in between.
  RunSpec spec = delta_spec(true);
  spec.measure_psnr = false;
  const DeltaResult r = run_delta_comparison(butterfly(), spec, {});
  std::map<DeltaPolicy, std::int64_t> pixels;
  for (const MeasuredRun& run : r.runs) pixels[run.settings.delta] = run.summary.pixels;
  EXPECT_GT(pixels[DeltaPolicy::kOne], pixels[DeltaPolicy::kSqrtAbsDet]);
  EXPECT_GT(pixels[DeltaPolicy::kSqrtAbsDet], pixels[DeltaPolicy::kAbsDet]);
  EXPECT_EQ(r.runs.size(), delta_policies().size());
}

// The whole compound script on four cubes (as section 6.7.3), deterministic parts only: one
// repetition, no VTK renderer.
const Experiment2Result& experiment2() {
  static const Experiment2Result result = [] {
    Experiment2Spec spec;
    spec.repetitions = 1;
    spec.conventional_repetitions = 0;
    spec.grid_conventional_repetitions = 0;
    spec.grid_cubes = {1, 4};
    spec.grid_max_frames = 40;
    spec.grid_repetitions = 1;
    return run_experiment2(spec, {});
  }();
  return result;
}

TEST(Experiment2Published, FourCubesUseEveryUpdateLevel) {
  const auto& levels = experiment2().four_cubes.run.summary.levels;
  for (int l = 0; l < kLevelCount; ++l) {
    EXPECT_GT(levels[l], 0) << level_name(static_cast<Level>(l));
  }
}

TEST(Experiment2Published, MostFourCubesPolygonsNeedLessThanAPerspectiveWarp) {
  // Published: 62.2% of the polygons needed at most an affine warp.
  const auto& levels = experiment2().four_cubes.run.summary.levels;
  long total = 0;
  for (long c : levels) total += c;
  ASSERT_GT(total, 0);
  EXPECT_GT(2 * (levels[0] + levels[1] + levels[2]), total);
  EXPECT_EQ(experiment2().four_cubes.run.frames.size(), 401u) << "the whole compound script";
}

TEST(Experiment2Published, DrawnPolygonsGrowWithThePolygonCount) {
  // Published: frame time grew in proportion to the polygons (sections 6.7.1, 6.7.3);
  // the work behind it, polygons drawn per run, is compared here.
  const auto& small = experiment2().small;
  ASSERT_EQ(small.size(), 3u);
  EXPECT_EQ(small[0].polygons, 1);
  EXPECT_EQ(small[1].polygons, 2);
  EXPECT_EQ(small[2].polygons, 5);
  for (size_t i = 1; i < small.size(); ++i) {
    EXPECT_GT(small[i].run.summary.drawn(), small[i - 1].run.summary.drawn()) << small[i].scene;
  }
  EXPECT_GT(experiment2().grid[1].run.summary.drawn(), experiment2().grid[0].run.summary.drawn());
}

TEST(Experiment2Published, SkippingHiddenPolygonsNeverDrawsMore) {
  EXPECT_LE(experiment2().four_cubes_skipping.run.summary.drawn(),
            experiment2().four_cubes.run.summary.drawn());
}

TEST(WarpTiming, BothKernelsWriteTheSamePixelsForAffineMatrices) {
  const WarpTimingResult r = run_warp_timing(WarpTimingSpec{3}, {});
  EXPECT_EQ(r.timings.size(), 12u);
  for (const std::string size : {"243x198", "121x99"}) {
    for (const std::string matrix : {"identity", "rot45"}) {
      const WarpTiming* a = r.find(size, matrix, "affine");
      const WarpTiming* p = r.find(size, matrix, "perspective");
      ASSERT_TRUE(a && p) << size << " " << matrix;
      EXPECT_EQ(a->pixels_written, p->pixels_written) << size << " " << matrix;
      EXPECT_GT(a->pixels_written, 0);
    }
    EXPECT_EQ(r.find(size, "identity", "affine")->pixels_written,
              size == "243x198" ? 243 * 198 : 121 * 99);
  }
}

TEST(ExperimentReadings, LevelMixNamesTheLargestDifferences) {
  EXPECT_EQ(level_mix_reading({50, 50, 0, 0, 0}, {52, 48, 0, 0, 0}), "level mix within 5 points");
  EXPECT_EQ(level_mix_reading({26, 17, 7, 50, 0}, {0, 24, 44, 30, 2}),
            "more affine (+37), fewer none (-26)");
  EXPECT_EQ(percent(0.1234), "12.3%");
  EXPECT_EQ(fixed(NAN, 2), "n/a");
}

// The reprojection chapter's one-motion table from real runs (four cubes under translate, 5
// frames) and timings at a small size: a row per method in order, each as long as the header,
// the hole share recomputed from the run's own total, latency from the policy, a time for
// every method. The times themselves are reported, never asserted.
TEST(ReprojectionReport, OneMotionTableHasEveryMethodWithItsHolesTimeAndLatency) {
  ReprojectionResult result;
  result.spec = reprojection_spec(true);
  result.spec.max_frames = 5;
  result.spec.timing_width = 96;
  result.spec.timing_height = 54;
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("four-cubes")));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("translate"));
  PlayOptions options;
  options.max_frames = 5;
  options.warm_up = false;
  options.timing_repetitions = 1;
  ReprojectionSource s{"four-cubes", "translate", 640 * 480, {}};
  s.runs = run_policies(source_kind("scene"), source, one_motion_policies(), options);
  EXPECT_THROW(one_motion_table(result), std::invalid_argument);  // no four cubes yet
  result.sources.push_back(std::move(s));
  EXPECT_THROW(one_motion_table(result), std::invalid_argument);  // no timings yet
  result.timings =
      time_one_motion(result.spec.timing_width, result.spec.timing_height, result.spec.cadence);
  const ReportTable t = one_motion_table(result);
  const std::vector<const ReusePolicy*> methods = one_motion_policies();
  ASSERT_EQ(t.rows.size(), methods.size());
  ASSERT_EQ(t.header.size(), 8u);
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::vector<std::string>& row = t.rows[i];
    ASSERT_EQ(row.size(), t.header.size()) << methods[i]->name;
    EXPECT_EQ(row[0], methods[i]->name);
    const RunSummary& summary = result.sources[0].runs[i].run.summary;
    EXPECT_NEAR(std::stod(row[2]), 100.0 * summary.hole_pixels / (5.0 * 640 * 480), 5e-4) << row[0];
    EXPECT_GT(std::stod(row[6]), 0.0) << row[0];
    EXPECT_EQ(row[7], methods[i]->pixel_motion == PixelMotion::kBetweenRenders ? "1" : "0");
    const MethodTiming& timing = result.timings[i];
    EXPECT_EQ(timing.policy, methods[i]);
    // Frames made without rendering among frames 1..8: four on the cadence, eight otherwise.
    EXPECT_EQ(timing.frames, methods[i]->schedule == Schedule::kCadence ? 4 : 8) << row[0];
    EXPECT_NEAR(timing.ms_1080p, timing.ms * 400.0, 1e-9 * timing.ms_1080p);  // (1920/96)^2
  }
  EXPECT_NE(t.caption.find("measured at 96 x 54 and scaled by the pixel count"), std::string::npos)
      << t.caption;
}

TEST(Report, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(base64_encode(""), "");
  EXPECT_EQ(base64_encode("f"), "Zg==");
  EXPECT_EQ(base64_encode("fo"), "Zm8=");
  EXPECT_EQ(base64_encode("foo"), "Zm9v");
  EXPECT_EQ(base64_encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64_encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
}

TEST(Report, MarkdownAndHtmlEscapeTheirSpecialCharacters) {
  Report report;
  report.title = "a <b> & c";
  ReportSection s;
  s.id = "one";
  s.title = "One";
  s.paragraph("x < y");
  s.table({"caption", {"h|1", "h2"}, {{"a|b", "<td>"}}});
  report.sections.push_back(s);
  const std::string md = render_markdown(report);
  EXPECT_NE(md.find("| h\\|1 | h2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| a\\|b | <td> |"), std::string::npos) << md;
  const std::string html = render_html(report, ".");
  EXPECT_NE(html.find("<title>a &lt;b&gt; &amp; c</title>"), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;td&gt;</td>"), std::string::npos);
  EXPECT_NE(html.find("<p>x &lt; y</p>"), std::string::npos);
}

ChartSeries series(const std::string& name, std::vector<double> x, std::vector<double> y,
                   SeriesStyle style = SeriesStyle::kLine) {
  ChartSeries s;
  s.name = name;
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  return s;
}

ChartPanel panel(const std::string& title, const std::string& x_label, std::vector<ChartSeries> s) {
  ChartPanel p;
  p.title = title;
  p.x_label = x_label;
  p.series = std::move(s);
  return p;
}

TEST(Charts, CsvIsWideWhenSeriesShareXAndLongOtherwise) {
  Chart shared;
  shared.panels = {
      panel("p", "frame", {series("a", {0, 1}, {1, 2}), series("b", {0, 1}, {3, NAN})})};
  std::ostringstream wide;
  write_chart_csv(shared, wide);
  EXPECT_EQ(wide.str(), "frame,a,b\n0,1,3\n1,2,\n");
  Chart apart;
  apart.panels = {panel("p", "x", {series("a", {0}, {1}), series("b", {5}, {6})})};
  std::ostringstream long_form;
  write_chart_csv(apart, long_form);
  EXPECT_EQ(long_form.str(), "panel,series,x,y\np,a,0,1\np,b,5,6\n");
}

TEST(Charts, WritesAPngOrSaysWhyNot) {
  const fs::path path = testing::fresh_test_dir("oflab-chart") / "chart.png";
  Chart chart;
  chart.panels = {
      panel("levels", "frame", {series("l", {0, 1, 2}, {4, 0, 2}, SeriesStyle::kPoints)})};
  chart.panels[0].y_range = std::make_pair(-0.5, 4.5);
  chart.panels[0].y_ticks = level_ticks();
  ASSERT_EQ(chart_display_problem(), "") << "run the analysis tests under xvfb-run -a";
  write_chart_png(chart, path.string());
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_GT(fs::file_size(path), 1000u);
  Chart empty;
  EXPECT_THROW(write_chart_png(empty, path.string()), ChartError);
}

using testing::CliResult;

CliResult cli(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t occurrences(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(ExperimentsCommand, QuickRunWritesAReportThatParsesWithEveryChart) {
  const fs::path dir = testing::fresh_test_dir("oflab-experiments-quick") / "report";
  const CliResult c = cli({"experiments", "--quick", "--out", dir.string()});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.err.find("exp1"), std::string::npos) << "progress goes to stderr";
  const std::string md = read_text(dir / "report.md");
  const std::string html = read_text(dir / "report.html");
  ASSERT_FALSE(md.empty());
  ASSERT_FALSE(html.empty());
  for (const char* tag : {"<!DOCTYPE html>", "<html", "<head>", "<body>", "</body>", "</html>"}) {
    EXPECT_EQ(occurrences(html, tag), 1u) << tag;
  }
  EXPECT_EQ(occurrences(html, "<table>"), occurrences(html, "</table>"));
  EXPECT_EQ(occurrences(html, "<tr>"), occurrences(html, "</tr>"));
  EXPECT_EQ(occurrences(html, "<section"), occurrences(html, "</section>"));
  // One HTML table per Markdown table (a Markdown table has one "|---|" separator row).
  EXPECT_EQ(occurrences(html, "<table>"), occurrences(md, "\n|---|"));
  for (const char* id : {"about", "experiment-1", "delta", "warp-timing", "experiment-2",
                         "threshold-sweep", "costs", "policies", "visible-warp"}) {
    EXPECT_NE(html.find(std::string("<section id=\"") + id + "\">"), std::string::npos) << id;
  }
  // Every Markdown image is a chart file next to the report with its CSV, and every one
  // is embedded in the HTML as a PNG data URI.
  const std::regex image(R"(!\[[^\]]*\]\((charts/[^)]+\.png)\))");
  size_t images = 0;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), image); it != std::sregex_iterator();
       ++it) {
    const fs::path png = dir / (*it)[1].str();
    EXPECT_TRUE(fs::is_regular_file(png)) << png;
    EXPECT_GT(fs::file_size(png), 1000u) << png;
    fs::path csv = dir / "data" / png.filename();
    csv.replace_extension(".csv");
    EXPECT_TRUE(fs::is_regular_file(csv)) << csv;
    EXPECT_GT(fs::file_size(csv), 10u) << csv;
    ++images;
  }
  EXPECT_GE(images, 21u + 2u + 1u + 2u + 1u);  // exp1 per script and mode, delta, warp,
                                               // sweep, policies
  EXPECT_EQ(occurrences(html, "<img "), images);
  EXPECT_EQ(occurrences(html, "src=\"data:image/png;base64,iVBORw0KGgo"), images);
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "charts")) {
    EXPECT_GT(e.file_size(), 0u) << e.path();
  }
  if (!::testing::Test::HasFailure()) fs::remove_all(dir.parent_path());  // kept when it fails
}

TEST(ExperimentsCommand, RefusesANonEmptyDirectoryWithoutForce) {
  const fs::path dir = testing::fresh_test_dir("oflab-experiments-nonempty");
  std::ofstream(dir / "keep.txt") << "x";
  CliResult c = cli({"experiments", "--quick", "--only", "warp", "--out", dir.string()});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("--force"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(dir / "report.md"));
  c = cli({"experiments", "--quick", "--only", "warp", "--out", dir.string(), "--force"});
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_TRUE(fs::exists(dir / "report.md"));
  EXPECT_FALSE(fs::exists(dir / "keep.txt"));  // --force replaces DIR whole: no stale file
  const std::string md = read_text(dir / "report.md");
  EXPECT_EQ(md.find("Experiment 1"), std::string::npos) << "--only runs only what it names";
}

TEST(ExperimentsCommand, RejectsUnknownExperimentsAndOptionsNamingThem) {
  CliResult c = cli({"experiments", "--only", "exp3"});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("'exp3'"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("exp1, delta, warp, exp2, sweep"), std::string::npos) << c.err;
  c = cli({"experiments", "--only"});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("--only"), std::string::npos) << c.err;
  c = cli({"experiments", "--fast"});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("--fast"), std::string::npos) << c.err;
}

TEST(ExperimentsCommand, WithoutADisplayFailsBeforeCreatingTheDirectory) {
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  const fs::path dir = testing::fresh_test_dir("oflab-experiments-nodisplay") / "out";
  const CliResult c = cli({"experiments", "--quick", "--only", "warp", "--out", dir.string()});
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(c.code, 1);
  EXPECT_NE(c.err.find("xvfb-run"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace oflab
