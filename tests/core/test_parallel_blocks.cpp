// core/parallel_blocks: every item once, in blocks, on the threads asked for;
// nothing for no items; a block's exception reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "deepguide/core/parallel_blocks.hpp"

using namespace deepguide;

TEST(ParallelBlocks, EveryItemOnceOnTheWorkersAsked) {
  std::vector<std::atomic<int>> seen(1000);
  std::vector<std::atomic<int>> by_worker(3);
  parallel_blocks(seen.size(), 7, 3, [&](std::size_t begin, std::size_t end, std::size_t worker) {
    EXPECT_LE(end - begin, 7u);
    ASSERT_LT(worker, 3u);
    by_worker[worker] += static_cast<int>(end - begin);
    for (std::size_t i = begin; i < end; ++i) ++seen[i];
  });
  for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
  EXPECT_EQ(by_worker[0] + by_worker[1] + by_worker[2], 1000);
}

TEST(ParallelBlocks, NoItemsNoCallsAndErrorsReachTheCaller) {
  int calls = 0;
  parallel_blocks(0, 16, 4, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_THROW(parallel_blocks(100, 1, 2,
                               [](std::size_t begin, std::size_t, std::size_t) {
                                 if (begin == 42) throw std::runtime_error("block 42");
                               }),
               std::runtime_error);
}
