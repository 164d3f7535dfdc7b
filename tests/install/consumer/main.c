/* Loads a library that does not exist: proves headers, linking and the
   run-time path work from the install tree, and that failure is reported. */
#include <anari/anari.h>
#include <stdio.h>

static int g_reported = 0;

static void onStatus(const void *user,
    ANARIDevice device,
    ANARIObject source,
    ANARIDataType type,
    ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *message)
{
  (void)user, (void)device, (void)source, (void)type, (void)message;
  if (severity == ANARI_SEVERITY_ERROR
      && code == ANARI_STATUS_INVALID_OPERATION)
    g_reported = 1;
}

int main(void)
{
  ANARILibrary library = anariLoadLibrary("notinstalled", onStatus, NULL);
  if (library != NULL || !g_reported) {
    printf("unexpected: library %p, reported %d\n", library, g_reported);
    return 1;
  }
  printf("consumer ok\n");
  return 0;
}
