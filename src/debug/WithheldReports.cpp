#include "WithheldReports.h"

namespace prism::debug {
namespace {

// Per thread: a report on another thread (a frame rendering in the
// background) is about another call.
thread_local const void *t_withholding = nullptr;

} // namespace

WithheldReports::WithheldReports(const void *layerDevice, bool withhold)
    : m_previous(t_withholding)
{
  if (withhold)
    t_withholding = layerDevice;
}

WithheldReports::~WithheldReports()
{
  t_withholding = m_previous;
}

bool WithheldReports::withheld(
    const void *layerDevice, ANARIStatusSeverity severity)
{
  // Performance warnings and information are not about the misuse.
  return t_withholding == layerDevice && severity <= ANARI_SEVERITY_WARNING;
}

} // namespace prism::debug
