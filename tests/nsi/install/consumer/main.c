/* Begins a context through the installed libnsi, makes a node and refuses
   a connection loop through its error handler: headers, linking and the
   run-time path work from the install tree. */
#include <nsi.h>

#include <stdio.h>

static int g_errors = 0;

static void onError(void *data, int level, int code, const char *message)
{
  (void)data, (void)code, (void)message;
  if (level == NSIErrError)
    ++g_errors;
}

int main(void)
{
  NSIErrorHandler_t handler = onError;
  NSIParam_t param = {"errorhandler", &handler, NSITypePointer, 0, 1, 0};
  NSIContext_t ctx = NSIBegin(1, &param);
  if (ctx == NSI_BAD_CONTEXT) {
    printf("unexpected: no context\n");
    return 1;
  }
  NSICreate(ctx, "t", "transform", 0, NULL);
  NSIConnect(ctx, "t", "", "t", "objects", 0, NULL);
  NSIEnd(ctx);
  if (g_errors != 1) {
    printf("unexpected: %d errors for one loop\n", g_errors);
    return 1;
  }
  printf("nsi consumer ok\n");
  return 0;
}
