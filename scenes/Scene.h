// A built scene: the committed world plus what its builder knows about how to
// look at it. Demo scenes and the file loaders of prism-render return this.
#pragma once

#include <anari/anari.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace prism::scenes {

using Vec3 = std::array<float, 3>;
using Vec4 = std::array<float, 4>;

// A camera the scene suggests; positions in world space.
struct SuggestedCamera
{
  bool valid{false};
  Vec3 eye{0.f, 0.f, 1.f};
  Vec3 at{0.f, 0.f, 0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float fovyDegrees{45.f}; // perspective: vertical field of view
  bool orthographic{false};
  float height{1.f}; // orthographic: world-space height of the view
};

// An axis-aligned box in world space; empty (lower > upper) until extended.
struct Bounds
{
  Vec3 lower{std::numeric_limits<float>::infinity(),
      std::numeric_limits<float>::infinity(),
      std::numeric_limits<float>::infinity()};
  Vec3 upper{-std::numeric_limits<float>::infinity(),
      -std::numeric_limits<float>::infinity(),
      -std::numeric_limits<float>::infinity()};

  bool empty() const;
  void extend(const Vec3 &point);
  void extend(const Bounds &other);
};

// One surface of the scene as the viewer's panels need it: its handles
// (each retained by the scene, released by releaseScene), the subtypes their
// parameters are introspected by, and the `id` the objectId channel reports
// for it.
struct SceneSurface
{
  ANARISurface surface{nullptr};
  ANARIGeometry geometry{nullptr};
  std::string geometrySubtype;
  ANARIMaterial material{nullptr};
  std::string materialSubtype;
  uint32_t id{~0u};
};

// The subtype of one of the scene's `lights`.
struct SceneLight
{
  ANARILight light{nullptr};
  std::string subtype;
};

struct Scene
{
  // Committed; the caller owns this reference and releases it (with the
  // lights': releaseScene).
  ANARIWorld world{nullptr};
  std::string name;
  std::string description;
  SuggestedCamera camera;
  // World-space bounds as the builder computed them, for devices that do
  // not report the world's `bounds` property.
  Bounds bounds;
  // A sample of the surface's points in world space (file loaders:
  // scene_io/Outline.h), to frame a camera on the shape rather than its
  // box; empty: the bounds frame it.
  std::vector<Vec3> outline;
  // A background the scene looks right with; `hasBackground` false leaves
  // the renderer's default.
  bool hasBackground{false};
  Vec4 background{0.f, 0.f, 0.f, 1.f};
  // Whether the scene was made to be seen in a viewer's environment, as
  // glTF and OBJ files are (their emissive materials light nothing much),
  // or is lit as built (the demos).
  bool expectsEnvironment{false};
  // The world's own light objects (a glTF file's KHR_lights_punctual, a
  // demo's lamps), one reference each owned like `world`, so a tool can add
  // an environment to them (scene_io::addWorldLight).
  std::vector<ANARILight> lights;
  // What the builder made the world of (listSurface, listLight); the
  // surfaces inside instances are listed too, once each.
  std::vector<SceneSurface> surfaces;
  std::vector<SceneLight> lightSubtypes;
  // What the builder had to leave out on this device (e.g. lights), in
  // lower case without trailing period, for the application to report.
  std::vector<std::string> notes;
};

// Makes and commits a surface of `geometry` and `material` with user id
// `id`, and lists it in `surfaces` (retaining the three handles); the caller
// releases its own references as before. Every builder makes its surfaces
// through this, so the list is complete.
ANARISurface newListedSurface(ANARIDevice device,
    std::vector<SceneSurface> &surfaces,
    ANARIGeometry geometry,
    const std::string &geometrySubtype,
    ANARIMaterial material,
    const std::string &materialSubtype,
    uint32_t id);
// Records the subtype of `light`, one of the scene's lights.
void listLight(Scene &scene, ANARILight light, const std::string &subtype);
// The listed subtype of `light`; empty when not listed.
std::string lightSubtype(const Scene &scene, ANARILight light);

// Releases the references of the listed surfaces and clears the list (for
// tools that keep the world but have no use for the list).
void releaseListedSurfaces(ANARIDevice device, Scene &scene);

// Releases the scene's references (world, lights, listed surfaces) and
// clears them.
void releaseScene(ANARIDevice device, Scene &scene);

} // namespace prism::scenes
