// Scratch memory a tile's wavefront reuses: queues and path states sized
// for a tile, handed to one render thread at a time and kept for the next
// tile. Allocating them per tile made the allocator return the pages to
// the kernel and fault them back in, tile after tile (a quarter of the
// path tracer's time went to TLB shootdowns).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

namespace prism {

template <typename Workspace>
class WorkspacePool
{
 public:
  // A workspace for the caller's exclusive use until it is destroyed.
  class Lease
  {
   public:
    Lease(WorkspacePool &pool, std::unique_ptr<Workspace> workspace)
        : m_pool(pool), m_workspace(std::move(workspace))
    {}
    ~Lease()
    {
      m_pool.giveBack(std::move(m_workspace));
    }
    Lease(const Lease &) = delete;
    Lease &operator=(const Lease &) = delete;

    Workspace &operator*() const
    {
      return *m_workspace;
    }
    Workspace *operator->() const
    {
      return m_workspace.get();
    }

   private:
    WorkspacePool &m_pool;
    std::unique_ptr<Workspace> m_workspace;
  };

  Lease take()
  {
    std::unique_ptr<Workspace> workspace;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_free.empty()) {
        workspace = std::move(m_free.back());
        m_free.pop_back();
      }
    }
    if (!workspace)
      workspace = std::make_unique<Workspace>();
    return Lease(*this, std::move(workspace));
  }

 private:
  void giveBack(std::unique_ptr<Workspace> workspace)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_free.push_back(std::move(workspace));
  }

  std::mutex m_mutex;
  std::vector<std::unique_ptr<Workspace>> m_free;
};

} // namespace prism
