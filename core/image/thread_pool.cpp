// The worker threads of core's pixel loops (core/image/thread_pool.h): one job at a time,
// its bands handed out in order under one mutex, the caller taking bands too.
#include "image/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace oflab {
namespace {

// One loop's bands: which is next, how many are unfinished, each band's exception.
struct Job {
  const std::function<void(int, int, int)>* body = nullptr;
  int rows = 0;
  int bands = 0;
  int next = 0;                            // guarded by the pool's mutex
  std::atomic<int> unfinished{0};          // written under the mutex, read by the waiting caller
  std::vector<std::exception_ptr> errors;  // each band writes its own
};

void run_band(const std::function<void(int, int, int)>& body, int band, int begin, int end);

using Clock = std::chrono::steady_clock;

// How long a worker watches for the next loop before it sleeps, and a caller for the last
// bands before it sleeps: a frame runs many short loops one after another, and a thread
// woken from sleep on a busy machine may wait a whole time slice for a core.
constexpr auto kWorkerSpin = std::chrono::microseconds(200);
constexpr auto kCallerSpin = std::chrono::microseconds(500);

class Pool {
 public:
  ~Pool() { stop(); }

  int threads() const { return threads_; }

  void resize(int count) {
    stop();
    threads_ = 1;
    stopping_ = false;
    try {
      // A worker starts from the jobs posted before it was made, so it cannot miss one
      // posted before it first runs.
      const unsigned posted = posted_.load();
      for (int i = 1; i < count; ++i) workers_.emplace_back([this, posted] { work(posted); });
      threads_ = count;
    } catch (const std::system_error&) {
      stop();  // no threads here: every band on the caller
      threads_ = 1;
    }
  }

  // Runs the job's bands, or returns false when another job holds the pool.
  bool run(Job& job) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    std::unique_lock<std::mutex> lock(mutex_);
    job_ = &job;
    posted_.fetch_add(1, std::memory_order_release);
    wake_.notify_all();
    take_bands(job, lock);
    lock.unlock();
    const auto until = Clock::now() + kCallerSpin;
    while (job.unfinished.load(std::memory_order_acquire) > 0 && Clock::now() < until) {
      std::this_thread::yield();
    }
    lock.lock();
    done_.wait(lock, [&] { return job.unfinished.load() == 0; });
    job_ = nullptr;  // under the mutex: no worker reaches the job after this
    return true;
  }

 private:
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
    workers_.clear();
  }

  void work(unsigned seen) {
    for (;;) {
      const auto until = Clock::now() + kWorkerSpin;
      while (posted_.load(std::memory_order_acquire) == seen && Clock::now() < until) {
        std::this_thread::yield();
      }
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || posted_.load() != seen; });
      if (stopping_) return;
      seen = posted_.load();
      if (job_) take_bands(*job_, lock);
    }
  }

  // Takes the job's next band until none is left; the last to finish wakes the caller.
  // `lock` holds the mutex on entry and on return, so the job is alive while it is read.
  void take_bands(Job& job, std::unique_lock<std::mutex>& lock) {
    while (job.next < job.bands) {
      const int band = job.next++;
      lock.unlock();
      const int begin = static_cast<int>(static_cast<long long>(job.rows) * band / job.bands);
      const int end = static_cast<int>(static_cast<long long>(job.rows) * (band + 1) / job.bands);
      try {
        run_band(*job.body, band, begin, end);
      } catch (...) {
        job.errors[static_cast<std::size_t>(band)] = std::current_exception();
      }
      lock.lock();
      if (job.unfinished.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_all();
    }
  }

  std::mutex busy_;   // held by the one job on the pool
  std::mutex mutex_;  // guards job_, stopping_ and the job's next band
  std::condition_variable wake_;
  std::condition_variable done_;
  Job* job_ = nullptr;
  std::atomic<unsigned> posted_{0};  // jobs posted so far
  bool stopping_ = false;
  int threads_ = 1;
  std::vector<std::thread> workers_;
};

// True on a thread while it runs a band: a loop inside a band runs its own bands in order.
thread_local bool in_band = false;

// Runs one band, marking the thread as inside it.
void run_band(const std::function<void(int, int, int)>& body, int band, int begin, int end) {
  in_band = true;
  try {
    body(band, begin, end);
  } catch (...) {
    in_band = false;
    throw;
  }
  in_band = false;
}

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

int worker_threads() { return pool().threads(); }

void set_worker_threads(int count) {
  if (count < 1 || count > kMaxWorkerThreads) {
    throw std::invalid_argument("worker threads: " + std::to_string(count) + " is outside 1.." +
                                std::to_string(kMaxWorkerThreads));
  }
  if (count != pool().threads()) pool().resize(count);
}

int machine_cores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

int band_count(int rows, int min_rows) {
  if (rows <= 0 || min_rows <= 0) return 1;
  return std::clamp(rows / min_rows, 1, kMaxBands);
}

void for_each_band(int rows, int min_rows, const std::function<void(int, int, int)>& body) {
  const int bands = band_count(rows, min_rows);
  Job job;
  job.body = &body;
  job.rows = std::max(rows, 0);
  job.bands = bands;
  job.unfinished.store(bands);
  job.errors.resize(static_cast<std::size_t>(bands));
  if (bands == 1 || in_band || pool().threads() == 1 || !pool().run(job)) {
    for (int band = 0; band < bands; ++band) {
      body(band, job.rows * band / bands, job.rows * (band + 1) / bands);
    }
    return;
  }
  for (const std::exception_ptr& e : job.errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace oflab
