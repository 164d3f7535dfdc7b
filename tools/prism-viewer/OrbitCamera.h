// The viewer's camera as the user moves it: orbit about a pivot around the
// up axis, pan, zoom (dolly towards the pivot), fly (WASD, moving eye and
// target together), field of view and depth of field. Pure math, no device:
// the session copies the pose to the ANARI camera when it changes.
#pragma once

#include "CameraFraming.h"
#include "Scene.h"

namespace prism::viewer {

using scenes::Vec3;

struct CameraPose
{
  Vec3 eye{0.f, 0.f, 1.f};
  Vec3 at{0.f, 0.f, 0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float fovyDegrees{45.f};
  bool orthographic{false};
  float height{1.f};         // orthographic view height
  float apertureRadius{0.f}; // 0: pinhole
  float focusDistance{1.f};  // along the view direction
};

class OrbitCamera
{
 public:
  // Starts from a framed (or the file's) view; the pivot is `pivot`, the
  // scene's centre.
  void reset(const scene_io::CameraSetup &setup, const Vec3 &pivot);

  // Turns eye and target about the pivot: `yawDegrees` around the up axis
  // (positive: the eye moves to its right), `pitchDegrees` around the
  // view's right axis, stopping short of the poles.
  void orbit(float yawDegrees, float pitchDegrees);
  // Moves eye and target along the view's right and up axes by fractions
  // of the view's height at the target's distance.
  void pan(float right, float up);
  // Moves the eye towards the target: its distance times `factor` (< 1:
  // closer), never through the target.
  void zoom(float factor);
  // Moves eye and target together: `forward`, `right`, `upward` in world
  // units.
  void fly(float forward, float right, float upward);
  // Turns the view direction about the eye (fly mode looking around).
  void look(float yawDegrees, float pitchDegrees);

  void setFovy(float degrees);
  // Depth of field: focus at the distance of `point` along the view.
  void focusOn(const Vec3 &point);
  void setAperture(float radius);

  // Takes a pose as it is (the MPI mirror's followers).
  void setPose(const CameraPose &pose)
  {
    m_pose = pose;
  }
  const CameraPose &pose() const
  {
    return m_pose;
  }
  const Vec3 &pivot() const
  {
    return m_pivot;
  }
  // Distance from eye to target.
  float distance() const;

 private:
  CameraPose m_pose;
  Vec3 m_pivot{0.f, 0.f, 0.f};
};

// `v` turned by `degrees` about the unit `axis` (right-handed).
Vec3 rotateAbout(const Vec3 &v, const Vec3 &axis, float degrees);

} // namespace prism::viewer
