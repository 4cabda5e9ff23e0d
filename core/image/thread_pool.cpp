// The worker threads of core's pixel loops (core/image/thread_pool.h): one job at a time,
// its bands handed out in order under one mutex, the caller taking bands too.
#include "image/thread_pool.h"

#include <algorithm>
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
  int next = 0;
  int unfinished = 0;
  std::vector<std::exception_ptr> errors;
};

void run_band(const std::function<void(int, int, int)>& body, int band, int begin, int end);

class Pool {
 public:
  ~Pool() { stop(); }

  int threads() const { return threads_; }

  void resize(int count) {
    stop();
    threads_ = 1;
    stopping_ = false;
    try {
      for (int i = 1; i < count; ++i) workers_.emplace_back([this] { work(); });
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
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
    }
    wake_.notify_all();
    take_bands(job);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return job.unfinished == 0; });
    job_ = nullptr;
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

  void work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || (job_ && job_->next < job_->bands); });
      if (stopping_) return;
      Job& job = *job_;
      lock.unlock();
      take_bands(job);
      lock.lock();
    }
  }

  // Takes the job's next band until none is left; the last to finish wakes the caller.
  void take_bands(Job& job) {
    std::unique_lock<std::mutex> lock(mutex_);
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
      if (--job.unfinished == 0) done_.notify_all();
    }
  }

  std::mutex busy_;   // held by the one job on the pool
  std::mutex mutex_;  // guards job_, stopping_ and the job's next and unfinished
  std::condition_variable wake_;
  std::condition_variable done_;
  Job* job_ = nullptr;
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
  job.unfinished = bands;
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
