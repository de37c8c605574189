#pragma once
// N ranks of a parallel renderer as N threads of one test (parallel/RankExchange.h): each
// collective waits until every rank has brought its buffer, then hands each the result.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "parallel/RankExchange.h"

namespace aokit::testing {

class ThreadGroup {
 public:
  explicit ThreadGroup(int n) : n_(n), buffers_(n) {}
  int size() const { return n_; }
  // Every rank's bytes, once all have arrived (a generation barrier keeps calls in step).
  std::vector<std::vector<std::uint8_t>> exchange(int rank, std::vector<std::uint8_t> mine) {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait(lock, [&] { return !draining_; });
    buffers_[rank] = std::move(mine);
    if (++arrived_ == n_) {
      result_ = buffers_;
      draining_ = true;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return draining_; });
    }
    std::vector<std::vector<std::uint8_t>> out = result_;
    if (--arrived_ == 0) {
      draining_ = false;
      cv_.notify_all();
    }
    return out;
  }

 private:
  int n_;
  std::mutex m_;
  std::condition_variable cv_;
  std::vector<std::vector<std::uint8_t>> buffers_, result_;
  int arrived_ = 0;
  bool draining_ = false;
};

class ThreadRanks : public RankExchange {
 public:
  ThreadRanks(ThreadGroup& group, int rank) : group_(group), rank_(rank) {}
  int ranks() const override { return group_.size(); }
  int rank() const override { return rank_; }
  void minimum(std::vector<float>& v) override { reduce(v, [](float a, float b) { return b < a ? b : a; }); }
  void minimum(std::vector<double>& v) override { reduce(v, [](double a, double b) { return b < a ? b : a; }); }
  void minimum(std::vector<int>& v) override { reduce(v, [](int a, int b) { return b < a ? b : a; }); }
  void bitwiseOr(std::vector<std::uint8_t>& v) override {
    reduce(v, [](std::uint8_t a, std::uint8_t b) { return static_cast<std::uint8_t>(a | b); });
  }
  std::vector<std::vector<std::uint8_t>> allGather(const std::vector<std::uint8_t>& mine) override {
    ++calls;
    return group_.exchange(rank_, mine);
  }
  int calls = 0;  // collectives this rank took part in

 private:
  template <class T, class Op>
  void reduce(std::vector<T>& v, Op op) {
    ++calls;
    std::vector<std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(v.data()),
                                    reinterpret_cast<const std::uint8_t*>(v.data() + v.size()));
    const auto all = group_.exchange(rank_, std::move(bytes));
    for (const auto& b : all) {
      const T* other = reinterpret_cast<const T*>(b.data());
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = op(v[i], other[i]);
    }
  }
  ThreadGroup& group_;
  int rank_;
};

// Runs body(rank, exchange) on n threads at once and waits for them.
inline void onRanks(int n, const std::function<void(int, ThreadRanks&)>& body) {
  ThreadGroup group(n);
  std::vector<ThreadRanks> ranks;
  for (int r = 0; r < n; ++r) ranks.emplace_back(group, r);
  std::vector<std::thread> threads;
  for (int r = 0; r < n; ++r) threads.emplace_back([&, r] { body(r, ranks[r]); });
  for (std::thread& t : threads) t.join();
}

}  // namespace aokit::testing
