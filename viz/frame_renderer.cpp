#include "viz/frame_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "viz/exposed_particles.hpp"
#include "viz/gl_program.hpp"
#include "viz/shaders.hpp"
#include "viz/surface/hoar_crystals.hpp"

namespace firn::viz {
namespace {

constexpr int kColorMapSize = 256;
constexpr double kGroundRadius = 8;  // the ground's half-width, in camera radii
enum TextureUnit { kAlbedoUnit, kNormalUnit, kDepthUnit, kShadowUnit, kOcclusionUnit, kColorMapUnit };

std::array<float, 3> to_float(const Vec3& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

// A full-screen pass's source with the settings' switches and the shared functions inserted
// after its #version line.
std::string screen_pass_source(const char* body, const RenderSettings& s) {
  std::string source = body;
  const std::string prelude = "#define SHADOWS " + std::to_string(int(s.shadows)) + "\n#define AMBIENT_OCCLUSION " +
                              std::to_string(int(s.ambient_occlusion)) + "\n#define SUBSURFACE " +
                              std::to_string(int(s.subsurface)) + "\n" + shaders::kScreenFunctions;
  return source.insert(source.find('\n') + 1, prelude);
}

}  // namespace

struct FrameRenderer::Resources {
  Resources(const Gl& gl, const RenderSettings& settings)
      : sphere(gl, "spheres", shaders::kSphereVertex, shaders::kSphereFragment),
        sphere_shadow(gl, "sphere shadows", shaders::kSphereVertex, shaders::kSphereShadowFragment),
        mesh(gl, "meshes", shaders::kMeshVertex, shaders::kMeshFragment),
        mesh_shadow(gl, "mesh shadows", shaders::kMeshVertex, shaders::kDepthOnlyFragment),
        snow(gl, "snow", shaders::kMeshVertex, shaders::kSnowFragment),
        occlusion(gl, "occlusion", shaders::kCompositeVertex, screen_pass_source(shaders::kOcclusionFragment, settings)),
        composite(gl, "composite", shaders::kCompositeVertex, screen_pass_source(shaders::kCompositeFragment, settings)) {}
  GlProgram sphere, sphere_shadow, mesh, mesh_shadow, snow, occlusion, composite;
  GLuint vao[4] = {};           // spheres, meshes, the empty one of the full-screen pass, snow
  // x0, x1, x2, scalar, mesh vertices, particle indices, snow positions, snow normals, snow indices,
  // snow rest positions
  GLuint buffers[10] = {};
  GLuint framebuffers[4] = {};  // shadow, geometry (albedo, normal, depth), occlusion, final
  // shadow depth, albedo, normal (packed 0.5 n + 0.5), depth, occlusion (half size), final, colour map
  GLuint textures[7] = {};
  int shadow_size = 0;          // texels along the shadow map's side
};

namespace {

GLuint make_texture(const Gl& gl, GLenum internal, int w, int h, GLenum format, GLenum type, GLint filter) {
  GLuint t = 0;
  gl.glGenTextures(1, &t);
  gl.glBindTexture(GL_TEXTURE_2D, t);
  gl.glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, type, nullptr);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

// Attaches `colors` (0 to 2 textures) and `depth` and checks that the framebuffer is complete.
void attach(const Gl& gl, GLuint framebuffer, std::initializer_list<GLuint> colors, GLuint depth, const char* name) {
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  GLenum targets[2];
  GLsizei count = 0;
  for (GLuint c : colors) {
    targets[count] = GLenum(GL_COLOR_ATTACHMENT0 + count);
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, targets[count], GL_TEXTURE_2D, c, 0);
    ++count;
  }
  if (count > 0) gl.glDrawBuffers(count, targets);
  else gl.glDrawBuffer(GL_NONE);
  if (depth) gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("the ") + name + " framebuffer is incomplete");
}

}  // namespace

FrameRenderer::FrameRenderer(const GlContext& context, const RenderSettings& settings)
    : gl_(context.gl()), settings_(settings), r_(std::make_unique<Resources>(gl_, settings)) {
  const Gl& gl = gl_;
  gl.glGenVertexArrays(4, r_->vao);
  gl.glGenBuffers(10, r_->buffers);
  gl.glGenFramebuffers(4, r_->framebuffers);
  const int w = settings_.width, h = settings_.height;
  GLuint* t = r_->textures;
  // About as many shadow-map texels per metre as the image has pixels per metre at the target.
  r_->shadow_size = std::clamp(int(std::pow(2, std::floor(std::log2(std::max(w, h))))), 512, 2048);
  const int side = r_->shadow_size;
  t[0] = make_texture(gl, GL_DEPTH_COMPONENT24, side, side, GL_DEPTH_COMPONENT, GL_FLOAT, GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  t[1] = make_texture(gl, GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST);
  t[2] = make_texture(gl, GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST);
  t[3] = make_texture(gl, GL_DEPTH_COMPONENT24, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST);
  t[4] = make_texture(gl, GL_R8, (w + 1) / 2, (h + 1) / 2, GL_RED, GL_UNSIGNED_BYTE, GL_LINEAR);
  t[5] = make_texture(gl, GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST);
  t[6] = make_texture(gl, GL_RGB8, kColorMapSize, 1, GL_RGB, GL_UNSIGNED_BYTE, GL_LINEAR);
  std::vector<unsigned char> lut(3 * kColorMapSize);
  for (int i = 0; i < kColorMapSize; ++i) {
    const Rgb c = color_map_rgb(settings_.color_map, double(i) / (kColorMapSize - 1));
    for (int k = 0; k < 3; ++k) lut[std::size_t(3 * i + k)] = static_cast<unsigned char>(std::lround(255 * c[std::size_t(k)]));
  }
  gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, kColorMapSize, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, lut.data());
  attach(gl, r_->framebuffers[0], {}, t[0], "shadow map");
  attach(gl, r_->framebuffers[1], {t[1], t[2]}, t[3], "geometry");
  attach(gl, r_->framebuffers[2], {t[4]}, 0, "occlusion");
  attach(gl, r_->framebuffers[3], {t[5]}, 0, "final");
  gl.check("creating the renderer's framebuffers");
}

FrameRenderer::~FrameRenderer() {
  gl_.glDeleteTextures(7, r_->textures);
  gl_.glDeleteFramebuffers(4, r_->framebuffers);
  gl_.glDeleteBuffers(10, r_->buffers);
  gl_.glDeleteVertexArrays(4, r_->vao);
}

Image FrameRenderer::render(const FrameScene& scene, const Camera& camera) {
  const Gl& gl = gl_;
  const RenderSettings& s = settings_;
  const PositionColumns& pos = scene.positions;
  const std::size_t element = pos.doubles ? sizeof(double) : sizeof(float);

  // The cutaway removes the particles on the camera's side of the plane through the target
  // across the coordinate axis closest to the viewing direction.
  std::optional<CutPlane> cut;
  if (s.cutaway) {
    const Vec3 to_eye = camera.eye - camera.target;
    std::size_t axis = 0;
    for (std::size_t d = 1; d < 3; ++d)
      if (std::abs(to_eye[d]) > std::abs(to_eye[axis])) axis = d;
    cut = CutPlane{camera.target, {0, 0, 0}};
    cut->normal[axis] = to_eye[axis] > 0 ? 1 : -1;
  }
  const std::vector<std::uint32_t> shown = exposed_particles(pos, s.particle_spacing, cut);

  // Upload the engine's columns as they are (three position arrays and the colour scalar) and
  // the indices of the particles to draw.
  gl.glBindVertexArray(r_->vao[0]);
  for (GLuint d = 0; d < 4; ++d) {
    const void* data = d < 3 ? pos.x[d] : scene.scalar;
    if (!data) {
      gl.glDisableVertexAttribArray(d);
      gl.glVertexAttrib1f(d, 0.0f);
      continue;
    }
    gl.glBindBuffer(GL_ARRAY_BUFFER, r_->buffers[d]);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(pos.count * (d < 3 ? element : sizeof(float))), data, GL_STREAM_DRAW);
    gl.glVertexAttribPointer(d, 1, d < 3 && pos.doubles ? GL_DOUBLE : GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.glEnableVertexAttribArray(d);
  }
  gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r_->buffers[5]);
  gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(shown.size() * sizeof(std::uint32_t)), shown.data(),
                  GL_STREAM_DRAW);
  // Draws the shown particles whose index lies in [begin, end).
  auto draw_particles = [&](std::size_t begin, std::size_t end) {
    const auto first = std::lower_bound(shown.begin(), shown.end(), begin);
    const auto last = std::lower_bound(first, shown.end(), end);
    if (last == first) return;
    gl.glDrawElements(GL_POINTS, GLsizei(last - first), GL_UNSIGNED_INT,
                      reinterpret_cast<const void*>((first - shown.begin()) * sizeof(std::uint32_t)));
  };
  gl.glEnable(GL_PROGRAM_POINT_SIZE);

  // Ground and collider meshes in one vertex buffer: the ground quad first.
  std::vector<float> meshes;
  const double ground_y = s.ground_height.value_or(s.domain_min[1]);
  // The ground is a square around the target that fades into the background by its edge, so
  // nothing beyond it costs lighting.
  const double ground_half = kGroundRadius * camera.radius;
  if (s.ground) {
    const double cx = camera.target[0], cz = camera.target[2];
    const double corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      const float v[6] = {float(cx + c[0] * ground_half), float(ground_y), float(cz + c[1] * ground_half), 0, 1, 0};
      meshes.insert(meshes.end(), v, v + 6);
    }
  }
  const GLsizei ground_vertices = GLsizei(meshes.size() / 6);
  for (const ColliderMesh& m : scene.colliders) meshes.insert(meshes.end(), m.mesh.vertices.begin(), m.mesh.vertices.end());
  const GLsizei mesh_vertices = GLsizei(meshes.size() / 6);
  gl.glBindVertexArray(r_->vao[1]);
  gl.glBindBuffer(GL_ARRAY_BUFFER, r_->buffers[4]);
  gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(meshes.size() * sizeof(float)), meshes.data(), GL_STREAM_DRAW);
  gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.glEnableVertexAttribArray(0);
  gl.glEnableVertexAttribArray(1);

  // The snow surface and, after its vertices and triangles, its hoar crystals as closed hexagonal
  // prisms: positions and normals uploaded as the reconstruction stores them.
  GLsizei snow_indices = 0, crystal_indices = 0;
  if (scene.snow) {
    const surface::SurfaceMesh& m = *scene.snow;
    std::vector<surface::Vec3f> crystal_positions, crystal_normals;
    std::vector<std::uint32_t> crystal_triangles;
    surface::append_crystal_prisms(m.crystals, crystal_positions, crystal_normals, crystal_triangles);
    for (std::uint32_t& v : crystal_triangles) v += std::uint32_t(m.vertex_count());
    static_assert(sizeof(surface::Vec3f) == 3 * sizeof(float), "Vec3f must be packed floats");
    // Two arrays one after the other in `buffer`.
    auto upload = [&](GLenum target, GLuint buffer, const void* a, std::size_t a_bytes, const void* b, std::size_t b_bytes) {
      gl.glBindBuffer(target, buffer);
      gl.glBufferData(target, GLsizeiptr(a_bytes + b_bytes), nullptr, GL_STREAM_DRAW);
      gl.glBufferSubData(target, 0, GLsizeiptr(a_bytes), a);
      gl.glBufferSubData(target, GLintptr(a_bytes), GLsizeiptr(b_bytes), b);
    };
    gl.glBindVertexArray(r_->vao[3]);
    const std::size_t vec = sizeof(surface::Vec3f);
    upload(GL_ARRAY_BUFFER, r_->buffers[6], m.positions.data(), m.positions.size() * vec, crystal_positions.data(),
           crystal_positions.size() * vec);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    upload(GL_ARRAY_BUFFER, r_->buffers[7], m.normals.data(), m.normals.size() * vec, crystal_normals.data(),
           crystal_normals.size() * vec);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    // Rest positions seed the grains; the crystals have none (zeros).
    const std::vector<surface::Vec3f> crystal_rest(crystal_positions.size(), surface::Vec3f{0, 0, 0});
    upload(GL_ARRAY_BUFFER, r_->buffers[9], m.rest_positions.data(), m.rest_positions.size() * vec, crystal_rest.data(),
           crystal_rest.size() * vec);
    gl.glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    for (GLuint a = 0; a < 3; ++a) gl.glEnableVertexAttribArray(a);
    const std::size_t index = sizeof(std::uint32_t);
    upload(GL_ELEMENT_ARRAY_BUFFER, r_->buffers[8], m.triangles.data(), m.triangles.size() * index,
           crystal_triangles.data(), crystal_triangles.size() * index);
    snow_indices = GLsizei(m.triangles.size());
    crystal_indices = GLsizei(crystal_triangles.size());
  }
  auto draw_snow = [&](GLsizei first, GLsizei count) {
    if (count == 0) return;
    gl.glBindVertexArray(r_->vao[3]);
    gl.glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, reinterpret_cast<const void*>(first * sizeof(std::uint32_t)));
  };

  auto set_camera = [&](const GlProgram& p, const Mat4& view, const Mat4& projection) {
    p.use();
    p.set("view", view);
    p.set("projection", projection);
    p.set("radius", float(s.sphere_radius));
  };

  // 1. Shadow map: spheres (as discs), colliders and snow seen from the light.
  const LightCamera light = light_camera(camera);
  const int shadow_size = r_->shadow_size;
  if (s.shadows) {
    gl.glBindFramebuffer(GL_FRAMEBUFFER, r_->framebuffers[0]);
    gl.glViewport(0, 0, shadow_size, shadow_size);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(GL_LESS);
    gl.glClear(GL_DEPTH_BUFFER_BIT);
    const GlProgram& p = r_->sphere_shadow;
    set_camera(p, light.view, light.projection);
    p.set("perspective", 0);
    p.set("pixels_per_unit", float(0.5 * shadow_size * light.projection.at(0, 0)));
    gl.glBindVertexArray(r_->vao[0]);
    draw_particles(0, pos.count);
    set_camera(r_->mesh_shadow, light.view, light.projection);
    if (mesh_vertices > ground_vertices) {
      gl.glBindVertexArray(r_->vao[1]);
      gl.glDrawArrays(GL_TRIANGLES, ground_vertices, mesh_vertices - ground_vertices);
    }
    draw_snow(0, snow_indices + crystal_indices);
  }

  // 2. Geometry: albedo, normal and depth of spheres, snow, colliders and ground.
  const Mat4 view = camera.view(), projection = camera.projection();
  gl.glBindFramebuffer(GL_FRAMEBUFFER, r_->framebuffers[1]);
  gl.glViewport(0, 0, s.width, s.height);
  gl.glEnable(GL_DEPTH_TEST);
  gl.glClear(GL_DEPTH_BUFFER_BIT);  // the lighting pass reads colour only where depth < 1
  {
    const GlProgram& p = r_->sphere;
    set_camera(p, view, projection);
    p.set("perspective", 1);
    p.set("pixels_per_unit", float(0.5 * s.height * projection.at(1, 1)));
    p.set("inverse_viewport", 1.0f / float(s.width), 1.0f / float(s.height));
    gl.glActiveTexture(GL_TEXTURE0 + kColorMapUnit);
    gl.glBindTexture(GL_TEXTURE_2D, r_->textures[6]);
    p.set("color_map", int(kColorMapUnit));
    gl.glBindVertexArray(r_->vao[0]);
    if (scene.scalar) {
      p.set("use_scalar", 1);
      p.set("scalar_range", float(scene.scalar_min), float(scene.scalar_max));
      draw_particles(0, pos.count);
    } else {
      p.set("use_scalar", 0);
      for (const ColorRange& range : scene.ranges) {
        p.set("base_color", range.color.data());
        draw_particles(range.begin, range.end);
      }
    }
  }
  if (snow_indices + crystal_indices > 0) {
    const GlProgram& p = r_->snow;
    set_camera(p, view, projection);
    p.set("grain", float(s.snow_grain));
    p.set("facets", 0);
    draw_snow(0, snow_indices);
    p.set("facets", 1);
    draw_snow(snow_indices, crystal_indices);
  }
  if (mesh_vertices > 0) {
    const GlProgram& p = r_->mesh;
    set_camera(p, view, projection);
    gl.glBindVertexArray(r_->vao[1]);
    if (ground_vertices > 0) {
      const Rgb ground_color = {0.80f, 0.79f, 0.77f};
      const auto centre = to_float({camera.target[0], ground_y, camera.target[2]});
      p.set("base_color", ground_color.data());
      p.set("gloss", 0.04f);
      p.set("checker", float(camera.radius / 2));
      p.set("fade_center", centre.data());
      p.set("fade_radius", float(ground_half));
      gl.glDrawArrays(GL_TRIANGLES, 0, ground_vertices);
    }
    p.set("checker", 0.0f);
    p.set("fade_radius", 0.0f);
    GLint first = ground_vertices;
    for (const ColliderMesh& m : scene.colliders) {
      p.set("base_color", m.color.data());
      p.set("gloss", m.gloss);
      gl.glDrawArrays(GL_TRIANGLES, first, GLsizei(m.mesh.vertex_count()));
      first += GLint(m.mesh.vertex_count());
    }
  }

  // 3. Ambient occlusion at half resolution, then lighting, shadows, background, tone and gamma
  //    into 8-bit RGBA.
  gl.glDisable(GL_DEPTH_TEST);
  const GLuint inputs[5] = {r_->textures[1], r_->textures[2], r_->textures[3], r_->textures[0], r_->textures[4]};
  for (int unit = 0; unit < 5; ++unit) {
    gl.glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    gl.glBindTexture(GL_TEXTURE_2D, inputs[unit]);
  }
  auto set_screen = [&](const GlProgram& p) {
    p.use();
    p.set("albedo_tex", int(kAlbedoUnit));
    p.set("normal_tex", int(kNormalUnit));
    p.set("depth_tex", int(kDepthUnit));
    p.set("shadow_map", int(kShadowUnit));
    p.set("occlusion_tex", int(kOcclusionUnit));
    p.set("viewport", s.width, s.height);
    p.set("near_plane", float(camera.near));
    p.set("far_plane", float(camera.far));
    p.set("projection_scale", projection.at(0, 0), projection.at(1, 1));
  };
  gl.glBindVertexArray(r_->vao[2]);
  if (s.ambient_occlusion) {
    gl.glBindFramebuffer(GL_FRAMEBUFFER, r_->framebuffers[2]);
    gl.glViewport(0, 0, (s.width + 1) / 2, (s.height + 1) / 2);
    set_screen(r_->occlusion);
    // Samples reach about four particle radii, projected at the target's distance.
    const double pixels_per_metre = s.height / (2 * std::tan(camera.fov / 2) * length(camera.eye - camera.target));
    r_->occlusion.set("ao_radius_px", float(std::clamp(4 * s.sphere_radius * pixels_per_metre, 2.0, 40.0)));
    r_->occlusion.set("ao_range", float(4 * s.sphere_radius));
    gl.glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  Mat4 to_unit = Mat4::identity();  // clip [-1, 1] -> texture [0, 1]
  for (int i = 0; i < 3; ++i) to_unit.at(i, i) = 0.5f, to_unit.at(i, 3) = 0.5f;
  const Mat4 view_to_shadow = to_unit * light.projection * light.view * inverse_rigid(view);
  const auto light_dir_view = to_float(normalize(rotate(view, -1.0 * camera.light_direction)));
  const auto up_view = to_float(rotate(view, {0, 1, 0}));
  const float shadow_texel = float(2 * light.half_width / shadow_size);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, r_->framebuffers[3]);
  gl.glViewport(0, 0, s.width, s.height);
  const GlProgram& c = r_->composite;
  set_screen(c);
  c.set("light_dir_view", light_dir_view.data());
  c.set("up_view", up_view.data());
  c.set("view_to_shadow", view_to_shadow);
  c.set("shadow_bias", 2.0f * shadow_texel);
  c.set("background_top", s.background_top.data());
  c.set("background_bottom", s.background_bottom.data());
  gl.glDrawArrays(GL_TRIANGLES, 0, 3);

  // 4. Read back; GL's rows run bottom to top.
  Image image(s.width, s.height);
  std::vector<std::uint8_t> rows(image.rgb.size());
  gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.glReadPixels(0, 0, s.width, s.height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  gl.check("drawing a frame");
  const std::size_t stride = std::size_t(s.width) * 3;
  for (int y = 0; y < s.height; ++y)
    std::memcpy(image.pixel(0, y), &rows[std::size_t(s.height - 1 - y) * stride], stride);
  return image;
}

}  // namespace firn::viz
