// A tiny scene builder over the C API for tests with known answers: one
// device, helpers to make geometry from std::vectors, and a render call
// that returns the color and depth channels as floats.
#pragma once

#include "../api/DeviceTestSupport.h"

#include <anari/frontend/type_utility.h>

#include <cstring>
#include <vector>

struct RenderedImage
{
  uint32_t width{0}, height{0};
  std::vector<float> color; // RGBA per pixel, row 0 at the bottom
  std::vector<float> depth;
  std::vector<uint32_t> primitiveId, objectId, instanceId;

  const float *pixel(uint32_t x, uint32_t y) const
  {
    return &color[4 * (size_t(y) * width + x)];
  }
  float depthAt(uint32_t x, uint32_t y) const
  {
    return depth[size_t(y) * width + x];
  }
};

class AnalyticTest : public PrismDeviceTest
{
 protected:
  // A managed array of `values` read as elements of `type` (a vector of
  // floats becomes FLOAT32_VEC3 elements three at a time).
  template <typename T>
  ANARIArray1D array1D(const std::vector<T> &values, ANARIDataType type)
  {
    const size_t count = values.size() * sizeof(T) / anari::sizeOf(type);
    ANARIArray1D array =
        anariNewArray1D(m_device, nullptr, nullptr, nullptr, type, count);
    std::memcpy(anariMapArray(m_device, array),
        values.data(),
        values.size() * sizeof(T));
    anariUnmapArray(m_device, array);
    return array;
  }
  void setArray(ANARIObject object, const char *name, ANARIArray1D array)
  {
    anariSetParameter(m_device, object, name, ANARI_ARRAY1D, &array);
    anariRelease(m_device, array);
  }
  // A quad light (not committed) at `position` spanning `edge1` and
  // `edge2` (it emits towards edge2 x edge1, spec 5.7.4), its `brightness`
  // ("intensity" or "radiance") `value`.
  ANARILight quadLight(const float position[3],
      const float edge1[3],
      const float edge2[3],
      const char *brightness,
      float value)
  {
    ANARILight light = anariNewLight(m_device, "quad");
    anariSetParameter(
        m_device, light, "position", ANARI_FLOAT32_VEC3, position);
    anariSetParameter(m_device, light, "edge1", ANARI_FLOAT32_VEC3, edge1);
    anariSetParameter(m_device, light, "edge2", ANARI_FLOAT32_VEC3, edge2);
    anariSetParameter(m_device, light, brightness, ANARI_FLOAT32, &value);
    return light;
  }
  // Commits `light` and makes it the only light of `w` (released), then
  // commits `w`.
  void setOnlyLight(ANARIWorld w, ANARILight light)
  {
    anariCommitParameters(m_device, light);
    setArray(w,
        "light",
        anariNewArray1D(m_device, &light, nullptr, nullptr, ANARI_LIGHT, 1));
    anariRelease(m_device, light);
    anariCommitParameters(m_device, w);
  }
  ANARIGeometry geometry(const char *subtype,
      const std::vector<float> &positions /* xyz triples */)
  {
    ANARIGeometry g = anariNewGeometry(m_device, subtype);
    setArray(g, "vertex.position", array1D(positions, ANARI_FLOAT32_VEC3));
    return g;
  }
  ANARIMaterial matte(float r, float g, float b)
  {
    ANARIMaterial m = anariNewMaterial(m_device, "matte");
    const float color[3] = {r, g, b};
    anariSetParameter(m_device, m, "color", ANARI_FLOAT32_VEC3, color);
    anariCommitParameters(m_device, m);
    return m;
  }
  // A surface of the committed geometry with `material` (both released).
  ANARISurface surface(ANARIGeometry g, ANARIMaterial m, uint32_t id = ~0u)
  {
    anariCommitParameters(m_device, g);
    ANARISurface s = anariNewSurface(m_device);
    anariSetParameter(m_device, s, "geometry", ANARI_GEOMETRY, &g);
    anariSetParameter(m_device, s, "material", ANARI_MATERIAL, &m);
    if (id != ~0u)
      anariSetParameter(m_device, s, "id", ANARI_UINT32, &id);
    anariCommitParameters(m_device, s);
    anariRelease(m_device, g);
    anariRelease(m_device, m);
    return s;
  }
  ANARIWorld world(const std::vector<ANARISurface> &surfaces)
  {
    ANARIWorld w = anariNewWorld(m_device);
    if (!surfaces.empty()) {
      setArray(w,
          "surface",
          anariNewArray1D(m_device,
              surfaces.data(),
              nullptr,
              nullptr,
              ANARI_SURFACE,
              surfaces.size()));
    }
    for (ANARISurface s : surfaces)
      anariRelease(m_device, s);
    anariCommitParameters(m_device, w);
    return w;
  }
  // Gives `w` one instance, placing a group of `surface` (taken over) by
  // `transform` (column-major 4x4).
  void placeInstanced(
      ANARIWorld w, ANARISurface surface, const float *transform)
  {
    ANARIGroup group = anariNewGroup(m_device);
    setArray(group,
        "surface",
        anariNewArray1D(
            m_device, &surface, nullptr, nullptr, ANARI_SURFACE, 1));
    anariCommitParameters(m_device, group);
    anariRelease(m_device, surface);
    ANARIInstance instance = anariNewInstance(m_device, "transform");
    anariSetParameter(m_device, instance, "group", ANARI_GROUP, &group);
    anariSetParameter(
        m_device, instance, "transform", ANARI_FLOAT32_MAT4, transform);
    anariCommitParameters(m_device, instance);
    anariRelease(m_device, group);
    setArray(w,
        "instance",
        anariNewArray1D(
            m_device, &instance, nullptr, nullptr, ANARI_INSTANCE, 1));
    anariRelease(m_device, instance);
    anariCommitParameters(m_device, w);
  }
  // A box corner without lights: a grey floor, a green wall, a red ball
  // (bounces, shadows and occlusion once lit).
  ANARIWorld boxCorner()
  {
    return world({surface(geometry(
                              "quad", {-3, -3, 0, 3, -3, 0, 3, 3, 0, -3, 3, 0}),
                      matte(0.8f, 0.8f, 0.8f)),
        surface(geometry("quad", {-3, 1, 0, 3, 1, 0, 3, 1, 3, -3, 1, 3}),
            matte(0.2f, 0.7f, 0.3f)),
        surface(geometry("sphere", {0, 0, 0.5f}), matte(0.9f, 0.3f, 0.2f))});
  }
  ANARICamera perspective(const float eye[3], const float dir[3], float fovy)
  {
    ANARICamera c = anariNewCamera(m_device, "perspective");
    anariSetParameter(m_device, c, "position", ANARI_FLOAT32_VEC3, eye);
    anariSetParameter(m_device, c, "direction", ANARI_FLOAT32_VEC3, dir);
    anariSetParameter(m_device, c, "fovy", ANARI_FLOAT32, &fovy);
    anariCommitParameters(m_device, c);
    return c;
  }
  ANARICamera orthographic(const float eye[3], const float dir[3], float height)
  {
    ANARICamera c = anariNewCamera(m_device, "orthographic");
    anariSetParameter(m_device, c, "position", ANARI_FLOAT32_VEC3, eye);
    anariSetParameter(m_device, c, "direction", ANARI_FLOAT32_VEC3, dir);
    anariSetParameter(m_device, c, "height", ANARI_FLOAT32, &height);
    anariCommitParameters(m_device, c);
    return c;
  }
  ANARIRenderer renderer(const char *subtype)
  {
    ANARIRenderer r = anariNewRenderer(m_device, subtype);
    const float black[4] = {0, 0, 0, 1};
    anariSetParameter(m_device, r, "background", ANARI_FLOAT32_VEC4, black);
    anariCommitParameters(m_device, r);
    return r;
  }
  // A committed width x height frame of channel.color as RGBA floats,
  // accumulating or not.
  ANARIFrame colorFrame(ANARIWorld w,
      ANARICamera c,
      ANARIRenderer r,
      uint32_t width,
      uint32_t height,
      bool accumulation = true)
  {
    ANARIFrame f = anariNewFrame(m_device);
    const uint32_t extent[2] = {width, height};
    const ANARIDataType color = ANARI_FLOAT32_VEC4;
    const uint8_t on = accumulation ? 1 : 0;
    anariSetParameter(m_device, f, "world", ANARI_WORLD, &w);
    anariSetParameter(m_device, f, "camera", ANARI_CAMERA, &c);
    anariSetParameter(m_device, f, "renderer", ANARI_RENDERER, &r);
    anariSetParameter(m_device, f, "size", ANARI_UINT32_VEC2, extent);
    anariSetParameter(m_device, f, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(m_device, f, "accumulation", ANARI_BOOL, &on);
    anariCommitParameters(m_device, f);
    return f;
  }
  // channel.color of `f` (RGBA floats, row 0 at the bottom; empty when
  // not rendered), once its render in flight is done.
  std::vector<float> mappedColor(ANARIFrame f)
  {
    anariFrameReady(m_device, f, ANARI_WAIT);
    uint32_t width = 0, height = 0;
    ANARIDataType type;
    auto *p = (const float *)anariMapFrame(
        m_device, f, "channel.color", &width, &height, &type);
    std::vector<float> out;
    if (p)
      out.assign(p, p + 4 * size_t(width) * height);
    anariUnmapFrame(m_device, f, "channel.color");
    return out;
  }
  // channel.color after `frames` accumulated frames of a size x size
  // image (releases nothing it was given).
  std::vector<float> accumulatedColor(
      ANARIWorld w, ANARICamera c, ANARIRenderer r, uint32_t size, int frames)
  {
    ANARIFrame f = colorFrame(w, c, r, size, size);
    for (int i = 0; i < frames; i++)
      anariRenderFrame(m_device, f);
    std::vector<float> out = mappedColor(f);
    anariRelease(m_device, f);
    return out;
  }
  // Renders and returns every channel (releases nothing it was given).
  RenderedImage render(ANARIWorld w,
      ANARICamera c,
      ANARIRenderer r,
      uint32_t width,
      uint32_t height)
  {
    ANARIFrame f = anariNewFrame(m_device);
    const uint32_t size[2] = {width, height};
    const ANARIDataType color = ANARI_FLOAT32_VEC4, depth = ANARI_FLOAT32,
                        id = ANARI_UINT32;
    anariSetParameter(m_device, f, "world", ANARI_WORLD, &w);
    anariSetParameter(m_device, f, "camera", ANARI_CAMERA, &c);
    anariSetParameter(m_device, f, "renderer", ANARI_RENDERER, &r);
    anariSetParameter(m_device, f, "size", ANARI_UINT32_VEC2, size);
    anariSetParameter(m_device, f, "channel.color", ANARI_DATA_TYPE, &color);
    anariSetParameter(m_device, f, "channel.depth", ANARI_DATA_TYPE, &depth);
    anariSetParameter(m_device, f, "channel.primitiveId", ANARI_DATA_TYPE, &id);
    anariSetParameter(m_device, f, "channel.objectId", ANARI_DATA_TYPE, &id);
    anariSetParameter(m_device, f, "channel.instanceId", ANARI_DATA_TYPE, &id);
    anariCommitParameters(m_device, f);
    anariRenderFrame(m_device, f);
    anariFrameReady(m_device, f, ANARI_WAIT);
    RenderedImage image;
    image.width = width;
    image.height = height;
    auto read = [&](const char *channel, auto &out, size_t components) {
      uint32_t w2, h2;
      ANARIDataType type;
      const void *p = anariMapFrame(m_device, f, channel, &w2, &h2, &type);
      using T = typename std::decay_t<decltype(out)>::value_type;
      if (p)
        out.assign((const T *)p, (const T *)p + size_t(w2) * h2 * components);
      anariUnmapFrame(m_device, f, channel);
    };
    read("channel.color", image.color, 4);
    read("channel.depth", image.depth, 1);
    read("channel.primitiveId", image.primitiveId, 1);
    read("channel.objectId", image.objectId, 1);
    read("channel.instanceId", image.instanceId, 1);
    anariRelease(m_device, f);
    return image;
  }
};
