#include "DynamicProcedurals.h"

#include "ContextTable.h"

#include <nsi_procedural.h>

#include <dlfcn.h>

#ifndef PRISM_NSI_VERSION_STRING
#define PRISM_NSI_VERSION_STRING "unknown"
#endif

namespace prism::nsi {

namespace {

// The context whose procedural is being called on this thread: its reports
// reach it even while NSIEnd has taken it out of the table.
thread_local const std::pair<NSIContext_t, const ReportFunction *> *t_calling =
    nullptr;

void reportFromProcedural(NSIContext_t ctx, int level, const char *message)
{
  const std::string text = message ? message : "";
  if (t_calling && t_calling->first == ctx)
    return (*t_calling->second)(level, text);
  if (auto context = ContextTable::instance().find(ctx))
    return context->report(level, text);
  defaultErrorHandler(nullptr, level, 0, text.c_str());
}

// Makes the procedural's reports reach this context while it runs.
class Calling
{
 public:
  Calling(NSIContext_t ctx, const ReportFunction &report)
      : m_this(ctx, &report), m_previous(t_calling)
  {
    t_calling = &m_this;
  }
  ~Calling()
  {
    t_calling = m_previous;
  }

 private:
  std::pair<NSIContext_t, const ReportFunction *> m_this;
  const std::pair<NSIContext_t, const ReportFunction *> *m_previous;
};

// libnsi's own file, which a procedural may load to call NSI through it.
std::string libraryPath()
{
  Dl_info info{};
  if (dladdr(reinterpret_cast<void *>(&reportFromProcedural), &info)
      && info.dli_fname)
    return info.dli_fname;
  return {};
}

} // namespace

DynamicProcedurals::DynamicProcedurals(NSIContext_t ctx, ReportFunction report)
    : m_ctx(ctx), m_report(std::move(report))
{}

DynamicProcedurals::~DynamicProcedurals()
{
  Calling calling(m_ctx, m_report);
  for (auto &[name, library] : m_libraries) {
    if (library.procedural && library.procedural->unload)
      library.procedural->unload(
          m_ctx, reportFromProcedural, library.procedural);
    if (library.handle)
      dlclose(library.handle);
  }
}

NSIProcedural_t *DynamicProcedurals::load(const std::string &fileName)
{
  if (auto found = m_libraries.find(fileName); found != m_libraries.end())
    return found->second.procedural;
  const std::string what = "NSIEvaluate: procedural '" + fileName + "': ";
#ifdef PRISM_NSI_NO_DYNAMIC_LIBRARIES
  // The fuzzing build: its inputs must not name libraries to load.
  m_report(
      NSIErrError, what + "dynamic libraries are not loaded in this build");
  return nullptr;
#endif
  dlerror();
  void *handle = dlopen(fileName.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char *why = dlerror();
    m_report(NSIErrError, what + "cannot load: " + (why ? why : "unknown"));
    return nullptr;
  }
  auto entry =
      reinterpret_cast<NSIProceduralLoad_t>(dlsym(handle, "NSIProceduralLoad"));
  if (!entry) {
    m_report(NSIErrError, what + "has no NSIProceduralLoad");
    dlclose(handle);
    return nullptr;
  }
  NSIProcedural_t *procedural = nullptr;
  {
    Calling calling(m_ctx, m_report);
    procedural = entry(m_ctx,
        reportFromProcedural,
        libraryPath().c_str(),
        "Prism " PRISM_NSI_VERSION_STRING);
  }
  if (!procedural) {
    m_report(NSIErrError, what + "NSIProceduralLoad returned nothing");
    dlclose(handle);
    return nullptr;
  }
  // A library whose version is not ours may lay the struct out otherwise:
  // nothing of it is called, not even unload.
  if (procedural->nsi_version == 0 || procedural->nsi_version > NSI_VERSION) {
    m_report(NSIErrError,
        what + "built for NSI version "
            + std::to_string(procedural->nsi_version) + ", not "
            + std::to_string(NSI_VERSION));
    dlclose(handle);
    return nullptr;
  }
  m_libraries[fileName] = {handle, procedural};
  return procedural;
}

void DynamicProcedurals::execute(
    const std::string &fileName, const ParameterList &params)
{
  NSIProcedural_t *procedural = load(fileName);
  if (!procedural)
    return;
  if (!procedural->execute) {
    m_report(NSIErrError,
        "NSIEvaluate: procedural '" + fileName + "' has no execute function");
    return;
  }
  const ParamArray array(params);
  Calling calling(m_ctx, m_report);
  procedural->execute(
      m_ctx, reportFromProcedural, procedural, array.size(), array.data());
}

} // namespace prism::nsi
