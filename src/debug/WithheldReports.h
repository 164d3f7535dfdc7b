// One report per problem: while the layer forwards a call it has already
// reported a problem about, the wrapped device's own warnings and errors on
// that thread are withheld. They would report the same problem again, in the
// wrapped device's words (docs/debug-layer.md).
#pragma once

#include "anari/anari.h"

namespace prism::debug {

class WithheldReports
{
 public:
  // Withholds the reports of `layerDevice`'s wrapped device on this thread
  // until destroyed, if `withhold`.
  WithheldReports(const void *layerDevice, bool withhold);
  ~WithheldReports();
  WithheldReports(const WithheldReports &) = delete;
  WithheldReports &operator=(const WithheldReports &) = delete;

  // Whether a message of `severity` from `layerDevice`'s wrapped device,
  // arriving on this thread now, is withheld.
  static bool withheld(const void *layerDevice, ANARIStatusSeverity severity);

 private:
  const void *m_previous;
};

} // namespace prism::debug
