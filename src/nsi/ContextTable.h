// The process's NSI contexts by handle. Handles are never reused, so a stale
// handle is reported as unknown rather than reaching another context.
#pragma once

#include "Context.h"

#include <map>
#include <memory>
#include <mutex>

namespace prism::nsi {

class ContextTable
{
 public:
  static ContextTable &instance();

  NSIContext_t add(std::function<std::shared_ptr<Context>(NSIContext_t)> make);
  std::shared_ptr<Context> find(NSIContext_t id);
  std::shared_ptr<Context> take(NSIContext_t id);

 private:
  std::mutex m_mutex;
  std::map<NSIContext_t, std::shared_ptr<Context>> m_contexts;
  NSIContext_t m_next{1};
};

} // namespace prism::nsi
