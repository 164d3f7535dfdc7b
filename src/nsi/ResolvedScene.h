// What the SceneResolver makes of a node graph: plain data in world terms,
// ready to become ANARI objects. No ANARI types here.
#pragma once

#include "CameraFraming.h"
#include "GlobalOptions.h"
#include "Matrix.h"
#include "ShaderTable.h"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace prism::nsi {

// Triangles (one vertex per face-vertex, so face-varying data needs no
// welding) or spheres, in object space.
struct GeometryData
{
  bool spheres{false};
  bool curves{false};  // round linear segments
  bool isPlane{false}; // an NSI plane's big square
  double planeHalfSize{0};
  std::vector<float> positions; // xyz
  // Triangles whose vertices move: `positions` and `normals` at times
  // uniform over the shutter (two or more keys, the first equal to
  // positions and normals; normalKeys empty when the normals stay).
  std::vector<std::vector<float>> positionKeys;
  std::vector<std::vector<float>> normalKeys;
  std::vector<float> normals;          // xyz per position, or empty
  std::vector<float> texcoords;        // st per position, or empty
  std::vector<float> colors;           // rgb per position, or empty
  std::vector<float> radii;            // spheres and curves, per position
  std::vector<uint32_t> segmentStarts; // curves
  std::vector<uint32_t> triangles;
  std::vector<uint32_t> triangleFaces; // the polygon each triangle is of

  bool operator==(const GeometryData &) const = default;
};

// One geometry with one resolved shader, placed once or more.
struct SurfaceItem
{
  std::string geometryHandle;
  std::string shaderHandle; // empty: the default material
  ShaderDescription shader;
  bool visibleToCamera{true};
  std::vector<Placement> worldFromObject;
};

// A `volume` node: one grid of a NanoVDB file, read when the ANARI objects
// are built (so a bad file is reported there), placed once or more.
struct VolumeItem
{
  std::string handle;
  std::string fileName;     // vdbfilename, expanded
  std::string densityGrid;  // empty: the file's first scalar grid
  std::string shaderHandle; // empty: no volume shader
  ShaderDescription shader; // its color and density
  std::vector<Placement> worldFromObject;

  bool operator==(const VolumeItem &) const = default;
};

struct LightItem
{
  enum class Kind { Quad, Point, Spot, Ring, Ambient, Directional, Hdri };
  Kind kind{Kind::Quad};
  ShaderDescription shader;
  std::array<float, 3> position{}, edge1{}, edge2{}, direction{0, 0, -1};
  float radius{0};
  float angularDiameter{0};
  float openingAngle{0}, falloffAngle{0}; // spot, radians
  bool visibleToCamera{true};

  bool operator==(const LightItem &) const = default;
};

struct OutputItem
{
  std::string layerHandle, variableName, driverName, fileName;
  bool withAlpha{false};
  bool halfFloat{false}; // scalarformat "half": EXR files in half floats
};

struct CameraItem
{
  std::string handle;
  bool orthographic{false};
  double fov{35.0};
  Matrix worldFromCamera{kIdentity}; // at shutter open
  // When the camera moves: world from camera at times uniform over the
  // shutter (two or more, the first worldFromCamera); else empty.
  Placement motion;
  double near{0}, far{INFINITY};              // clippingrange
  double apertureRadius{0}, focusDistance{1}; // depthoffield.*
  ScreenSettings screen;
  int oversampling{1};
  std::vector<OutputItem> outputs;
};

struct ResolvedScene
{
  // Some placement or geometry moves: its matrices or keys span the
  // shutter, which ANARI sees as the time range [0, 1].
  bool hasMotion{false};
  std::map<std::string, GeometryData> geometries; // by node handle
  std::vector<SurfaceItem> surfaces;
  std::vector<LightItem> lights;
  std::vector<VolumeItem> volumes;
  std::vector<CameraItem> cameras;
  GlobalOptions options;
};

} // namespace prism::nsi
