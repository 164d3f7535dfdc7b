// ANARICamera: where rays start and where they go. Screen coordinates are
// in [0,1]^2 over the frame (lower left origin); stereo splits them into
// per-eye images, then imageRegion maps those onto the sensor (spec 5.2).
#pragma once

#include "../array/MovingObject.h"
#include "../math/MotionTransform.h"
#include "../math/Vec.h"

#include <limits>

namespace prism {

// A ray in world space; hits count for t in [tMin, tMax]. The direction is
// a unit vector, so t is the Euclidean distance from the origin.
struct Ray
{
  float3 origin;
  float3 direction;
  float tMin{0.f};
  float tMax{std::numeric_limits<float>::infinity()};
  // When the ray is traced, in the shutter's [0, 1] (motion blur);
  // secondary rays inherit their camera ray's time.
  float time{0.5f};
};

class Camera : public MovingObject
{
 public:
  Camera(DeviceState &device, const std::string &subtype);

  // The ray through `screen` ([0,1]^2 over the frame) and `lensSample`
  // (uniform in [0,1)^2, (0.5, 0.5) is the lens centre) at `time`, where
  // the camera is then (KHR_CAMERA_MOTION_TRANSFORMATION), for a frame of
  // `frameAspect` (width / height), which an unset 'aspect' follows.
  Ray generateRay(float2 screen,
      float2 lensSample,
      float time = 0.5f,
      float frameAspect = 1.f) const;
  // The ray through the lens centre (a pinhole camera).
  Ray generateRay(float2 screen) const
  {
    return generateRay(screen, {0.5f, 0.5f});
  }
  // [open, close] of the shutter within the frame's time span, in [0,1]
  // (KHR_CAMERA_SHUTTER).
  float2 shutter() const
  {
    return m_shutter;
  }
  // When the sensor at `screen` records, for `sample` uniform in [0, 1)
  // over its exposure (0.5: its middle): the whole shutter, or with
  // KHR_CAMERA_ROLLING_SHUTTER the rollingShutterDuration during which the
  // shutter passes that line.
  float rayTime(float2 screen, float sample) const;
  // Whether rays depend on the lens sample (KHR_CAMERA_DEPTH_OF_FIELD).
  // A simple pinhole (no stereo, no lens, no clipping) lets renderers build
  // primary rays in bulk: direction(x, y) = normalize(corner + x*dx + y*dy)
  // for screen (x, y) in [0,1]^2, all from `origin`, for a frame of
  // `frameAspect` (as generateRay()). False otherwise.
  struct Pinhole
  {
    float3 origin, corner, dx, dy;
  };
  virtual bool pinhole(Pinhole &, float /*frameAspect*/) const
  {
    return false;
  }

  bool hasDepthOfField() const
  {
    return m_apertureRadius > 0.f;
  }

 protected:
  enum class StereoMode { kNone, kLeft, kRight, kSideBySide, kTopBottom };
  // Which way the shutter rolls across the image ("down": top line first).
  enum class RollingShutter { kNone, kLeft, kRight, kDown, kUp };

  void commitParameters() override;
  // The ray through a point of the sensor for an eye displaced by
  // `eyeShift` (world units along the eye baseline, 0 without stereo), in
  // a frame of `frameAspect` (width / height).
  virtual Ray rayThroughSensor(float2 sensor,
      float eyeShift,
      float2 lensSample,
      float frameAspect) const = 0;

  // The thin-lens ray: a point of the disk of radius apertureRadius spanned
  // by lensU and lensV around `origin`, aimed at the pinhole ray's point at
  // distance `focusT`, so all lens samples agree there.
  Ray throughLens(float3 origin,
      float3 direction,
      float focusT,
      float3 lensU,
      float3 lensV,
      float2 lensSample) const;
  // Clip distances along the view direction turned into the ray's
  // [tMin, tMax] (they are farther along rays that leave at an angle).
  void clipAlongView(Ray &ray, float near, float far) const;
  // Reads and validates 'near' and 'far' (0 <= near < far).
  void readNearFar(float &near, float &far);
  // Reads 'aspect' (perspective, orthographic), which has no default (ANARI
  // 1.2): unset or invalid, the image follows the frame's width / height.
  void readAspect();
  // The width / height of one eye's image in a frame of `frameAspect`.
  float eyeAspect(float frameAspect) const
  {
    return (m_aspect > 0.f ? m_aspect : frameAspect) * m_eyeAspectScale;
  }
  // Whether the camera moves or is placed by motion.* keys; rays then need
  // generateRay() (no pinhole() fast path).
  bool hasMotion() const
  {
    return m_motion.isSet();
  }

  float3 m_position{0, 0, 0};
  float3 m_direction{0, 0, -1}; // normalised
  float3 m_up{0, 1, 0};         // orthonormal to m_direction
  float3 m_right{1, 0, 0};
  float2 m_regionLower{0, 0};
  float2 m_regionUpper{1, 1};
  float m_apertureRadius{0.f};
  float m_focusDistance{1.f};
  StereoMode m_stereoMode{StereoMode::kNone};
  float m_interpupillaryDistance{0.0635f};
  // An eye's image is this fraction of the frame's width/height ratio.
  float m_eyeAspectScale{1.f};
  // The given 'aspect'; 0 when the frame's ratio is used.
  float m_aspect{0.f};
  float2 m_shutter{0.5f, 0.5f};
  RollingShutter m_rollingShutter{RollingShutter::kNone};
  float m_rollingShutterDuration{0.f};
  // World from the camera frame above at each time (motion.* keys).
  MotionTransform m_motion;

 private:
  void readShutter();
};

} // namespace prism
