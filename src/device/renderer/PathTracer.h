// The `pathtracer` renderer (and `default`): unidirectional path tracing
// with next-event estimation and multiple importance sampling (power
// heuristic) for every light, emissive surfaces and the renderer's ambient
// light; lights chosen by power; Russian roulette after three bounces. One
// path per pixel per frame: with frame accumulation the image converges.
//
// It runs as a wavefront: a tile's paths advance bounce by bounce, each
// bounce's rays traced together as one queue (and the shadow rays as
// another) through a RayTransport, so the data-parallel device can trace
// the same queues across ranks.
#pragma once

#include "../material/MaterialShading.h"
#include "../shading/Bsdf.h"
#include "../shading/Sampling.h"
#include "Renderer.h"
#include "SurfaceHit.h"
#include "wavefront/BounceDecisions.h"
#include "wavefront/PathState.h"
#include "wavefront/RayTransport.h"
#include "wavefront/WorkspacePool.h"

#include <optional>
#include <vector>

namespace prism {

class PathTracer : public Renderer
{
 public:
  PathTracer(DeviceState &device, const std::string &subtype)
      : Renderer(device, subtype)
  {}

  // "raysTraced" (UINT64): camera, bounce and shadow rays traced since the
  // renderer was created, for benchmarks.
  bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask) override;

  uint32_t convergedSampleCount() const override
  {
    return 256;
  }
  // Every 2^k samples stratified (a centred first one would not be): on
  // the Cornell box 8 % less error at 128 samples per pixel.
  bool centresFirstSample() const override
  {
    return false;
  }
  bool tracesWavefronts() const override
  {
    return true;
  }

 protected:
  void commitParameters() override;
  // A tile's wavefront, traced through context.transport.
  void renderTile(const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers,
      const std::atomic<bool> &cancel) const override;

 private:
  class Wavefront;

  // What shading some rays of a bounce queues: continuing paths' next
  // rays, light samples' shadow rays and what each brings (contributions[k]
  // for shadow ray k, added if nothing blocks it), in ray order.
  struct BounceQueues
  {
    rt::RayQueue next, shadows;
    std::vector<ShadowContribution> contributions;

    void clear();
    // Appends `more`'s rays and contributions after these.
    void append(const BounceQueues &more);
  };
  // Shades the hits of `rays` into `out`: a tile's wavefront on this
  // thread, a larger one (a lockstep render's row of tiles) in tile-sized
  // blocks on the process's threads, each into one of `blocks`, appended
  // in ray order, so the queues are the same either way.
  void shadeBounce(const RenderContext &context,
      std::vector<PathState> &paths,
      const rt::RayQueue &rays,
      BounceDecisions &decisions,
      BounceQueues &out,
      std::vector<BounceQueues> &blocks) const;
  // Shades rays [begin, end) of `rays` into `out`. Each ray passes the
  // stages below in order; each stage reads and writes only the ray's
  // Bounce and path.
  void shadeRays(const RenderContext &context,
      std::vector<PathState> &paths,
      const rt::RayQueue &rays,
      size_t begin,
      size_t end,
      const BounceDecisions &decisions,
      BounceQueues &out) const;

  // One ray of a bounce as the stages see it.
  struct Bounce
  {
    PathState &path;
    uint32_t tag;    // the path's index, carried by its rays
    size_t rayIndex; // in the bounce's queue (and its BounceDecisions)
    Ray ray;
    float tMin{0.f};
    rt::Hit hit;
    // Where the ray passed a single-sided surface from behind (+inf: it
    // did not), see rt::RayQueue::passedOneSidedAt.
    float passedOneSided;
    bool found{false}; // a live surface was hit
    SurfaceHit &surface;
    // The material there: its own constant shading, or the hit's, shaded
    // into the caller's storage.
    const MaterialShading *shading{nullptr};
    const Bsdf *constantBsdf{nullptr}; // when the material's is constant
  };
  // Where the BSDF sits: its frame (normal maps applied), the BSDF (the
  // material's constant one, or the hit's in the caller's storage), the
  // direction towards the viewer, how far new rays start off and the side
  // the surface receives light on, for light sampling: the geometric
  // normal turned towards the viewer, or zero where light passes through
  // (transmission, a volume's boundary).
  struct Scattering
  {
    LocalFrame frame;
    const Bsdf &bsdf;
    float3 wo;
    float offset;
    float3 receiverNormal;
  };
  // Stages: what the ray hit and the material there; a collision in a
  // volume before it; light reached along
  // the ray (and the background or ambient light on a miss); stochastic
  // pass-through of see-through surfaces; the first hit's channels; the
  // surface's own emission; next-event estimation; BSDF sampling with
  // media changes; Russian roulette.
  Bounce resolveHit(const RenderContext &context,
      PathState &path,
      const rt::RayQueue &rays,
      size_t r,
      SurfaceHit &surface,
      MaterialShading &shading) const;
  // Delta tracking through the volumes before the hit: true when the path
  // ended in one (having added its emission).
  bool collidesInVolume(const RenderContext &context, Bounce &b) const;
  void emitAlongRay(const RenderContext &context, Bounce &b) const;
  bool passThrough(Bounce &b, rt::RayQueue &next) const;
  void recordFirstHit(Bounce &b) const;
  void emitFromSurface(const RenderContext &context, Bounce &b) const;
  Scattering scatteringAt(const Bounce &b, std::optional<Bsdf> &storage) const;
  // `last`: no BSDF sample follows (the path ends at this surface).
  void nextEvent(const RenderContext &context,
      const Bounce &b,
      const Scattering &scattering,
      const BounceDecisions &decisions,
      bool last,
      rt::RayQueue &shadows,
      std::vector<ShadowContribution> &contributions) const;
  void scatter(Bounce &b,
      const Scattering &scattering,
      const BounceDecisions &decisions,
      rt::RayQueue &next) const;
  // `u`: the bounce's roulette decision.
  bool survivesRoulette(PathState &path, float u) const;
  // Radiance arriving along a ray from lights it reaches within (tMin,
  // hitDistance), weighted against light sampling. A light beyond
  // `passedOneSided` (where the ray passed a single-sided surface from
  // behind) is one a shadow ray finds blocked there: light sampling says
  // it sends nothing, and so does this.
  float3 lightsAlong(const RenderContext &context,
      const float3 &origin,
      const float3 &direction,
      float tMin,
      float hitDistance,
      float passedOneSided,
      const PathState &path) const;

  // What a tile's wavefront works in, reused tile after tile.
  struct TileWorkspace
  {
    std::vector<PathState> paths;
    rt::RayQueue rays;
    BounceQueues queued;
    std::vector<BounceQueues> blocks; // shadeBounce's, reused
    std::vector<Ray> cameraRays;
    BounceDecisions decisions;
  };
  mutable WorkspacePool<TileWorkspace> m_workspaces;
  mutable std::atomic<uint64_t> m_raysTraced{0};
  // The multiple importance sampling weight of emission a ray found by
  // hitting a surface, against next-event estimation sampling it (0 when
  // the ray passed a single-sided surface from behind before it, as
  // lightsAlong()).
  float emissionWeight(const RenderContext &context,
      const PathState &path,
      const Bounce &b) const;

  int m_maxPathLength{8};
  bool m_volumeMajorantGrid{true};
  float3 m_ambient{0.f, 0.f, 0.f}; // ambientColor * ambientRadiance
};

} // namespace prism
