// fuzz_api_seeds DIR: writes fuzz_api's seed corpus, one meaningful program
// per file: scenes of every geometry, material, sampler, light, camera,
// instance and renderer subtype, then each corruption the fuzzer knows on a
// valid scene (wrong types, stale/foreign/NULL handles, cycles, extreme
// values, maps and releases in odd orders, several devices).
#include "ApiProgram.h"

#include <cstdio>
#include <string>
#include <vector>

using namespace prism::fuzz;

namespace {

using Bytes = std::vector<uint8_t>;

// NewArray's sharing operand.
constexpr uint8_t kManaged = 0, kSharedWithDeleter = 1, kBorrowed = 2;

// Subtype counts and orders as the device introspects them (BuildScene picks
// subtypes by index; a changed list only changes which scenes the seeds make).
constexpr int kGeometrySubtypes = 6; // cone curve cylinder quad sphere triangle
constexpr int kMaterialSubtypes = 2; // matte physicallyBased
constexpr int kLightSubtypes = 6;    // directional hdri point quad ring spot
constexpr int kCameraSubtypes = 3;
constexpr int kRendererSubtypes = 5;

Bytes floats(std::initializer_list<float> values)
{
  Bytes out;
  for (float v : values)
    out.push_back(floatSelector(v));
  return out;
}

Bytes operator+(Bytes a, const Bytes &b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// A program and a mirror of the interpreter's object pool, so operands can
// name objects by pool index and handle selectors pick the intended object.
class Seed
{
 public:
  explicit Seed(uint8_t flags = 0) : m_writer(flags) {}

  struct Object
  {
    ANARIDataType type;
    int device;
    bool live;
  };

  // NewObject of a named subtype ("" for types without subtypes).
  int object(ANARIDataType type, const std::string &subtype, int device = 0)
  {
    Bytes p = {uint8_t(device), uint8_t(indexOf(kCategories, type)), 0, 0};
    ProgramWriter::appendName(p, subtype);
    m_writer.op(Op::NewObject, p);
    return add(type, device);
  }
  int unknownObject(ANARIDataType type)
  {
    // Subtype index 255 is past the end of every subtype list.
    Bytes p = {0, uint8_t(indexOf(kCategories, type)), 255, 1, 0};
    m_writer.op(Op::NewObject, p);
    return add(type, 0);
  }
  // NewArray; `values` are selectors (floats(...), handles, integers).
  int array(ANARIDataType elementType,
      uint64_t n1,
      uint64_t n2 = 0,
      uint64_t n3 = 0,
      const Bytes &values = {},
      uint8_t sharing = kManaged,
      int device = 0)
  {
    const int dimensions = n3 ? 3 : n2 ? 2 : 1;
    Bytes p = {uint8_t(device),
        uint8_t(dimensions - 1),
        uint8_t(indexOf(kElementTypes, elementType)),
        uint8_t(n1),
        uint8_t(n2),
        uint8_t(n3),
        sharing};
    m_writer.op(Op::NewArray, p + values);
    const ANARIDataType type = dimensions == 1   ? ANARI_ARRAY1D
                               : dimensions == 2 ? ANARI_ARRAY2D
                                                 : ANARI_ARRAY3D;
    if (n1 == 0 || (dimensions > 1 && n2 == 0) || (dimensions > 2 && n3 == 0)
        || indexOf(kElementTypes, elementType) >= kElementTypeCount - 2)
      return add(type, device, false);
    return add(type, device);
  }
  // An array of n elements of the type element type selector `selector`
  // picks (kAnyElementType and up: every plain data type).
  int arrayOf(uint8_t selector, uint64_t n)
  {
    m_writer.op(Op::NewArray, {0, 0, selector, uint8_t(n), 0, 0, kManaged});
    return add(ANARI_ARRAY1D, 0);
  }
  // An object array of `elements` (pool indices).
  int objects(ANARIDataType elementType, const std::vector<int> &elements)
  {
    Bytes handles;
    for (int e : elements)
      handles.push_back(handle(e));
    return array(elementType, elements.size(), 0, 0, handles);
  }

  // The selector that makes the interpreter pick pool object `index` among
  // the live objects of its type (and device).
  uint8_t handle(int index) const
  {
    int position = 0;
    for (int i = 0; i < index; i++) {
      const Object &o = m_pool[i];
      if (o.live && o.type == m_pool[index].type
          && o.device == m_pool[index].device)
        position++;
    }
    return uint8_t(position);
  }
  // An existing array as a parameter value (selectors 100..199 pick one).
  uint8_t arrayHandle(int index) const
  {
    int matches = 0, position = 0;
    for (int i = 0; i < int(m_pool.size()); i++) {
      const Object &o = m_pool[i];
      if (o.live && o.type == m_pool[index].type
          && o.device == m_pool[index].device) {
        if (i < index)
          position++;
        matches++;
      }
    }
    for (int s = 100; s < 200; s++) {
      if (s % matches == position)
        return uint8_t(s);
    }
    return 100;
  }

  void set(int object,
      const std::string &name,
      ANARIDataType type,
      const Bytes &values,
      Twist twist = Twist::None)
  {
    Bytes p = {
        uint8_t(object), uint8_t(indexOf(kAnyTypes, type)), uint8_t(twist)};
    ProgramWriter::appendName(p, name);
    m_writer.op(Op::SetNamedParameter, p + values);
  }
  void setObject(int object, const std::string &name, int value)
  {
    const ANARIDataType type = m_pool[value].type;
    const bool isArray =
        int(type) >= ANARI_ARRAY1D && int(type) <= ANARI_ARRAY3D;
    set(object, name, type, {isArray ? arrayHandle(value) : handle(value)});
  }
  // A fresh array value: the interpreter makes it from the accepted element
  // types of the parameter (element type index, sizes, shared, values).
  void setFresh(int object,
      const std::string &name,
      ANARIDataType arrayType,
      const Bytes &layout,
      const Bytes &values = {})
  {
    set(object, name, arrayType, Bytes{0} + layout + values);
    add(arrayType, m_pool[object].device);
  }
  void setFloat(int object, const std::string &name, float v)
  {
    set(object, name, ANARI_FLOAT32, floats({v}));
  }
  void setVec3(int object, const std::string &name, float x, float y, float z)
  {
    set(object, name, ANARI_FLOAT32_VEC3, floats({x, y, z}));
  }
  void setString(int object, const std::string &name, uint8_t choice)
  {
    set(object, name, ANARI_STRING, {choice});
  }
  void setInt(int object, const std::string &name, uint8_t value)
  {
    set(object, name, ANARI_INT32, {value});
  }
  void setBool(int object, const std::string &name, bool value)
  {
    set(object, name, ANARI_BOOL, {uint8_t(value)});
  }
  void commit(int object)
  {
    m_writer.op(Op::CommitParameters, {uint8_t(object)});
  }
  void release(int object)
  {
    m_writer.op(Op::Release, {uint8_t(object)});
    m_pool[object].live = false;
  }
  void retain(int object)
  {
    m_writer.op(Op::Retain, {uint8_t(object)});
  }
  void op(Op op, const Bytes &payload)
  {
    m_writer.op(op, payload);
  }

  // A whole scene (BuildScene); returns the index of its first object.
  int scene(int geometry,
      int material,
      int light,
      int camera,
      int renderer,
      uint8_t flags,
      int device = 0)
  {
    m_writer.op(Op::BuildScene,
        {uint8_t(device),
            uint8_t(geometry),
            uint8_t(material),
            uint8_t(light),
            uint8_t(camera),
            uint8_t(renderer),
            flags});
    const int first = int(m_pool.size());
    static const ANARIDataType kTypes[kSceneObjects] = {ANARI_ARRAY1D,
        ANARI_GEOMETRY,
        ANARI_ARRAY2D,
        ANARI_SAMPLER,
        ANARI_MATERIAL,
        ANARI_SURFACE,
        ANARI_ARRAY1D,
        ANARI_GROUP,
        ANARI_INSTANCE,
        ANARI_ARRAY1D,
        ANARI_LIGHT,
        ANARI_ARRAY1D,
        ANARI_WORLD,
        ANARI_CAMERA,
        ANARI_RENDERER,
        ANARI_FRAME};
    for (ANARIDataType t : kTypes)
      add(t, device);
    return first;
  }
  // Pool indices of BuildScene's objects, relative to its first.
  enum SceneObject {
    kPositions = 0,
    kGeometry = 1,
    kImage = 2,
    kSampler = 3,
    kMaterial = 4,
    kSurface = 5,
    kSurfaces = 6,
    kGroup = 7,
    kInstance = 8,
    kInstances = 9,
    kLight = 10,
    kLights = 11,
    kWorld = 12,
    kCamera = 13,
    kRenderer = 14,
    kFrame = 15
  };

  // Renders frame `frame` (a pool index among frames: see frameOperand).
  void render(int frameOrdinal, uint8_t wait = 3)
  {
    m_writer.op(Op::RenderFrame, {uint8_t(frameOrdinal), wait});
  }
  int newDevice()
  {
    m_writer.op(Op::NewDevice, {});
    return m_devices++;
  }
  int add(ANARIDataType type, int device, bool live = true)
  {
    m_pool.push_back({type, device, live});
    return int(m_pool.size()) - 1;
  }
  const Bytes &bytes() const
  {
    return m_writer.bytes();
  }

 private:
  ProgramWriter m_writer;
  std::vector<Object> m_pool;
  int m_devices = 1;
};

// A triangle, quad or other geometry made by hand (not BuildScene), with its
// own arrays, in a world with a light, and rendered with `renderer`.
struct Manual
{
  Seed s;
  int geometry = -1, material = -1, surface = -1, world = -1, camera = -1,
      renderer = -1, frame = -1;

  explicit Manual(const std::string &geometryType, uint8_t flags = 0) : s(flags)
  {
    geometry = s.object(ANARI_GEOMETRY, geometryType);
  }
  // Material, surface, world with a point light, camera, renderer, frame.
  void finish(const std::string &materialType = "matte",
      const std::string &rendererType = "default",
      int light = -1)
  {
    s.commit(geometry);
    if (material < 0) {
      material = s.object(ANARI_MATERIAL, materialType);
      s.commit(material);
    }
    surface = s.object(ANARI_SURFACE, "");
    s.setObject(surface, "geometry", geometry);
    s.setObject(surface, "material", material);
    s.commit(surface);
    const int surfaces = s.objects(ANARI_SURFACE, {surface});
    world = s.object(ANARI_WORLD, "");
    s.setObject(world, "surface", surfaces);
    if (light < 0) {
      light = s.object(ANARI_LIGHT, "point");
      s.setVec3(light, "position", 0, 3, 5);
      s.setFloat(light, "intensity", 4);
      s.commit(light);
    }
    const int lights = s.objects(ANARI_LIGHT, {light});
    s.setObject(world, "light", lights);
    s.commit(world);
    camera = s.object(ANARI_CAMERA, "perspective");
    s.setVec3(camera, "position", 0, 0, 3);
    s.commit(camera);
    renderer = s.object(ANARI_RENDERER, rendererType);
    s.commit(renderer);
    frame = s.object(ANARI_FRAME, "");
    s.setObject(frame, "world", world);
    s.setObject(frame, "camera", camera);
    s.setObject(frame, "renderer", renderer);
    s.set(frame, "size", ANARI_UINT32_VEC2, {8, 6});
    // channel.color: FLOAT32_VEC4 is value 2 of its accepted list.
    s.set(frame, "channel.color", ANARI_DATA_TYPE, {2});
    s.set(frame, "channel.depth", ANARI_DATA_TYPE, {0});
    s.commit(frame);
  }
};

const Bytes kQuadPoints = floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});

struct Corpus
{
  std::string directory;
  int written = 0;

  void write(const std::string &name, const Bytes &bytes)
  {
    const std::string path = directory + "/seed-" + name;
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) {
      std::fprintf(stderr, "fuzz_api_seeds: cannot write %s\n", path.c_str());
      std::exit(1);
    }
    std::fclose(f);
    written++;
  }
};

void writeScenes(Corpus &corpus)
{
  // Every geometry subtype through BuildScene, with varied materials,
  // lights, cameras and renderers, direct and instanced, sampled colors.
  for (int g = 0; g < kGeometrySubtypes; g++) {
    for (int variant = 0; variant < 2; variant++) {
      Seed s;
      const uint8_t flags =
          uint8_t(kSceneRender | (variant ? kSceneInstanced | kSceneSampler : 0)
                  | (g % 3 == 2 ? kSceneAccumulate : 0));
      const int first = s.scene(g,
          (g + variant) % kMaterialSubtypes,
          (g + 3 * variant) % kLightSubtypes,
          (g + variant) % kCameraSubtypes,
          (g + 2 * variant) % kRendererSubtypes,
          flags);
      s.render(0, 3);
      s.op(Op::GetProperty, {uint8_t(first + Seed::kWorld), 0, 0, 1, 0});
      corpus.write(
          "scene-geometry" + std::to_string(g) + "-" + std::to_string(variant),
          s.bytes());
    }
  }
  for (int l = 0; l < kLightSubtypes; l++) {
    Seed s;
    s.scene(l % kGeometrySubtypes, 1, l, 0, 1, kSceneRender | kSceneInstanced);
    corpus.write("scene-light" + std::to_string(l), s.bytes());
  }
  for (int r = 0; r < kRendererSubtypes; r++) {
    Seed s;
    s.scene(5, r % 2, 2, r % kCameraSubtypes, r, kSceneRender | kSceneSampler);
    corpus.write("scene-renderer" + std::to_string(r), s.bytes());
  }
}

void writeGeometries(Corpus &corpus)
{
  {
    // Indexed triangles with normals, colors and face-varying attributes.
    Manual m("triangle");
    const int position = m.s.array(ANARI_FLOAT32_VEC3, 4, 0, 0, kQuadPoints);
    const int index = m.s.array(ANARI_UINT32_VEC3, 2, 0, 0, {0, 1, 2, 0, 2, 3});
    const int normal = m.s.array(ANARI_FLOAT32_VEC3,
        4,
        0,
        0,
        floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}));
    m.s.setObject(m.geometry, "vertex.position", position);
    m.s.setObject(m.geometry, "primitive.index", index);
    m.s.setObject(m.geometry, "vertex.normal", normal);
    m.s.setFresh(m.geometry, "vertex.color", ANARI_ARRAY1D, {3, 4, 0, 0, 0});
    m.s.setFresh(
        m.geometry, "faceVarying.attribute0", ANARI_ARRAY1D, {0, 6, 0, 0, 1});
    m.finish("physicallyBased", "raycast");
    m.s.render(0);
    m.s.op(Op::MapFrame, {0, 1});
    corpus.write("geometry-triangle-indexed", m.s.bytes());
  }
  {
    Manual m("quad");
    const int position =
        m.s.array(ANARI_FLOAT32_VEC3, 4, 0, 0, kQuadPoints, kSharedWithDeleter);
    m.s.setObject(m.geometry, "vertex.position", position);
    m.s.setFresh(m.geometry,
        "primitive.index",
        ANARI_ARRAY1D,
        {0, 0, 0, 0, 0},
        {0, 1, 2, 3});
    m.s.setFresh(
        m.geometry, "faceVarying.normal", ANARI_ARRAY1D, {0, 3, 0, 0, 0});
    m.finish("matte", "pathtracer");
    m.s.render(0);
    corpus.write("geometry-quad", m.s.bytes());
  }
  {
    Manual m("sphere");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 5, 0, 0, 1});
    m.s.setFresh(m.geometry,
        "vertex.radius",
        ANARI_ARRAY1D,
        {0, 5, 0, 0, 0},
        floats({0.5, 0.25, 1, 0.125, 2, 0.5}));
    m.s.setFresh(m.geometry,
        "primitive.index",
        ANARI_ARRAY1D,
        {0, 2, 0, 0, 0},
        {0, 4, 2});
    m.finish("matte", "ao");
    m.s.setInt(m.renderer, "aoSamples", 2);
    m.s.commit(m.renderer);
    m.s.render(0);
    corpus.write("geometry-sphere", m.s.bytes());
  }
  {
    Manual m("cone");
    m.s.setFresh(m.geometry,
        "vertex.position",
        ANARI_ARRAY1D,
        {0, 3, 0, 0, 0},
        floats({0, -1, 0, 0, 1, 0, 1, 1, 0, 2, 2, 0}));
    m.s.setFresh(m.geometry,
        "vertex.radius",
        ANARI_ARRAY1D,
        {0, 3, 0, 0, 0},
        floats({0.5, 0, 0.25, 0.5}));
    m.s.setFresh(
        m.geometry, "vertex.cap", ANARI_ARRAY1D, {0, 3, 0, 0, 0}, {1, 0, 1, 1});
    m.s.setString(m.geometry, "caps", 3);
    m.finish("physicallyBased", "debug");
    m.s.setString(m.renderer, "mode", 14);
    m.s.commit(m.renderer);
    m.s.render(0);
    corpus.write("geometry-cone", m.s.bytes());
  }
  {
    Manual m("cylinder");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 3, 0, 0, 0});
    m.s.setFresh(m.geometry,
        "primitive.radius",
        ANARI_ARRAY1D,
        {0, 1, 0, 0, 0},
        floats({0.25, 0.5}));
    m.s.setFloat(m.geometry, "radius", 0.3f);
    m.s.setString(m.geometry, "caps", 1);
    m.finish("matte", "raycast");
    m.s.render(0);
    corpus.write("geometry-cylinder", m.s.bytes());
  }
  {
    Manual m("curve");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 7, 0, 0, 0});
    m.s.setFresh(m.geometry, "vertex.radius", ANARI_ARRAY1D, {0, 7, 0, 0, 0});
    m.s.setFresh(m.geometry,
        "primitive.index",
        ANARI_ARRAY1D,
        {0, 3, 0, 0, 0},
        {0, 2, 4, 5});
    m.s.setFloat(m.geometry, "radius", 0.125f);
    m.finish("matte", "pathtracer");
    m.s.render(0);
    corpus.write("geometry-curve", m.s.bytes());
  }
  {
    // PRISM_GEOMETRY_POSITION_RADIUS: centres and radii in one shared
    // FLOAT32_VEC4 array, read in place.
    Manual m("sphere");
    m.s.setFresh(m.geometry,
        "vertex.positionRadius",
        ANARI_ARRAY1D,
        {0, 4, 0, 0, 1},
        floats({0, 0, 0, 0.5, 1, 0, 0, 0.25, 0, 1, 0, 0.75, -1, 0, 0, 0.5}));
    m.finish("matte", "raycast");
    m.s.render(0);
    corpus.write("geometry-sphere-packed", m.s.bytes());
  }
  {
    Manual m("curve");
    m.s.setFresh(
        m.geometry, "vertex.positionRadius", ANARI_ARRAY1D, {0, 6, 0, 0, 1});
    m.finish("matte", "pathtracer");
    m.s.render(0);
    corpus.write("geometry-curve-packed", m.s.bytes());
  }
  {
    // Motion-deformed triangles: an array of per-time-step vertex arrays.
    Manual m("triangle");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 5, 0, 0, 0});
    m.s.set(m.geometry,
        "motion.vertex.position",
        ANARI_ARRAY1D,
        Bytes{0, 0, 2, 0, 0, 0});
    // Two inner arrays then the outer one.
    m.s.add(ANARI_ARRAY1D, 0);
    m.s.add(ANARI_ARRAY1D, 0);
    m.s.add(ANARI_ARRAY1D, 0);
    m.s.set(m.geometry, "time", ANARI_FLOAT32_BOX1, floats({0, 1}));
    m.finish();
    m.s.render(0);
    corpus.write("geometry-triangle-motion", m.s.bytes());
  }
}

void writeMaterialsAndSamplers(Corpus &corpus)
{
  {
    // physicallyBased with every lobe and an emissive part (an emitter).
    Manual m("sphere");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 3, 0, 0, 0});
    m.s.setFloat(m.geometry, "radius", 0.75f);
    m.material = m.s.object(ANARI_MATERIAL, "physicallyBased");
    const int mat = m.material;
    m.s.setVec3(mat, "baseColor", 0.75f, 0.5f, 0.25f);
    m.s.setFloat(mat, "metallic", 0.5f);
    m.s.setFloat(mat, "roughness", 0.25f);
    m.s.setVec3(mat, "emissive", 1, 0.5f, 0);
    m.s.setFloat(mat, "clearcoat", 1);
    m.s.setFloat(mat, "clearcoatRoughness", 0.125f);
    m.s.setFloat(mat, "transmission", 0.5f);
    m.s.setFloat(mat, "ior", 1.5f);
    m.s.setFloat(mat, "thickness", 0.25f);
    m.s.setVec3(mat, "sheenColor", 1, 1, 1);
    m.s.setFloat(mat, "sheenRoughness", 0.5f);
    m.s.setFloat(mat, "iridescence", 1);
    m.s.setFloat(mat, "iridescenceThickness", 0.5f);
    m.s.setFloat(mat, "specular", 0.5f);
    m.s.setString(mat, "alphaMode", 2);
    m.s.setFloat(mat, "opacity", 0.5f);
    m.s.commit(mat);
    m.finish("physicallyBased", "pathtracer");
    m.s.setInt(m.renderer, "maxPathLength", 3);
    m.s.commit(m.renderer);
    m.s.render(0);
    corpus.write("material-physically-based", m.s.bytes());
  }
  {
    // Samplers of every kind feeding material inputs and attributes.
    Manual m("triangle");
    const int position = m.s.array(ANARI_FLOAT32_VEC3, 6, 0, 0);
    m.s.setObject(m.geometry, "vertex.position", position);
    m.s.setFresh(
        m.geometry, "vertex.attribute0", ANARI_ARRAY1D, {1, 5, 0, 0, 0});
    m.material = m.s.object(ANARI_MATERIAL, "physicallyBased");
    const int image1 = m.s.object(ANARI_SAMPLER, "image1D");
    m.s.setFresh(image1, "image", ANARI_ARRAY1D, {16, 7, 0, 0, 1});
    m.s.setString(image1, "filter", 1);
    m.s.setString(image1, "wrapMode", 2);
    m.s.commit(image1);
    const int image2 = m.s.object(ANARI_SAMPLER, "image2D");
    m.s.setFresh(image2, "image", ANARI_ARRAY2D, {3, 3, 2, 0, 0});
    m.s.setString(image2, "inAttribute", 5);
    m.s.setString(image2, "wrapMode1", 1);
    m.s.setString(image2, "wrapMode2", 2);
    m.s.set(image2,
        "inTransform",
        ANARI_FLOAT32_MAT4,
        floats({2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));
    m.s.commit(image2);
    const int image3 = m.s.object(ANARI_SAMPLER, "image3D");
    m.s.setFresh(image3, "image", ANARI_ARRAY3D, {19, 1, 2, 3, 0});
    m.s.setString(image3, "inAttribute", 1);
    m.s.commit(image3);
    const int primitive = m.s.object(ANARI_SAMPLER, "primitive");
    m.s.setFresh(primitive, "array", ANARI_ARRAY1D, {2, 2, 0, 0, 0});
    m.s.set(primitive, "inOffset", ANARI_UINT64, {1});
    m.s.commit(primitive);
    const int transform = m.s.object(ANARI_SAMPLER, "transform");
    m.s.setString(transform, "inAttribute", 2);
    m.s.commit(transform);
    m.s.setObject(m.material, "baseColor", image2);
    m.s.setObject(m.material, "roughness", image1);
    m.s.setObject(m.material, "metallic", image3);
    m.s.setObject(m.material, "emissive", primitive);
    m.s.setObject(m.material, "normal", transform);
    m.s.commit(m.material);
    m.finish("physicallyBased", "raycast");
    m.s.render(0);
    corpus.write("material-samplers", m.s.bytes());
  }
  {
    // matte colored by an attribute, masked by a sampled opacity.
    Manual m("quad");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 7, 0, 0, 0});
    m.s.setFresh(m.geometry, "vertex.color", ANARI_ARRAY1D, {17, 7, 0, 0, 0});
    m.material = m.s.object(ANARI_MATERIAL, "matte");
    m.s.setString(m.material, "color", 1);
    m.s.setString(m.material, "alphaMode", 1);
    m.s.setFloat(m.material, "alphaCutoff", 0.5f);
    m.s.commit(m.material);
    m.finish("matte", "default");
    m.s.render(0);
    corpus.write("material-matte-attributes", m.s.bytes());
  }
}

void writeLightsCamerasInstances(Corpus &corpus)
{
  {
    // An hdri from a 2D radiance array, plus a quad light with a
    // distribution, a ring and a spot light, all in one world.
    Seed s;
    const int first = s.scene(4, 0, 0, 0, 1, kSceneInstanced);
    const int hdri = s.object(ANARI_LIGHT, "hdri");
    s.setFresh(hdri, "radiance", ANARI_ARRAY2D, {0, 7, 3, 0, 0});
    s.setVec3(hdri, "up", 0, 1, 0);
    s.setFloat(hdri, "scale", 2);
    s.commit(hdri);
    const int quad = s.object(ANARI_LIGHT, "quad");
    s.setVec3(quad, "position", -1, 3, 0);
    s.setVec3(quad, "edge1", 2, 0, 0);
    s.setVec3(quad, "edge2", 0, 0, 2);
    s.setString(quad, "side", 2);
    s.setFresh(quad, "intensityDistribution", ANARI_ARRAY1D, {0, 7, 0, 0, 0});
    s.commit(quad);
    const int ring = s.object(ANARI_LIGHT, "ring");
    s.setFloat(ring, "radius", 1);
    s.setFloat(ring, "innerRadius", 0.5f);
    s.setFresh(ring, "intensityDistribution", ANARI_ARRAY2D, {0, 3, 3, 0, 0});
    s.commit(ring);
    const int spot = s.object(ANARI_LIGHT, "spot");
    s.setFloat(spot, "openingAngle", 1);
    s.setFloat(spot, "falloffAngle", 0.25f);
    s.commit(spot);
    const int lights = s.objects(ANARI_LIGHT, {hdri, quad, ring, spot});
    s.setObject(first + Seed::kWorld, "light", lights);
    s.commit(first + Seed::kWorld);
    s.render(0);
    corpus.write("lights-all", s.bytes());
  }
  {
    // Cameras: depth of field, stereo, orthographic, omnidirectional,
    // motion; then a rolling shutter.
    Seed s;
    const int first = s.scene(5, 0, 2, 0, 0, kSceneRender);
    const int camera = first + Seed::kCamera;
    s.setFloat(camera, "apertureRadius", 0.25f);
    s.setFloat(camera, "focusDistance", 4);
    s.setString(camera, "stereoMode", 3);
    s.setFloat(camera, "interpupillaryDistance", 0.5f);
    s.set(
        camera, "imageRegion", ANARI_FLOAT32_BOX2, floats({0.25, 0, 1, 0.75}));
    s.commit(camera);
    s.render(0);
    const int ortho = s.object(ANARI_CAMERA, "orthographic");
    s.setFloat(ortho, "height", 4);
    s.setFresh(ortho, "motion.transform", ANARI_ARRAY1D, {0, 1, 0, 0, 0});
    s.set(ortho, "time", ANARI_FLOAT32_BOX1, floats({0, 1}));
    s.commit(ortho);
    s.setObject(first + Seed::kFrame, "camera", ortho);
    s.commit(first + Seed::kFrame);
    s.render(0);
    const int omni = s.object(ANARI_CAMERA, "omnidirectional");
    s.setString(omni, "rollingShutterDirection", 2);
    s.setFloat(omni, "rollingShutterDuration", 0.5f);
    s.commit(omni);
    s.setObject(first + Seed::kFrame, "camera", omni);
    s.commit(first + Seed::kFrame);
    s.render(0);
    corpus.write("cameras", s.bytes());
  }
  {
    // Instances: a transform, an array of transforms with ids, motion.
    Seed s;
    const int first = s.scene(4, 1, 2, 0, 1, kSceneInstanced);
    const int instance = first + Seed::kInstance;
    s.set(instance,
        "transform",
        ANARI_FLOAT32_MAT4,
        floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0.5, 0, 1}));
    s.commit(instance);
    s.render(0);
    const int many = s.object(ANARI_INSTANCE, "transform");
    s.setObject(many, "group", first + Seed::kGroup);
    s.setFresh(many, "transform", ANARI_ARRAY1D, {0, 3, 0, 0, 0});
    s.setFresh(many, "id", ANARI_ARRAY1D, {0, 3, 0, 0, 0});
    s.commit(many);
    const int moving =
        s.object(ANARI_INSTANCE, "motionScaleRotationTranslation");
    s.setObject(moving, "group", first + Seed::kGroup);
    s.setFresh(moving, "motion.translation", ANARI_ARRAY1D, {0, 2, 0, 0, 0});
    s.setFresh(moving, "motion.rotation", ANARI_ARRAY1D, {0, 2, 0, 0, 0});
    s.commit(moving);
    const int matrix = s.object(ANARI_INSTANCE, "motionTransform");
    s.setObject(matrix, "group", first + Seed::kGroup);
    s.setFresh(matrix, "motion.transform", ANARI_ARRAY1D, {0, 2, 0, 0, 0});
    s.commit(matrix);
    const int instances =
        s.objects(ANARI_INSTANCE, {instance, many, moving, matrix});
    s.setObject(first + Seed::kWorld, "instance", instances);
    s.commit(first + Seed::kWorld);
    // Every frame channel.
    const int frame = first + Seed::kFrame;
    for (const char *channel : {"channel.normal",
             "channel.albedo",
             "channel.primitiveId",
             "channel.objectId",
             "channel.instanceId"})
      s.set(frame, channel, ANARI_DATA_TYPE, {0});
    s.set(
        frame, "frameCompletionCallback", ANARI_FRAME_COMPLETION_CALLBACK, {});
    s.set(frame, "frameCompletionCallbackUserData", ANARI_VOID_POINTER, {0});
    s.commit(frame);
    s.render(0);
    for (uint8_t c = 0; c < 9; c++)
      s.op(Op::MapFrame, {0, c});
    s.op(Op::GetProperty, {uint8_t(frame), 1, 0, 1, 0});
    corpus.write("instances-channels", s.bytes());
  }
  {
    // Renderer parameters: background image, ambient light, denoising.
    Seed s;
    const int first = s.scene(0, 1, 1, 0, 1, 0);
    const int renderer = first + Seed::kRenderer;
    s.setFresh(renderer, "background", ANARI_ARRAY2D, {3, 4, 4, 0, 0});
    s.setVec3(renderer, "ambientColor", 1, 1, 0.5f);
    s.setFloat(renderer, "ambientRadiance", 0.5f);
    s.setBool(renderer, "denoise", true);
    s.setInt(renderer, "maxPathLength", 2);
    s.commit(renderer);
    s.render(0);
    s.set(first + Seed::kFrame, "accumulation", ANARI_BOOL, {1});
    s.commit(first + Seed::kFrame);
    s.render(0, 0);
    s.render(0, 1);
    s.render(0, 3);
    corpus.write("renderer-parameters", s.bytes());
  }
}

void writeCorruptions(Corpus &corpus)
{
  // Each SetParameter twist on a rendered scene's objects.
  for (uint8_t t = 1; t < uint8_t(Twist::Count); t++) {
    Seed s;
    const int first = s.scene(t % kGeometrySubtypes,
        t % 2,
        t % 6,
        0,
        1,
        kSceneRender | kSceneInstanced);
    const int other = s.newDevice();
    s.object(ANARI_GEOMETRY, "sphere", other);
    s.release(first + Seed::kSampler);
    for (int object : {first + Seed::kGeometry,
             first + Seed::kSurface,
             first + Seed::kInstance,
             first + Seed::kWorld,
             first + Seed::kCamera,
             first + Seed::kLight,
             first + Seed::kFrame}) {
      for (uint8_t parameter = 0; parameter < 6; parameter++) {
        s.op(Op::SetParameter,
            {uint8_t(object), parameter, t, 200, 201, 195, 194});
      }
      s.commit(object);
    }
    s.render(0);
    corpus.write("twist" + std::to_string(t), s.bytes());
  }
  {
    // Extreme values: 1e30 in an instance transform, NaN camera, -0 and
    // denormal radii, an absurd frame size.
    Seed s;
    const int first = s.scene(4, 0, 2, 0, 1, kSceneInstanced);
    s.set(first + Seed::kInstance,
        "transform",
        ANARI_FLOAT32_MAT4,
        {16, 0, 0, 0, 0, 16, 0, 0, 0, 0, 16, 0, 192, 0, 0, 16},
        Twist::Extreme);
    s.commit(first + Seed::kInstance);
    s.render(0);
    s.set(first + Seed::kCamera,
        "direction",
        ANARI_FLOAT32_VEC3,
        {194, 0, 197},
        Twist::Extreme);
    s.commit(first + Seed::kCamera);
    s.render(0);
    s.set(first + Seed::kGeometry,
        "radius",
        ANARI_FLOAT32,
        {198},
        Twist::Extreme);
    s.commit(first + Seed::kGeometry);
    s.render(0);
    s.set(first + Seed::kFrame,
        "size",
        ANARI_UINT32_VEC2,
        {0, 0},
        Twist::Extreme);
    s.commit(first + Seed::kFrame);
    s.render(0);
    corpus.write("extreme-values", s.bytes());
  }
  // Reference cycles of each kind, released or left to the device.
  for (uint8_t kind = 0; kind < uint8_t(Cycle::Count); kind++) {
    for (uint8_t flags : {uint8_t(0), uint8_t(kLeaveObjectsToDevice)}) {
      Seed s(flags);
      const int first = s.scene(kind, 0, 0, 0, 1, kSceneRender);
      s.op(Op::MakeCycle, {kind, uint8_t(first + Seed::kGeometry)});
      s.render(0);
      corpus.write(
          "cycle" + std::to_string(kind) + (flags ? "-left" : ""), s.bytes());
    }
  }
  {
    // Object arrays remapped after their objects were released, while a
    // world uses them; shared arrays released while in use.
    Seed s;
    const int first = s.scene(5, 0, 2, 0, 1, kSceneRender);
    s.release(first + Seed::kSurface);
    s.release(first + Seed::kPositions);
    s.render(0);
    const int extra = s.object(ANARI_SURFACE, "");
    s.setObject(extra, "geometry", first + Seed::kGeometry);
    s.setObject(extra, "material", first + Seed::kMaterial);
    s.commit(extra);
    s.op(Op::MapArray, {uint8_t(first + Seed::kSurfaces), 0, s.handle(extra)});
    s.render(0);
    s.release(extra);
    s.op(Op::MapArray, {uint8_t(first + Seed::kSurfaces), 0, kHandleStale});
    s.render(0);
    s.op(Op::MapArray, {uint8_t(first + Seed::kSurfaces), 1, kHandleNull});
    s.render(0);
    s.op(Op::UnmapArray, {uint8_t(first + Seed::kSurfaces)});
    s.render(0);
    corpus.write("remap-object-arrays", s.bytes());
  }
  {
    // The SDK's pattern: shared arrays without a deleter, released and their
    // memory freed before rendering; others with a deleter, released while
    // in use; then remapped after release.
    Manual m("triangle");
    const int position =
        m.s.array(ANARI_FLOAT32_VEC3, 4, 0, 0, kQuadPoints, kBorrowed);
    const int index =
        m.s.array(ANARI_UINT32_VEC3, 2, 0, 0, {0, 1, 2, 0, 2, 3}, kBorrowed);
    const int color = m.s.array(ANARI_FLOAT32_VEC4,
        4,
        0,
        0,
        floats({1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1}),
        kSharedWithDeleter);
    m.s.setObject(m.geometry, "vertex.position", position);
    m.s.setObject(m.geometry, "primitive.index", index);
    m.s.setObject(m.geometry, "vertex.color", color);
    m.s.release(position);
    m.s.release(index);
    m.s.release(color);
    m.finish("matte", "raycast");
    m.s.render(0);
    m.s.op(Op::MapArray, {uint8_t(position), 0, 16, 16, 16});
    m.s.render(0);
    corpus.write("shared-arrays-released", m.s.bytes());
  }
  {
    // Release everything in the middle of a frame; render, map, discard in
    // odd orders; a frame released without waiting.
    Seed s(kNoFinalWait);
    const int first = s.scene(1, 1, 3, 1, 1, 0);
    s.render(0, 0);
    for (int i = 0; i < Seed::kFrame; i++)
      s.release(first + i);
    s.op(Op::DiscardFrame, {0});
    s.op(Op::MapFrame, {0, 0});
    s.render(0, 0);
    s.op(Op::FrameReady, {0, 0});
    s.release(first + Seed::kFrame);
    s.render(0, 3);
    corpus.write("release-while-rendering", s.bytes());
  }
  {
    // Two devices: handles of one given to the other, the second released
    // with objects alive, a third made afterwards.
    Seed s;
    const int a = s.scene(4, 0, 2, 0, 1, kSceneRender);
    const int other = s.newDevice();
    const int b = s.scene(5, 1, 1, 1, 2, kSceneRender, other);
    s.op(Op::SetParameter,
        {uint8_t(b + Seed::kFrame), 1, uint8_t(Twist::ForeignHandle)});
    s.set(a + Seed::kSurface,
        "geometry",
        ANARI_GEOMETRY,
        {0},
        Twist::ForeignHandle);
    s.commit(a + Seed::kSurface);
    s.render(0);
    s.render(1);
    s.op(Op::ReleaseDevice, {uint8_t(other)});
    s.render(1);
    s.op(Op::ReleaseDevice, {uint8_t(other)});
    s.newDevice();
    s.render(0);
    corpus.write("devices", s.bytes());
  }
  {
    // Parameter arrays mapped, left mapped, remapped; maps of the wrong
    // element type; unmaps of names never mapped.
    Seed s;
    const int first = s.scene(5, 0, 2, 0, 1, kSceneRender);
    const int geometry = first + Seed::kGeometry;
    s.op(Op::MapParameterArray, {uint8_t(geometry), 0, 2, 0, 6, 0, 0, 0});
    s.op(Op::MapParameterArray, {uint8_t(geometry), 0, 2, 0, 6, 0, 0, 1});
    s.op(Op::MapParameterArray, {uint8_t(geometry), 0, 2, 0, 6, 0, 0, 0});
    s.op(Op::UnmapParameterArray, {uint8_t(geometry), 0});
    s.op(Op::UnmapParameterArray, {uint8_t(geometry), 0});
    s.op(Op::MapParameterArray,
        {uint8_t(first + Seed::kRenderer), 3, 3, 1, 3, 3, 0, 0});
    s.commit(geometry);
    s.commit(first + Seed::kRenderer);
    s.render(0);
    s.op(Op::MapParameterArray, {uint8_t(geometry), 255, 19, 0, 2, 0, 0, 1});
    corpus.write("parameter-arrays", s.bytes());
  }
  {
    // Unknown subtypes, wrong-typed handles, stale releases and retains,
    // slot reuse, introspection and property queries of every kind.
    Seed s(kLeaveObjectsToDevice);
    const int first = s.scene(0, 0, 0, 0, 0, 0);
    const int unknown = s.unknownObject(ANARI_GEOMETRY);
    s.commit(unknown);
    s.unknownObject(ANARI_RENDERER);
    s.retain(first + Seed::kWorld);
    s.release(first + Seed::kWorld);
    s.release(first + Seed::kWorld);
    s.release(first + Seed::kWorld);
    s.op(Op::Churn, {0, 40});
    s.op(Op::Churn, {10, 20});
    for (uint8_t c = 0; c < kCategoryCount; c++) {
      for (uint8_t info = 0; info < 6; info++)
        s.op(Op::Introspect, {0, c, 0, 0, info, 0});
      for (uint8_t info = 0; info < 9; info++)
        s.op(Op::Introspect, {0, c, 1, 130, info, 0});
    }
    s.op(Op::Introspect, {0, 240, 0, 200, 2, 200});
    for (uint8_t name = 0; name < 12; name++) {
      s.op(Op::GetProperty, {255, name, 0, 1, 0});
      s.op(Op::GetProperty, {uint8_t(first + Seed::kFrame), name, 0, 1, 0});
      s.op(Op::GetProperty, {uint8_t(first + Seed::kWorld), name, 0, 0, 2});
    }
    for (uint8_t which = 0; which < 5; which++)
      s.op(Op::SetDeviceParameter, {0, which});
    s.op(Op::SetDeviceParameter, {0, 0});
    s.render(0);
    corpus.write("misuse", s.bytes());
  }
  {
    // The library's entry points.
    Seed s;
    for (uint8_t which = 0; which < 5; which++) {
      for (uint8_t name = 0; name < 4; name++)
        s.op(Op::LibraryQuery, {which, 0, name});
    }
    corpus.write("library", s.bytes());
  }
  // Arrays of every plain data type as a geometry's colors (each converted,
  // or refused, at the next frame), in four seeds of 32 types.
  for (int part = 0; part < 4; part++) {
    Manual m("triangle");
    m.s.setFresh(m.geometry, "vertex.position", ANARI_ARRAY1D, {0, 6, 0, 0, 0});
    m.finish("matte", "raycast");
    for (int i = 0; i < 32; i++) {
      const int colors =
          m.s.arrayOf(uint8_t(kAnyElementType + part * 32 + i), 6);
      m.s.setObject(m.geometry, "vertex.color", colors);
      m.s.commit(m.geometry);
      if (i % 4 == 3)
        m.s.render(0, 1);
    }
    corpus.write("element-types" + std::to_string(part), m.s.bytes());
  }
  {
    // Arrays of every element type and shape, shared and managed, zero
    // sized, mapped twice and unmapped twice.
    Seed s;
    for (int t = 0; t < kElementTypeCount; t++)
      s.array(kElementTypes[t],
          1 + t % 5,
          t % 3 ? 2 : 0,
          t % 3 == 2 ? 2 : 0,
          {},
          uint8_t(t % 3));
    const int empty = s.array(ANARI_FLOAT32, 0);
    s.op(Op::MapArray, {0, 1});
    s.op(Op::MapArray, {0, 0});
    s.op(Op::UnmapArray, {0});
    s.op(Op::UnmapArray, {uint8_t(empty)});
    corpus.write("arrays", s.bytes());
  }
}

} // namespace

void writeThreads(Corpus &corpus)
{
  // Two threads rendering frames of one scene's world, camera and renderer
  // at once (SharedThreads), then again once the world was released.
  Seed s;
  const int first = s.scene(0, 0, 0, 0, 0, kSceneInstanced);
  const Bytes shared = {uint8_t(first + Seed::kWorld),
      uint8_t(first + Seed::kCamera),
      uint8_t(first + Seed::kRenderer)};
  Bytes threeFrames = shared, oneFrame = shared;
  threeFrames.push_back(2);
  oneFrame.push_back(0);
  s.op(Op::SharedThreads, threeFrames);
  s.release(first + Seed::kWorld);
  s.op(Op::SharedThreads, oneFrame);
  corpus.write("shared-threads", s.bytes());
}

int main(int argc, char **argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_api_seeds DIRECTORY\n");
    return 2;
  }
  Corpus corpus{argv[1]};
  writeScenes(corpus);
  writeGeometries(corpus);
  writeMaterialsAndSamplers(corpus);
  writeLightsCamerasInstances(corpus);
  writeCorruptions(corpus);
  writeThreads(corpus);
  std::printf(
      "fuzz_api_seeds: %d seeds written to %s\n", corpus.written, argv[1]);
  return 0;
}
