// The task pool's thread count: what tasks see as their arena's
// concurrency, before and after setThreads.
#include "parallel/TaskPool.h"

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <chrono>
#include <thread>

namespace prism {
namespace {

int concurrencySeenByATask(TaskPool &pool)
{
  int seen = 0;
  pool.run([&] { seen = tbb::this_task_arena::max_concurrency(); });
  pool.wait();
  return seen;
}

TEST(TaskPool, SetThreadsLimitsTheArenaOfLaterTasks)
{
  TaskPool pool;
  const int everyThread = concurrencySeenByATask(pool);
  EXPECT_EQ(everyThread, tbb::this_task_arena::max_concurrency());
  pool.setThreads(1);
  EXPECT_EQ(concurrencySeenByATask(pool), 1);
  pool.setThreads(3);
  EXPECT_EQ(concurrencySeenByATask(pool), 3);
  pool.setThreads(0);
  EXPECT_EQ(concurrencySeenByATask(pool), everyThread);
}

TEST(TaskPool, SetThreadsWaitsForQueuedTasks)
{
  TaskPool pool;
  bool finished = false;
  pool.run([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    finished = true;
  });
  pool.setThreads(1);
  EXPECT_TRUE(finished);
  EXPECT_EQ(concurrencySeenByATask(pool), 1);
}

} // namespace
} // namespace prism
