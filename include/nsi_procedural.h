/* NSI dynamic-library procedurals: what a library loaded by NSIEvaluate
 * type "dynamiclibrary" exports and what the renderer calls in it. Written
 * for Prism from the NSI specification; the names and layout are NSI's so
 * procedurals built against another NSI renderer's header load unchanged. */
#ifndef NSI_PROCEDURAL_H
#define NSI_PROCEDURAL_H

#include "nsi.h"

#ifdef __cplusplus
extern "C" {
#endif

struct NSIProcedural_t;

/* Reports a message through the context's error handler. */
typedef void (*NSIReport_t)(NSIContext_t ctx, int level, const char *message);

#define NSI_PROCEDURAL_UNLOAD_PARAMS \
  NSIContext_t ctx, NSIReport_t report, struct NSIProcedural_t *proc
#define NSI_PROCEDURAL_EXECUTE_PARAMS                                 \
  NSIContext_t ctx, NSIReport_t report, struct NSIProcedural_t *proc, \
      int nparams, const struct NSIParam_t *params
#define NSI_PROCEDURAL_LOAD_PARAMS                                    \
  NSIContext_t ctx, NSIReport_t report, const char *nsi_library_path, \
      const char *renderer_version

/* Called once, at NSIEnd, after the last execution. */
#define NSI_PROCEDURAL_UNLOAD(name) void name(NSI_PROCEDURAL_UNLOAD_PARAMS)
typedef void (*NSIProceduralUnload_t)(NSI_PROCEDURAL_UNLOAD_PARAMS);

/* Called per NSIEvaluate with its parameters: makes the NSI calls. */
#define NSI_PROCEDURAL_EXECUTE(name) void name(NSI_PROCEDURAL_EXECUTE_PARAMS)
typedef void (*NSIProceduralExecute_t)(NSI_PROCEDURAL_EXECUTE_PARAMS);

/* Owned by the procedural, which may allocate more than this to keep its
 * own data after it; the renderer never copies or changes it. */
struct NSIProcedural_t
{
  unsigned nsi_version; /* NSI_VERSION of the header it was built with */
  NSIProceduralUnload_t unload;
  NSIProceduralExecute_t execute;
};

#define NSI_PROCEDURAL_INIT(proc, unload_function, execute_function) \
  do {                                                               \
    (proc).nsi_version = NSI_VERSION;                                \
    (proc).unload = (unload_function);                               \
    (proc).execute = (execute_function);                             \
  } while (0)

/* The entry point, looked up by this name once per context and library. */
#define NSI_PROCEDURAL_LOAD_SYMBOL NSIProceduralLoad
typedef struct NSIProcedural_t *(*NSIProceduralLoad_t)(
    NSI_PROCEDURAL_LOAD_PARAMS);

#ifdef __cplusplus
#define NSI_PROCEDURAL_LINKAGE extern "C"
#else
#define NSI_PROCEDURAL_LINKAGE
#endif
#if defined(_WIN32)
#define NSI_PROCEDURAL_EXPORT __declspec(dllexport)
#else
#define NSI_PROCEDURAL_EXPORT __attribute__((visibility("default")))
#endif

/* Defines the entry point: NSI_PROCEDURAL_LOAD { ... return &proc; } */
#define NSI_PROCEDURAL_LOAD                                             \
  NSI_PROCEDURAL_LINKAGE NSI_PROCEDURAL_EXPORT struct NSIProcedural_t * \
  NSI_PROCEDURAL_LOAD_SYMBOL(NSI_PROCEDURAL_LOAD_PARAMS)

#ifdef __cplusplus
}
#endif

#endif /* NSI_PROCEDURAL_H */
