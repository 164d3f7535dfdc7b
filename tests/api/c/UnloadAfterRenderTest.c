/* A program that does not use TBB itself renders with the prism device,
   releases everything, unloads the library and keeps running: TBB's worker
   threads, started by the frame, must not be left running code that was
   unmapped (the device library stays mapped: -z nodelete). */
#include <anari/anari.h>

#include <stdio.h>
#include <time.h>

static int renderOnce(ANARIDevice d)
{
  ANARIFrame f = anariNewFrame(d);
  ANARICamera c = anariNewCamera(d, "perspective");
  ANARIRenderer r = anariNewRenderer(d, "pathtracer");
  ANARIWorld w = anariNewWorld(d);
  unsigned size[2] = {64, 64};
  ANARIDataType t = ANARI_UFIXED8_RGBA_SRGB;
  uint32_t width = 0, height = 0;
  ANARIDataType type = ANARI_UNKNOWN;
  const void *pixels;
  anariCommitParameters(d, c);
  anariCommitParameters(d, r);
  anariCommitParameters(d, w);
  anariSetParameter(d, f, "size", ANARI_UINT32_VEC2, size);
  anariSetParameter(d, f, "channel.color", ANARI_DATA_TYPE, &t);
  anariSetParameter(d, f, "camera", ANARI_CAMERA, &c);
  anariSetParameter(d, f, "renderer", ANARI_RENDERER, &r);
  anariSetParameter(d, f, "world", ANARI_WORLD, &w);
  anariCommitParameters(d, f);
  anariRenderFrame(d, f);
  anariFrameReady(d, f, ANARI_WAIT);
  pixels = anariMapFrame(d, f, "channel.color", &width, &height, &type);
  anariUnmapFrame(d, f, "channel.color");
  anariRelease(d, w);
  anariRelease(d, r);
  anariRelease(d, c);
  anariRelease(d, f);
  return pixels != NULL && width == 64 && height == 64;
}

int main(void)
{
  int round, ok = 1;
  /* Twice: the library loads again after an unload. */
  for (round = 0; round < 2; round++) {
    ANARILibrary lib = anariLoadLibrary("prism", NULL, NULL);
    ANARIDevice d;
    if (!lib) {
      printf("cannot load prism\n");
      return 1;
    }
    d = anariNewDevice(lib, "default");
    ok &= renderOnce(d);
    anariRelease(d, d);
    anariUnloadLibrary(lib);
  }
  {
    /* Long enough for idle worker threads to wake and spin. */
    struct timespec pause = {0, 300000000};
    nanosleep(&pause, NULL);
  }
  printf(ok ? "rendered, unloaded, still running\n" : "a frame failed\n");
  return ok ? 0 : 1;
}
