#include "viz/frame_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "viz/color_field.hpp"
#include "viz/dual_contour.hpp"
#include "viz/legend.hpp"

namespace firn::viz {
namespace {

constexpr int kColliderMeshCells = 64;  // along the longest side of a collider's box
// Along the longest side of a body meshed in its own frame: 2 mm on the thesis' 40 cm tire, where
// the mesh takes about 2 s once (viz/dual_contour.hpp).
constexpr int kBodyMeshCells = 200;
const Rgb kSnowAlbedo = {0.9f, 0.95f, 1.0f};  // the thesis' snow albedo, as the snow shader uses it

template <class T>
void add_positions(const PositionColumns& p, Bounds& b) {
  const T* x[3] = {static_cast<const T*>(p.x[0]), static_cast<const T*>(p.x[1]), static_cast<const T*>(p.x[2])};
  for (std::size_t i = 0; i < p.count; ++i) b.add({double(x[0][i]), double(x[1][i]), double(x[2][i])});
}

// The box of the positions without the `leave_out` lowest and highest along each axis.
template <class T>
Bounds trimmed_bounds(const PositionColumns& p, std::size_t leave_out) {
  Bounds b;
  std::vector<T> v;
  for (std::size_t d = 0; d < 3; ++d) {
    const T* x = static_cast<const T*>(p.x[d]);
    v.assign(x, x + p.count);
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(leave_out), v.end());
    b.lo[d] = double(v[leave_out]);
    std::nth_element(v.begin(), v.end() - 1 - std::ptrdiff_t(leave_out), v.end());
    b.hi[d] = double(v[p.count - 1 - leave_out]);
  }
  return b;
}

// What the camera frames (viz/camera.hpp): the particles, all but the few most extreme along each
// axis (one stray particle does not widen the view; a thrown clump does), and the colliders that
// are bounded, cut to the domain; the first of them is the focus.
FrameSubject frame_subject(const RenderFrame& frame, const RenderSettings& s) {
  FrameSubject f;
  const PositionColumns& p = frame.positions;
  constexpr std::size_t kStray = 8;
  if (p.count > 100 * kStray) f.subject = p.doubles ? trimmed_bounds<double>(p, kStray) : trimmed_bounds<float>(p, kStray);
  else f.subject = position_bounds(p);
  for (const ColliderSolid& c : frame.colliders) {
    Bounds b;
    for (std::size_t d = 0; d < 3; ++d) b.lo[d] = std::max(c.lo[d], s.domain_min[d]), b.hi[d] = std::min(c.hi[d], s.domain_max[d]);
    const bool bounded = std::isfinite(c.lo[0] + c.lo[1] + c.lo[2] + c.hi[0] + c.hi[1] + c.hi[2]);
    if (!bounded || !(b.lo[0] < b.hi[0] && b.lo[1] < b.hi[1] && b.lo[2] < b.hi[2])) continue;
    f.subject.add_box(b);
    if (!f.focus) f.focus = b;
  }
  const std::vector<ColliderSolid>* colliders = &frame.colliders;
  f.solid = [colliders](const Vec3& x) {
    Vec3 n;
    for (const ColliderSolid& c : *colliders)
      if (c.distance(x, n) < 0) return true;
    return false;
  };
  return f;
}

// A mesh made in a body's frame, at the body's pose.
TriangleMesh posed(const TriangleMesh& m, const ColliderSolid::Body& b) {
  TriangleMesh out;
  out.vertices.resize(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); v += 6) {
    const Vec3 x = b.to_world({m.vertices[v], m.vertices[v + 1], m.vertices[v + 2]});
    const Vec3 n = b.rotate({m.vertices[v + 3], m.vertices[v + 4], m.vertices[v + 5]});
    for (std::size_t k = 0; k < 3; ++k) out.vertices[v + k] = float(x[k]), out.vertices[v + 3 + k] = float(n[k]);
  }
  return out;
}

// The mesh in its collider's material (viz/frame_renderer.hpp).
ColliderMesh collider_mesh(const ColliderSolid& c, TriangleMesh mesh) {
  ColliderMesh m;
  m.mesh = std::move(mesh);
  if (c.shape == ColliderShape::tire) m.color = {0.25f, 0.25f, 0.26f}, m.gloss = 0.3f;  // albedo 0.06 (stored as its root)
  if (c.shape == ColliderShape::plane) m.color = {0.30f, 0.30f, 0.31f};
  return m;
}

std::string time_caption(double t) {
  char buf[64];
  if (t < 1) std::snprintf(buf, sizeof buf, "t = %.3f ms", t * 1e3);
  else std::snprintf(buf, sizeof buf, "t = %.4f s", t);
  return buf;
}

}  // namespace

Bounds position_bounds(const PositionColumns& p) {
  Bounds b;
  if (p.doubles) add_positions<double>(p, b);
  else add_positions<float>(p, b);
  return b;
}

FramePipeline::FramePipeline(const RenderSettings& settings, GlApi api, const FrameOutputs& outputs)
    : settings_(settings),
      context_(make_gl_context(api)),
      renderer_(std::make_unique<FrameRenderer>(*context_, settings)),
      camera_rig_(settings) {
  std::unique_ptr<FfmpegPipe> video;
  if (!outputs.video_path.empty())
    video = std::make_unique<FfmpegPipe>(outputs.video_path, settings.width, settings.height, outputs.fps);
  writer_ = std::make_unique<FrameWriter>(outputs.png_dir, std::move(video));
}

FramePipeline::~FramePipeline() = default;

void FramePipeline::add(const RenderFrame& frame) {
  const RenderSettings& s = settings_;
  const Camera camera = camera_rig_.next(frame_subject(frame, s));

  FrameScene scene;
  scene.positions = frame.positions;
  for (const MaterialSpan& m : frame.materials)
    scene.ranges.push_back({m.begin, m.end, s.material_colors.at(std::size_t(m.material))});
  Legend legend;
  if (frame.surface) {
    // The snow surface stands for the particles, in the snow material (viz/shaders.cpp).
    scene.positions.count = 0;
    scene.snow = frame.surface;
    legend.title = "surface";
    legend.names = {"snow"};
    legend.colors = {kSnowAlbedo};
  } else if (frame.field) {
    const auto [lo, hi] = std::minmax_element(frame.field, frame.field + frame.positions.count);
    if (frame.positions.count > 0) {
      field_min_ = field_seen_ ? std::min(field_min_, double(*lo)) : *lo;
      field_max_ = field_seen_ ? std::max(field_max_, double(*hi)) : *hi;
      field_seen_ = true;
    }
    double a = s.color_min.value_or(field_min_), b = s.color_max.value_or(field_max_);
    if (s.color_map == ColorMap::diverging && !s.color_min && !s.color_max) {
      // Symmetric about the field's neutral value: 1 for J, 0 otherwise.
      const double centre = s.color_by == "J" ? 1 : 0, reach = std::max(std::abs(a - centre), std::abs(b - centre));
      a = centre - reach, b = centre + reach;
    }
    if (!(b > a)) b = a + std::max(1e-12, std::abs(a) * 1e-6);
    scene.scalar = frame.field;
    scene.scalar_min = a, scene.scalar_max = b;
    legend.title = color_field_title(s.color_by);
    legend.map = s.color_map;
    legend.min = a, legend.max = b;
  } else {
    legend.title = "material";
    legend.names = s.material_names;
    legend.colors = s.material_colors;
  }
  // Colliders as solids. One inside the domain is meshed once in its own frame with sharp edges
  // and moved to its pose every frame; any other is cut to the domain and meshed over its own box
  // within the domain (so a small collider gets fine cells), enlarged by two cells so the cut faces
  // close.
  body_meshes_.resize(frame.colliders.size());
  for (std::size_t i = 0; i < frame.colliders.size(); ++i) {
    const ColliderSolid& c = frame.colliders[i];
    bool inside = c.body.has_value();
    for (std::size_t d = 0; d < 3; ++d) inside = inside && c.lo[d] >= s.domain_min[d] && c.hi[d] <= s.domain_max[d];
    if (inside) {
      if (!body_meshes_[i]) {
        const ColliderSolid::Body& b = *c.body;
        const double h = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]}) / kBodyMeshCells;
        const Vec3 margin = {2 * h, 2 * h, 2 * h};
        body_meshes_[i] = dual_contour(b.distance, b.lo - margin, b.hi + margin, h);
      }
      scene.colliders.push_back(collider_mesh(c, posed(*body_meshes_[i], *c.body)));
      continue;
    }
    Vec3 lo, hi;
    for (std::size_t d = 0; d < 3; ++d) lo[d] = std::max(c.lo[d], s.domain_min[d]), hi[d] = std::min(c.hi[d], s.domain_max[d]);
    if (!(lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2])) continue;  // outside the domain
    const Vec3 margin = (2.0 / kColliderMeshCells) * (hi - lo);
    scene.colliders.push_back(collider_mesh(c, mesh_signed_distance(clip_to_box(c.distance, s.domain_min, s.domain_max), lo - margin,
                                                   hi + margin, kColliderMeshCells)));
  }

  Image image = renderer_->render(scene, camera);
  if (s.legend) {
    legend.caption = time_caption(frame.time);
    draw_legend(image, legend);
  }
  writer_->push(frame.frame, std::move(image));
}

void FramePipeline::finish() { writer_->finish(); }

}  // namespace firn::viz
