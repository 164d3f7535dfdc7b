// NSIEvaluate type "dynamiclibrary": procedural libraries loaded once per
// context (nsi_procedural.h), executed per Evaluate, unloaded at NSIEnd.
#pragma once

#include "GeometryBuilder.h"
#include "ParameterList.h"

#include <map>
#include <string>

struct NSIProcedural_t;

namespace prism::nsi {

class DynamicProcedurals
{
 public:
  DynamicProcedurals(NSIContext_t ctx, ReportFunction report);
  // Unloads every library (each procedural's unload, then dlclose).
  ~DynamicProcedurals();
  DynamicProcedurals(const DynamicProcedurals &) = delete;
  DynamicProcedurals &operator=(const DynamicProcedurals &) = delete;

  // Loads `fileName` unless loaded, then executes it with `params`.
  void execute(const std::string &fileName, const ParameterList &params);

 private:
  struct Library
  {
    void *handle{nullptr};
    NSIProcedural_t *procedural{nullptr};
  };
  // Null (reported) when the library cannot be used.
  NSIProcedural_t *load(const std::string &fileName);

  NSIContext_t m_ctx;
  ReportFunction m_report;
  std::map<std::string, Library> m_libraries; // by the name given
};

} // namespace prism::nsi
