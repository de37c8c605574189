#pragma once
// Runs work(row) for every row on worker threads that pull rows from an atomic counter, while the
// calling thread reports progress. Row results must depend on the row only (never on the thread),
// which keeps outputs identical for any thread count.
#include <functional>

namespace aokit {

// threads <= 0: std::thread::hardware_concurrency(). progress (optional) is called on the calling
// thread with the finished fraction, about every 100 ms and once with 1.0 at the end. An exception
// thrown by work or by progress stops the remaining rows and is rethrown here after all workers
// joined: a throwing progress callback is how a caller interrupts a long run.
void parallelRows(int rows, int threads, const std::function<void(int row)>& work,
                  const std::function<void(double)>& progress = {});

// The thread count parallelRows will use.
int resolveThreadCount(int threads, int rows);

}  // namespace aokit
