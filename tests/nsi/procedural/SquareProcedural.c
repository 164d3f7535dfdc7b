/* A dynamic-library procedural for the tests: each execution makes a 2 x 2
 * square mesh 10 units down -Z, named by the "handle" parameter (default
 * "square") and moved by the "x" parameter, hung under .root. It reports
 * loading, executing and unloading at NSIErrInfo. Built three times: as is,
 * without its entry point (SQUARE_NO_ENTRY) and claiming a newer NSI
 * (SQUARE_BAD_VERSION). */
#include <nsi_procedural.h>

#include <string.h>

static NSI_PROCEDURAL_UNLOAD(squareUnload)
{
  (void)proc;
  report(ctx, NSIErrInfo, "square procedural: unloaded");
}

static NSI_PROCEDURAL_EXECUTE(squareExecute)
{
  const char *handle = "square";
  float x = 0;
  int i;
  (void)proc;
  for (i = 0; i < nparams; ++i) {
    if (strcmp(params[i].name, "handle") == 0
        && params[i].type == NSITypeString)
      handle = *(const char *const *)params[i].data;
    else if (strcmp(params[i].name, "x") == 0 && params[i].type == NSITypeFloat)
      x = *(const float *)params[i].data;
  }
  {
    const int nvertices = 4;
    const float P[12] = {
        x - 1, -1, -10, x + 1, -1, -10, x + 1, 1, -10, x - 1, 1, -10};
    struct NSIParam_t mesh[2] = {
        {"nvertices", &nvertices, NSITypeInteger, 0, 1, 0},
        {"P", P, NSITypePoint, 0, 4, 0}};
    NSICreate(ctx, handle, "mesh", 0, NULL);
    NSISetAttribute(ctx, handle, 2, mesh);
    NSIConnect(ctx, handle, "", NSI_SCENE_ROOT, "objects", 0, NULL);
  }
  report(ctx, NSIErrInfo, "square procedural: executed");
}

#ifndef SQUARE_NO_ENTRY
NSI_PROCEDURAL_LOAD
{
  static struct NSIProcedural_t proc;
  (void)nsi_library_path;
  (void)renderer_version;
  NSI_PROCEDURAL_INIT(proc, squareUnload, squareExecute);
#ifdef SQUARE_BAD_VERSION
  proc.nsi_version = NSI_VERSION + 1;
#endif
  report(ctx, NSIErrInfo, "square procedural: loaded");
  return &proc;
}
#endif
