/* nsi.h from strict C99: the values clients compile in, the parameter
   layout, and a context begun and ended through the C calls alone. */
#include <nsi.h>

#include <stdio.h>
#include <string.h>

static int failures = 0;
#define CHECK(condition)                                               \
  do {                                                                 \
    if (!(condition)) {                                                \
      fprintf(stderr, "failed: %s (line %d)\n", #condition, __LINE__); \
      ++failures;                                                      \
    }                                                                  \
  } while (0)

static int errors = 0;
static void onError(void *data, int level, int code, const char *message)
{
  (void)data;
  (void)code;
  (void)message;
  if (level == NSIErrError)
    ++errors;
}

int main(void)
{
  NSIErrorHandler_t handler = onError;
  struct NSIParam_t param;
  NSIContext_t ctx;
  CHECK(NSI_VERSION == 2);
  CHECK(NSITypeDouble == 0x11 && NSITypeInt64 == 0x12
        && NSITypeDoubleMatrix == 0x18);
  CHECK(
      NSITypeSizeOf(NSITypeColor) == 12 && NSITypeSizeOf(NSITypeMatrix) == 64);
  CHECK(NSITypeSizeOf(NSITypeDoubleMatrix) == 128
        && NSITypeSizeOf(NSITypeHPoint) == 16);
  CHECK(
      NSITypeSizeOf(NSITypeString) == sizeof(char *) && NSITypeSizeOf(77) == 0);
  CHECK(sizeof(struct NSIParam_t) == 40);
  CHECK(NSIErrorMessage == NSIErrMessage && NSIRenderRestarted == 3);
  CHECK(strcmp(NSI_SCENE_ROOT, ".root") == 0
        && strcmp(NSI_ALL_NODES, ".all") == 0);

  param.name = "errorhandler";
  param.data = &handler;
  param.type = NSITypePointer;
  param.arraylength = 0;
  param.count = 1;
  param.flags = 0;
  ctx = NSIBegin(1, &param);
  CHECK(ctx != NSI_BAD_CONTEXT);
  NSICreate(ctx, "t", "transform", 0, NULL);
  NSIConnect(ctx, "t", "", "t", "objects", 0, NULL);
  CHECK(errors == 1);
  NSIEnd(ctx);
  if (failures == 0)
    printf("ok\n");
  return failures ? 1 : 0;
}
