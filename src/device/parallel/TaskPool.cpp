#include "TaskPool.h"

namespace prism {

TaskPool::TaskPool(int threads)
    : m_arena(threads > 0 ? threads : tbb::task_arena::automatic),
      m_thread([this] { loop(); })
{}

TaskPool::~TaskPool()
{
  {
    std::lock_guard lock(m_mutex);
    m_stopping = true;
  }
  m_wake.notify_all();
  m_thread.join();
}

void TaskPool::run(std::function<void()> task)
{
  {
    std::lock_guard lock(m_mutex);
    m_queue.push_back(std::move(task));
  }
  m_wake.notify_one();
}

void TaskPool::wait()
{
  if (isWorkerThread())
    return; // a task waiting for itself would never return
  std::unique_lock lock(m_mutex);
  m_idle.wait(lock, [&] { return m_queue.empty() && !m_busy; });
}

void TaskPool::setThreads(int threads)
{
  if (isWorkerThread())
    return; // the arena is in use by the caller itself
  // NOTE: the lock keeps the pool thread from starting a task (and so from
  // entering the arena) while the arena is rebuilt.
  std::unique_lock lock(m_mutex);
  m_idle.wait(lock, [&] { return m_queue.empty() && !m_busy; });
  m_arena.terminate();
  m_arena.initialize(threads > 0 ? threads : tbb::task_arena::automatic);
}

void TaskPool::loop()
{
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(m_mutex);
      m_wake.wait(lock, [&] { return m_stopping || !m_queue.empty(); });
      if (m_queue.empty())
        return; // stopping, nothing left
      task = std::move(m_queue.front());
      m_queue.pop_front();
      m_busy = true;
    }
    m_arena.execute([&] { task(); });
    {
      std::lock_guard lock(m_mutex);
      m_busy = false;
    }
    m_idle.notify_all();
  }
}

} // namespace prism
