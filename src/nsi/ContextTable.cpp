#include "ContextTable.h"

namespace prism::nsi {

ContextTable &ContextTable::instance()
{
  static ContextTable table;
  return table;
}

NSIContext_t ContextTable::add(
    std::function<std::shared_ptr<Context>(NSIContext_t)> make)
{
  NSIContext_t id;
  {
    std::lock_guard lock(m_mutex);
    if (m_next <= 0) // every positive int used: no more contexts
      return NSI_BAD_CONTEXT;
    id = m_next++;
  }
  auto context = make(id);
  if (!context)
    return NSI_BAD_CONTEXT;
  std::lock_guard lock(m_mutex);
  m_contexts[id] = std::move(context);
  return id;
}

std::shared_ptr<Context> ContextTable::find(NSIContext_t id)
{
  std::lock_guard lock(m_mutex);
  auto it = m_contexts.find(id);
  return it == m_contexts.end() ? nullptr : it->second;
}

std::shared_ptr<Context> ContextTable::take(NSIContext_t id)
{
  std::lock_guard lock(m_mutex);
  auto it = m_contexts.find(id);
  if (it == m_contexts.end())
    return nullptr;
  auto context = std::move(it->second);
  m_contexts.erase(it);
  return context;
}

} // namespace prism::nsi
