// The camera presets and the rig that follows a run (viz/camera.hpp): what each preset looks
// along, the contact preset's target, and a followed subject that never leaves the view and glides.
#include <gtest/gtest.h>

#include <cmath>

#include "viz/camera.hpp"

namespace firn::viz {
namespace {

Bounds box(Vec3 lo, Vec3 hi) {
  Bounds b;
  b.add(lo), b.add(hi);
  return b;
}

RenderSettings settings(CameraPreset preset, bool follow = true) {
  RenderSettings s;
  s.camera = preset;
  s.camera_follow = follow;
  return s;
}

// Every corner of `b` lies inside the camera's view (within the narrower half field of view).
bool sees(const Camera& c, const Bounds& b) {
  const Vec3 forward = normalize(c.target - c.eye);
  const double narrow = std::min(c.fov, 2 * std::atan(std::tan(c.fov / 2) * c.aspect));
  for (int k = 0; k < 8; ++k) {
    const Vec3 p = {k & 1 ? b.hi[0] : b.lo[0], k & 2 ? b.hi[1] : b.lo[1], k & 4 ? b.hi[2] : b.lo[2]};
    const Vec3 to = p - c.eye;
    if (std::acos(std::clamp(dot(normalize(to), forward), -1.0, 1.0)) > narrow / 2) return false;
  }
  return true;
}

TEST(Camera, PresetsLookAlongTheirAxes) {
  const Bounds b = box({-1, 0, -1}, {1, 1, 1});
  const Vec3 top = normalize(frame_camera(settings(CameraPreset::top), b).eye - Vec3{0, 0.5, 0});
  EXPECT_NEAR(top[1], 1, 1e-12);
  const Camera side = frame_camera(settings(CameraPreset::side), b);
  EXPECT_NEAR(side.eye[0], 0, 1e-12);
  EXPECT_GT(side.eye[2], 1);
  const Camera three = frame_camera(settings(CameraPreset::three_quarter), b);
  EXPECT_GT(three.eye[0], 1);
  EXPECT_GT(three.eye[1], 1);
  EXPECT_GT(three.eye[2], 1);
  for (CameraPreset p : {CameraPreset::automatic, CameraPreset::side, CameraPreset::three_quarter, CameraPreset::top})
    EXPECT_TRUE(sees(frame_camera(settings(p), b), b)) << int(p);
  EXPECT_THROW(parse_camera_preset("front"), std::invalid_argument);
  EXPECT_EQ(parse_camera_preset("three_quarter"), CameraPreset::three_quarter);
}

TEST(Camera, ContactLooksAtTheFocusLowestPointFromItsFrontQuarter) {
  CameraRig rig(settings(CameraPreset::contact));
  FrameSubject f;
  f.subject = box({-2, 0, -1}, {2, 1, 1});
  f.focus = box({0.5, 0.2, -0.1}, {0.9, 0.6, 0.1});  // a tire of radius 0.2 over (0.7, 0.2, 0)
  const Camera c = rig.next(f);
  EXPECT_NEAR(c.target[0], 0.7, 1e-12);
  EXPECT_NEAR(c.target[1], 0.24, 1e-12);  // a tenth of the focus's height above its lowest point
  EXPECT_NEAR(c.target[2], 0, 1e-12);
  EXPECT_GT(c.eye[0], c.target[0]);
  EXPECT_LT(c.eye[1] - c.target[1], c.eye[0] - c.target[0]);  // low
  EXPECT_LT(length(c.eye - c.target), 1.5);                   // close: the focus, not the subject
}

TEST(Camera, FollowedSubjectNeverLeavesTheViewAndTheViewGlides) {
  CameraRig rig(settings(CameraPreset::three_quarter));
  FrameSubject f;
  double previous_distance = 0;
  // A clump thrown from the origin along +x at 1 m per frame, then the view settles on a small box.
  for (int frame = 0; frame < 12; ++frame) {
    f.subject = frame < 6 ? box({0, 0, 0}, {0.2 + frame, 0.2, 0.2}) : box({0, 0, 0}, {0.2, 0.2, 0.2});
    const Camera c = rig.next(f);
    EXPECT_TRUE(sees(c, f.subject)) << frame;
    const double distance = length(c.eye - c.target);
    if (frame >= 7) {
      EXPECT_GT(distance, 0.5 * previous_distance) << frame;  // the view narrows a third of the way a frame
    }
    previous_distance = distance;
  }
  const Camera settled = frame_camera(settings(CameraPreset::three_quarter), f.subject);
  EXPECT_GT(previous_distance, length(settled.eye - settled.target));  // still gliding in after 6 frames
}

TEST(Camera, WithoutFollowTheFirstFrameCameraStays) {
  CameraRig rig(settings(CameraPreset::automatic, false));
  FrameSubject f;
  f.subject = box({0, 0, 0}, {1, 1, 1});
  const Camera first = rig.next(f);
  f.subject = box({5, 0, 0}, {9, 1, 1});
  const Camera later = rig.next(f);
  EXPECT_EQ(first.eye, later.eye);
  EXPECT_EQ(first.target, later.target);
}

}  // namespace
}  // namespace firn::viz
