// The worker threads of core's pixel loops: a small process-wide pool that runs the bands
// of one loop (rows of a warp, of a lit content's render, of a composite) at once.
//
// Determinism. A loop is cut into bands by its size alone (band_count), never by the number
// of threads, and every band writes only its own rows and its own slot of any per-band
// tally, which the caller sums in band order. So a frame and its report are the same bytes
// with 1 thread or with 8; the threads only decide which core runs which band.
//
// Race freedom. One loop runs on the pool at a time: a second caller (another thread, or a
// band that itself loops over bands) runs its bands itself, in order, on its own thread.
// The pool's state is guarded by one mutex; a band's body must not touch another band's
// rows. The default is 1 thread (no worker is started): the programs set the machine's
// cores (oflab-cli and oflab, option --threads), the browser page keeps 1.
#pragma once

#include <functional>

#include "flow/limits.h"

namespace oflab {

// Limits of set_worker_threads and of the bands of one loop.
constexpr int kMaxWorkerThreads = 64;
constexpr int kMaxBands = 16;

namespace limits {
// The threads that run core's pixel loops (`--threads N` of oflab-cli and oflab).
inline constexpr Limit kWorkerThreads{"thread count", "threads", 1.0, kMaxWorkerThreads, true};
}  // namespace limits

// The number of threads that run a loop's bands (the calling thread and the workers), >= 1.
int worker_threads();

// Sets the number of threads (1..kMaxWorkerThreads; 1: every band on the calling thread).
// Throws std::invalid_argument outside that range. Must not be called while a loop runs
// (the programs call it once, at start-up). When threads cannot be started (a platform
// without them), the pool stays at 1 thread.
void set_worker_threads(int count);

// The machine's cores as the standard library reports them (>= 1).
int machine_cores();

// How many bands a loop of `rows` rows is cut into when each band should have at least
// `min_rows` rows (>= 1): min(rows / min_rows, kMaxBands), at least 1; 0 rows give 1.
int band_count(int rows, int min_rows);

// Runs body(band, begin, end) for every band of band_count(rows, min_rows), rows
// [begin, end) of [0, rows), consecutive and in order, on the pool's threads, and returns
// when all are done. With one band, or one thread, or while another loop runs, the bands
// run here, in order. An exception thrown by a band is rethrown here (the first band's
// first) after every band has finished.
void for_each_band(int rows, int min_rows, const std::function<void(int, int, int)>& body);

}  // namespace oflab
