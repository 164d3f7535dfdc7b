// The device's workers: frames render one after another on a background
// thread that owns the arena's master slot, so TBB's workers join it for
// the per-tile loops (all cores busy, no oversubscription, no extra TBB
// global settings imposed on the application).
#pragma once

#include <tbb/task_arena.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace prism {

class TaskPool
{
 public:
  // `threads` 0 uses every hardware thread.
  explicit TaskPool(int threads = 0);
  ~TaskPool();
  TaskPool(const TaskPool &) = delete;
  TaskPool &operator=(const TaskPool &) = delete;

  // Queues `task` to run on the background thread, inside the arena.
  void run(std::function<void()> task);
  // Waits until every queued task has finished.
  void wait();
  // Waits until the pool is idle, then runs later tasks on `threads`
  // threads (0: every hardware thread).
  void setThreads(int threads);
  // Whether the caller is the pool's background thread.
  bool isWorkerThread() const
  {
    return std::this_thread::get_id() == m_thread.get_id();
  }

 private:
  void loop();

  tbb::task_arena m_arena;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::condition_variable m_idle;
  std::deque<std::function<void()>> m_queue;
  bool m_busy{false};
  bool m_stopping{false};
  std::thread m_thread;
};

} // namespace prism
