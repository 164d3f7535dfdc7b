// The task pool's thread count: what tasks see as their arena's
// concurrency, before and after setThreads, which waits for queued tasks.
#include "parallel/TaskPool.h"

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <atomic>
#include <future>
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

// Whether setThreads, called from another thread while a queued task is
// held at a gate, returned only after the task had finished.
bool setThreadsWaitedForAHeldTask(TaskPool &pool, int threads)
{
  std::promise<void> gate;
  std::atomic<bool> finished{false}, calling{false};
  pool.run([&, open = gate.get_future().share()] {
    open.wait();
    finished = true;
  });
  bool finishedWhenSetThreadsReturned = false;
  std::thread caller([&] {
    calling = true;
    pool.setThreads(threads);
    finishedWhenSetThreadsReturned = finished;
  });
  while (!calling)
    std::this_thread::yield();
  gate.set_value();
  caller.join();
  return finishedWhenSetThreadsReturned;
}

TEST(TaskPool, SetThreadsWaitsForQueuedTasks)
{
  // No sleeps: for a correct pool the result never depends on timing (the
  // gate opens whether or not setThreads has been entered yet). A pool that
  // did not wait is caught in a round where setThreads starts before the
  // gate opens, which waiting for the caller makes common; rounds are
  // cheap, so many of them. (A pool whose setThreads forgot the running
  // task failed 6 runs in 10 of this test, 1 in 10 of the 50 ms sleep it
  // replaces: TBB's arena terminate() waits for some of it.)
  TaskPool pool;
  for (int round = 0; round < 32; round++) {
    const int threads = 1 + round % 2;
    ASSERT_TRUE(setThreadsWaitedForAHeldTask(pool, threads)) << round;
    EXPECT_EQ(concurrencySeenByATask(pool), threads);
  }
}

} // namespace
} // namespace prism
