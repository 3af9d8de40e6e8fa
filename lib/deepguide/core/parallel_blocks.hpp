#pragma once
// Runs fn(begin, end, worker) over [0, count) in blocks of `block` items,
// handed out one at a time to `workers` threads (the calling thread is one of
// them), so uneven work per item still spreads evenly. `worker` is in
// [0, workers) and lets fn keep per-thread scratch space and results. The
// first exception a block throws stops the hand-out and is rethrown here.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// The threads worth using for CPU-bound work: the machine's cores, at least 1.
inline std::size_t hardware_workers() { return std::max<std::size_t>(1, std::thread::hardware_concurrency()); }

template <class Fn>
void parallel_blocks(std::size_t count, std::size_t block, std::size_t workers, Fn fn) {
  if (count == 0) return;
  block = std::max<std::size_t>(block, 1);
  workers = std::clamp<std::size_t>(workers, 1, (count + block - 1) / block);
  if (workers <= 1) {
    fn(std::size_t{0}, count, std::size_t{0});
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto run = [&](std::size_t worker) {
    try {
      for (std::size_t begin = next.fetch_add(block); begin < count && !failed; begin = next.fetch_add(block)) {
        fn(begin, std::min(begin + block, count), worker);
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  {
    std::vector<std::jthread> threads;
    for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(run, w);
    run(0);
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace deepguide
