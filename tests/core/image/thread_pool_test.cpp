// The worker threads of the pixel loops (core/image/thread_pool.h): the bands of a loop, that
// they really run on two threads, and that a scene's frames and reports are the same bytes
// with 1 thread and with 2.
#include "image/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

// Sets the pool's threads for one test and restores 1 after it.
class ThreadsFor {
 public:
  explicit ThreadsFor(int count) { set_worker_threads(count); }
  ~ThreadsFor() { set_worker_threads(1); }
  ThreadsFor(const ThreadsFor&) = delete;
  ThreadsFor& operator=(const ThreadsFor&) = delete;
};

TEST(ThreadPool, BandsDependOnTheRowsAlone) {
  EXPECT_EQ(band_count(0, 8), 1);
  EXPECT_EQ(band_count(7, 8), 1);
  EXPECT_EQ(band_count(16, 8), 2);
  EXPECT_EQ(band_count(17, 8), 2);
  EXPECT_EQ(band_count(100000, 8), kMaxBands);
  EXPECT_EQ(band_count(100, 0), 1);
}

TEST(ThreadPool, EveryRowIsVisitedOnceInConsecutiveBands) {
  for (const int threads : {1, 2, 3}) {
    const ThreadsFor pool(threads);
    for (const int rows : {0, 1, 9, 100, 1081}) {
      std::vector<int> visits(static_cast<std::size_t>(rows), 0);
      std::vector<std::pair<int, int>> bands(static_cast<std::size_t>(band_count(rows, 7)));
      for_each_band(rows, 7, [&](int band, int begin, int end) {
        bands[static_cast<std::size_t>(band)] = {begin, end};
        for (int r = begin; r < end; ++r) ++visits[static_cast<std::size_t>(r)];
      });
      for (int v : visits) EXPECT_EQ(v, 1) << rows << " rows, " << threads << " threads";
      int next = 0;
      for (const auto& [begin, end] : bands) {
        EXPECT_EQ(begin, next);
        EXPECT_LE(begin, end);
        next = end;
      }
      EXPECT_EQ(next, rows);
    }
  }
}

TEST(ThreadPool, TwoThreadsRunTwoBandsAtOnce) {
  // The first band waits until another band runs on another thread: with one thread it
  // would wait for ever (the bands run in order), so this passes only on two threads.
  const ThreadsFor pool(2);
  std::mutex m;
  std::condition_variable cv;
  bool other_started = false;
  const std::thread::id caller = std::this_thread::get_id();
  bool met = false;
  for_each_band(64, 8, [&](int band, int, int) {
    std::unique_lock<std::mutex> lock(m);
    if (band == 0) {
      met = cv.wait_for(lock, std::chrono::seconds(20), [&] { return other_started; });
    } else if (std::this_thread::get_id() != caller) {
      other_started = true;
      cv.notify_all();
    }
  });
  EXPECT_TRUE(met);
  // Negative control: with one thread every band runs on the caller.
  set_worker_threads(1);
  bool elsewhere = false;
  for_each_band(
      64, 8, [&](int, int, int) { elsewhere = elsewhere || std::this_thread::get_id() != caller; });
  EXPECT_FALSE(elsewhere);
}

TEST(ThreadPool, ABandsExceptionReachesTheCallerAfterEveryBand) {
  const ThreadsFor pool(2);
  std::atomic<int> done{0};
  EXPECT_THROW(for_each_band(64, 8,
                             [&](int band, int, int) {
                               ++done;
                               if (band == 3) throw std::runtime_error("band 3");
                             }),
               std::runtime_error);
  EXPECT_EQ(done.load(), band_count(64, 8));
}

TEST(ThreadPool, ALoopInsideABandRunsItsOwnBands) {
  const ThreadsFor pool(2);
  std::vector<std::atomic<int>> visits(64 * 64);
  for_each_band(64, 8, [&](int, int begin, int end) {
    for (int r = begin; r < end; ++r) {
      for_each_band(64, 8, [&](int, int b, int e) {
        for (int c = b; c < e; ++c) ++visits[static_cast<std::size_t>(r * 64 + c)];
      });
    }
  });
  for (const auto& v : visits) EXPECT_EQ(v.load(), 1);
}

TEST(ThreadPool, ThreadCountsOutsideTheLimitAreRefused) {
  EXPECT_THROW(set_worker_threads(0), std::invalid_argument);
  EXPECT_THROW(set_worker_threads(kMaxWorkerThreads + 1), std::invalid_argument);
  EXPECT_EQ(worker_threads(), 1);
  EXPECT_GE(machine_cores(), 1);
}

// One run of two open cubes, every face a different content, under `mode` (rendering every
// `cadence`-th frame where the policy has a cadence): each frame's pixels and the report's
// deterministic figures.
struct Played {
  std::vector<std::vector<Pixel>> frames;
  std::vector<std::vector<double>> figures;
};

Played play_cubes(const std::string& mode, int threads, int cadence = 1) {
  const ThreadsFor pool(threads);
  std::vector<ScenePolygon> polygons = testing::open_cube("a", Vec3(-1, 0, 0), 1.0);
  for (ScenePolygon& p : testing::open_cube("b", Vec3(1, 0, -0.5), 1.0)) polygons.push_back(p);
  const ContentKind kinds[] = {ContentKind::kTexture, ContentKind::kShaded, ContentKind::kImpostor};
  for (std::size_t i = 0; i < polygons.size(); ++i) polygons[i].content = kinds[i % 3];
  const Scene scene = testing::scene_with(polygons);
  const Camera camera = make_camera(520.0, 640, 480);
  SceneSettings settings;
  settings.engine.policy = &reuse_policy(mode);
  settings.engine.cadence = cadence;
  SceneEngine engine(scene, camera, settings);
  const ViewerPose start = look_at(Vec3(-0.5, 1.2, 4), Vec3(0, 0, 0), Vec3(0, 1, 0));
  const auto frames = expand_viewer_segments(
      start, {{4, Vec3(0.05, 0, -0.03), Vec3(0.0)}, {4, Vec3(0.0), Vec3(0, 0.03, 0.01)}});
  Played played;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const AnimationFrame r =
        i == 0 ? engine.start(frames[0].pose)
               : engine.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    played.frames.push_back(engine.frame().pixels());
    std::vector<double> f = {static_cast<double>(r.pixels_written),
                             r.model_work,
                             static_cast<double>(r.pixels_composited),
                             r.max_measured_error_px,
                             static_cast<double>(r.hidden),
                             r.max_photometric_error,
                             static_cast<double>(r.hole_pixels),
                             static_cast<double>(r.inpainted_pixels)};
    for (int l = 0; l < kLevelCount; ++l) f.push_back(r.levels[l]);
    played.figures.push_back(f);
  }
  return played;
}

TEST(ThreadPool, SceneFramesAndReportsAreTheSameWithOneAndTwoThreads) {
  for (const std::string mode : {"perspective", "rerender"}) {
    const Played one = play_cubes(mode, 1), two = play_cubes(mode, 2);
    ASSERT_EQ(one.frames.size(), two.frames.size());
    for (std::size_t i = 0; i < one.frames.size(); ++i) {
      EXPECT_TRUE(one.frames[i] == two.frames[i]) << mode << " frame " << i;
      EXPECT_EQ(one.figures[i], two.figures[i]) << mode << " frame " << i;
    }
    // Negative control: the comparison sees a changed frame (the next frame differs).
    EXPECT_FALSE(one.frames[1] == two.frames[2]) << mode;
  }
}

// Frame generation's policies paint, merge and inpaint in bands of rows (core/scene/
// frame_generation.h, view_interpolation.h, depth_mesh.h): on 1, 2 and 3 threads the frames
// and figures are the same, the generated frames (every other one) included.
TEST(ThreadPool, FrameGenerationFramesAndReportsAreTheSameWithOneTwoAndThreeThreads) {
  for (const std::string mode :
       {"mv-extrapolation", "mv-no-inpaint", "view-interpolation", "depth-mesh"}) {
    const Played one = play_cubes(mode, 1, 2);
    for (const int threads : {2, 3}) {
      const Played more = play_cubes(mode, threads, 2);
      ASSERT_EQ(one.frames.size(), more.frames.size());
      for (std::size_t i = 0; i < one.frames.size(); ++i) {
        EXPECT_TRUE(one.frames[i] == more.frames[i]) << mode << " frame " << i << ", " << threads;
        EXPECT_EQ(one.figures[i], more.figures[i]) << mode << " frame " << i << ", " << threads;
      }
    }
    // The generated frames are there, and the comparison sees a changed frame (the next one).
    EXPECT_GT(one.figures[1][0], 0.0) << mode;
    EXPECT_FALSE(one.frames[1] == one.frames[2]) << mode;
  }
}

}  // namespace
}  // namespace oflab
