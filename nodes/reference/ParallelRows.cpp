#include "reference/ParallelRows.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace aokit {

int resolveThreadCount(int threads, int rows) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(threads, rows));
}

void parallelRows(int rows, int threads, const std::function<void(int)>& work,
                  const std::function<void(double)>& progress) {
  if (rows <= 0) {
    if (progress) progress(1.0);
    return;
  }
  const int count = resolveThreadCount(threads, rows);
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable finished;
  std::exception_ptr failure;
  int running = count;

  auto worker = [&] {
    try {
      for (int row; !stop.load(std::memory_order_relaxed) && (row = next.fetch_add(1)) < rows;) {
        work(row);
        done.fetch_add(1, std::memory_order_relaxed);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
    std::lock_guard<std::mutex> lock(mutex);
    if (--running == 0) finished.notify_all();
  };

  std::vector<std::thread> pool;
  pool.reserve(count);
  for (int i = 0; i < count; ++i) pool.emplace_back(worker);

  std::exception_ptr progressFailure;
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(100));
      if (!progress || running == 0 || progressFailure) continue;
      lock.unlock();
      try {
        progress(static_cast<double>(done.load()) / rows);
      } catch (...) {
        progressFailure = std::current_exception();
        stop = true;
      }
      lock.lock();
    }
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (progressFailure) std::rethrow_exception(progressFailure);
  if (progress) progress(1.0);
}

}  // namespace aokit
