// The renderer (viz/): golden images (particles, and a snow surface) rendered with OSMesa and
// compared by per-pixel difference statistics (which survive Mesa versions, unlike byte
// equality), EGL against OSMesa, the PNG writer, ffmpeg started by argument vector, the .vtp
// reader, exposed-particle culling, SDF meshing and the colour maps. Regenerate the golden images with FIRN_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include "engine/output/vtp_writer.hpp"
#include "engine/particle_storage.hpp"
#include "engine/scene/scene_builder.hpp"
#include "kernels/backend/serial.hpp"
#include "studies/sweep/child_process.hpp"
#include "viz/collider_sdf.hpp"
#include "viz/color_map.hpp"
#include "viz/exposed_particles.hpp"
#include "viz/ffmpeg_pipe.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/frame_renderer.hpp"
#include "viz/legend.hpp"
#include "engine/output/png_file.hpp"
#include "viz/sdf_mesh.hpp"
#include "viz/surface/reconstruct_surface.hpp"
#include "viz/synthetic_particles.hpp"
#include "viz/vtp_reader.hpp"

namespace firn::viz {
namespace {

const std::string kGolden = FIRN_SOURCE_DIR "/tests/golden/";

std::string scratch(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "firn_render_test";
  ::mkdir(dir.c_str(), 0755);
  return dir + "/" + name;
}

Image decode_png(const unsigned char* data, int size) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load_from_memory(data, size, &w, &h, &channels, 3);
  if (!pixels) return Image();
  Image image(w, h);
  std::copy(pixels, pixels + image.rgb.size(), image.rgb.begin());
  stbi_image_free(pixels);
  return image;
}

Image load_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!pixels) return Image();
  Image image(w, h);
  std::copy(pixels, pixels + image.rgb.size(), image.rgb.begin());
  stbi_image_free(pixels);
  return image;
}

// Per-pixel difference statistics: the mean absolute difference over all channels (in 8-bit
// levels) and the fraction of pixels whose largest channel difference exceeds 32 levels.
struct Difference {
  double mean_abs = 1e9, fraction_over_32 = 1;
};

Difference compare(const Image& a, const Image& b) {
  Difference d;
  if (a.width != b.width || a.height != b.height || a.rgb.empty()) return d;
  double sum = 0;
  std::size_t over = 0;
  for (std::size_t p = 0; p < a.rgb.size(); p += 3) {
    int largest = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const int diff = std::abs(int(a.rgb[p + k]) - int(b.rgb[p + k]));
      sum += diff;
      largest = std::max(largest, diff);
    }
    over += largest > 32;
  }
  d.mean_abs = sum / double(a.rgb.size());
  d.fraction_over_32 = double(over) / double(a.rgb.size() / 3);
  return d;
}

// The tolerance every golden comparison uses: small shifts of a few edge pixels between Mesa
// versions pass, a missing shadow, colour or object does not (see GoldenTolerance below).
bool within_tolerance(const Difference& d) { return d.mean_abs <= 1.5 && d.fraction_over_32 <= 0.005; }

// Small scenes, rendered at 192 x 108.
struct GoldenScene {
  SyntheticParticles block = jittered_block(3375, 0.2, {0, 0, 0});
  RenderSettings settings;
  std::vector<float> field;
  FrameScene scene;

  explicit GoldenScene(const std::string& name) {
    settings.width = 192, settings.height = 108;
    settings.particle_spacing = block.spacing;
    settings.sphere_radius = 0.6 * block.spacing;
    settings.domain_min = {-0.15, 0, -0.15}, settings.domain_max = {0.35, 0.3, 0.35};
    scene.positions = block.columns();
    const std::size_t n = scene.positions.count;
    if (name == "layers") {
      for (std::size_t m = 0; m < 3; ++m) scene.ranges.push_back({m * n / 3, (m + 1) * n / 3, default_material_color(int(m))});
    } else {  // "field": height as a scalar through viridis, cut open, beside a box collider
      for (std::size_t i = 0; i < n; ++i) field.push_back(block.x[1][i]);
      scene.scalar = field.data();
      scene.scalar_min = 0, scene.scalar_max = 0.2;
      settings.cutaway = true;
      ColliderSpec box;
      box.kind = ColliderSpec::Kind::box;
      box.min = {0.24, 0, 0.0}, box.max = {0.3, 0.12, 0.2};
      scene.colliders.push_back({mesh_signed_distance(collider_solid(collider_body(box).collider).distance,
                                                      settings.domain_min, settings.domain_max, 48)});
    }
  }
  Camera camera() const { return frame_camera(settings, position_bounds(scene.positions)); }
};

Image render_with(GlApi api, GoldenScene& g) {
  const auto context = make_gl_context(api);
  FrameRenderer renderer(*context, g.settings);
  return renderer.render(g.scene, g.camera());
}

void check_golden(const std::string& name, const Image& image) {
  const std::string path = kGolden + name + ".png";
  if (std::getenv("FIRN_UPDATE_GOLDEN")) write_png(path, image);
  const Image golden = load_png(path);
  ASSERT_FALSE(golden.rgb.empty()) << "missing " << path << " (FIRN_UPDATE_GOLDEN=1 writes it)";
  const Difference d = compare(image, golden);
  write_png(scratch(name + ".rendered.png"), image);
  EXPECT_TRUE(within_tolerance(d)) << name << ": mean |difference| " << d.mean_abs << " levels, "
                                   << 100 * d.fraction_over_32 << "% of pixels off by more than 32 levels; "
                                   << "this render is in " << scratch(name + ".rendered.png");
}

TEST(GoldenImage, LayeredBlockWithShadowAndGround) {
  GoldenScene g("layers");
  check_golden("layers", render_with(GlApi::osmesa, g));
}

TEST(GoldenImage, ScalarFieldCutawayAndBoxCollider) {
  GoldenScene g("field");
  check_golden("field", render_with(GlApi::osmesa, g));
}

TEST(GoldenImage, LegendOnAFrame) {
  GoldenScene g("field");
  Image image = render_with(GlApi::osmesa, g);
  Legend legend;
  legend.title = "height (m)";
  legend.min = 0, legend.max = 0.2;
  legend.caption = "t = 1.000 ms";
  draw_legend(image, legend);
  check_golden("legend", image);
}

// Expects `image` out of the golden tolerance around `reference` (and records the mean difference).
void expect_rejected(const Image& image, const Image& reference, const std::string& what) {
  const Difference d = compare(image, reference);
  ::testing::Test::RecordProperty(what + " mean", std::to_string(d.mean_abs));
  EXPECT_FALSE(within_tolerance(d)) << what << ": mean " << d.mean_abs << ", over 32: " << d.fraction_over_32;
}

// The tolerance is tight enough to fail: the images without shadows, without ambient occlusion,
// or with one material's colour changed are all out of it.
TEST(GoldenTolerance, RejectsAVisibleChange) {
  GoldenScene g("layers");
  const Image reference = render_with(GlApi::osmesa, g);
  auto expect_rejected = [&](const char* what) { viz::expect_rejected(render_with(GlApi::osmesa, g), reference, what); };
  g.settings.shadows = false;
  expect_rejected("shadows off");
  g.settings.shadows = true;
  g.settings.ambient_occlusion = false;
  expect_rejected("no ambient occlusion");
  g.settings.ambient_occlusion = true;
  g.scene.ranges[1].color = {0.38f, 0.80f, 0.50f};
  expect_rejected("middle layer green instead of blue");
}

// The snow surface of a ball of particles (viz/surface) on the ground, at 320 x 180: large enough
// that its hoar crystals span a few pixels each.
struct SnowScene {
  ParticleStorage<float> particles;
  surface::SurfaceParams params;
  RenderSettings settings;
  surface::SurfaceMesh mesh;
  FrameScene scene;

  SnowScene() {
    // The particles of a jittered block within 0.1 m of its centre, at rest where they are.
    const SyntheticParticles block = jittered_block(8000, 0.2, {-0.1, 0, -0.1});
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < block.x[0].size(); ++i) {
      const double y = block.x[1][i] - 0.1;
      if (block.x[0][i] * block.x[0][i] + y * y + block.x[2][i] * block.x[2][i] < 0.01) inside.push_back(i);
    }
    particles.enable(Attribute::x0);
    particles.resize(inside.size());
    const ParticleView<float> pv = particles.view();
    for (std::size_t p = 0; p < pv.n; ++p) {
      for (int d = 0; d < 3; ++d) pv.x[d][p] = pv.x0[d][p] = block.x[d][inside[p]];
      pv.vol0[p] = float(block.spacing * block.spacing * block.spacing);
    }
    params.simulation_dx = 2 * block.spacing;  // two particles per cell and axis
    settings.width = 320, settings.height = 180;
    settings.particle_spacing = block.spacing;
    settings.sphere_radius = 0.5 * block.spacing;
    settings.domain_min = {-0.15, 0, -0.15}, settings.domain_max = {0.15, 0.3, 0.15};
    settings.camera_position = Vec3{0.21, 0.2, 0.25}, settings.camera_target = Vec3{0, 0.09, 0};  // the ball fills the frame
    settings.snow_grain = 0.004;  // a few pixels
  }
  Image render() {
    mesh = surface::reconstruct_surface(particles.view(), params, backend::Serial{});
    scene.snow = &mesh;
    const auto context = make_gl_context(GlApi::osmesa);
    FrameRenderer renderer(*context, settings);
    const Bounds bounds = position_bounds({{particles.view().x[0], particles.view().x[1], particles.view().x[2]}, false,
                                           particles.size()});
    return renderer.render(scene, frame_camera(settings, bounds));
  }
};

TEST(GoldenImage, SnowSurfaceWithCrystals) {
  SnowScene snow;
  const Image image = snow.render();
  EXPECT_GT(snow.mesh.crystals.size(), 100u);
  check_golden("snow", image);
}

// The snow model's parts are visible: without the subsurface term or without the hoar crystals the
// image is out of the golden tolerance.
TEST(GoldenTolerance, RejectsSnowWithoutSubsurfaceOrCrystals) {
  SnowScene snow;
  const Image reference = snow.render();
  auto expect_rejected = [&](const char* what) { viz::expect_rejected(snow.render(), reference, what); };
  snow.settings.subsurface = false;
  expect_rejected("Lambertian snow");
  snow.settings.subsurface = true;
  snow.params.crystals = false;
  expect_rejected("no hoar crystals");
}

TEST(GlContexts, EglAndOsMesaRenderTheSameImage) {
  GoldenScene g("layers");
  const Image osmesa = render_with(GlApi::osmesa, g);
  Image egl;
  try {
    egl = render_with(GlApi::egl, g);
  } catch (const std::exception& e) {
    FAIL() << "no EGL context: " << e.what();
  }
  const Difference d = compare(egl, osmesa);
  RecordProperty("mean_abs_difference", std::to_string(d.mean_abs));
  EXPECT_TRUE(within_tolerance(d)) << "mean " << d.mean_abs << ", over 32: " << d.fraction_over_32;
}

TEST(GlContexts, DoubleColumnsDrawLikeFloatOnes) {
  GoldenScene g("layers");
  const Image floats = render_with(GlApi::osmesa, g);
  std::vector<double> x[3];
  for (int d = 0; d < 3; ++d) x[d].assign(g.block.x[d].begin(), g.block.x[d].end());
  for (int d = 0; d < 3; ++d) g.scene.positions.x[d] = x[d].data();
  g.scene.positions.doubles = true;
  EXPECT_TRUE(within_tolerance(compare(render_with(GlApi::osmesa, g), floats)));
}

TEST(PngWriter, RoundTripsEveryPixel) {
  Image image(37, 23);  // odd sizes: no row padding assumptions
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = std::uint8_t((i * 7919) % 251);
  const std::vector<unsigned char> png = encode_png(image);
  const Image back = decode_png(png.data(), int(png.size()));
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 23);
  EXPECT_EQ(back.rgb, image.rgb);
  const std::string path = scratch("round_trip.png");
  write_png(path, image);
  EXPECT_EQ(load_png(path).rgb, image.rgb);
}

// ffprobe's report on the video, started from an argument vector (never a shell).
std::string run_ffprobe(const std::string& video) {
  sweep::ChildSpec probe;
  probe.argv = {"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                "stream=codec_name,pix_fmt,width,height,nb_read_frames", "-of", "default=nw=1", video};
  probe.log_path = video + ".ffprobe.txt";
  probe.search_path = true;
  sweep::wait_child(sweep::start_child(probe));
  std::ifstream log(probe.log_path);
  return std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>());
}

TEST(FfmpegPipe, EncodesH264Yuv420pOneFramePerImage) {
  if (find_on_path("ffmpeg").empty() || find_on_path("ffprobe").empty())
    GTEST_SKIP() << "ffmpeg/ffprobe not installed (make deps installs them)";
  const std::string video = scratch("pipe.mp4");
  std::remove(video.c_str());
  FfmpegPipe pipe(video, 64, 48, 30);
  for (int f = 0; f < 7; ++f) {
    Image frame(64, 48);
    for (std::size_t i = 0; i < frame.rgb.size(); ++i) frame.rgb[i] = std::uint8_t(i + 20 * f);
    pipe.write(frame);
  }
  pipe.finish();
  const std::string probe = run_ffprobe(video);
  EXPECT_NE(probe.find("codec_name=h264"), std::string::npos) << probe;
  EXPECT_NE(probe.find("pix_fmt=yuv420p"), std::string::npos) << probe;
  EXPECT_NE(probe.find("width=64"), std::string::npos) << probe;
  EXPECT_NE(probe.find("nb_read_frames=7"), std::string::npos) << probe;
}

TEST(FfmpegPipe, SaysSoWhenFfmpegIsMissing) {
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", "/nonexistent", 1);
  try {
    FfmpegPipe pipe(scratch("missing.mp4"), 64, 48, 30);
    ADD_FAILURE() << "no error without ffmpeg on PATH";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg"), std::string::npos) << e.what();
  }
  ::setenv("PATH", path.c_str(), 1);
}

TEST(FfmpegPipe, RefusesOddSizes) { EXPECT_THROW(FfmpegPipe(scratch("odd.mp4"), 65, 48, 30), std::runtime_error); }

TEST(ExposedParticles, KeepsTheTwoLayerSkinOfABlock) {
  const SyntheticParticles block = jittered_block(1000, 1.0, {0, 0, 0});  // 10^3, spacing 0.1
  EXPECT_EQ(exposed_particles(block.columns(), block.spacing, std::nullopt).size(), 1000u - 6 * 6 * 6);
  // Cut at x = 0.5: the half 5 x 10 x 10 stays; of it 1 x 6 x 6 are buried.
  const CutPlane cut{{0.5, 0.5, 0.5}, {1, 0, 0}};
  const auto shown = exposed_particles(block.columns(), block.spacing, cut);
  EXPECT_EQ(shown.size(), 500u - 36);
  for (std::uint32_t i : shown) EXPECT_LT(block.x[0][i], 0.5f);
  // No culling when the occupancy grid would be too large: all are kept.
  EXPECT_EQ(exposed_particles(block.columns(), block.spacing, std::nullopt, 10).size(), 1000u);
}

TEST(SdfMesh, SphereVerticesLieOnTheSurface) {
  const double r = 0.3, h = 1.0 / 32;
  const SignedDistance sphere = [r](const Vec3& x, Vec3& n) {
    n = normalize(x);
    return length(x) - r;
  };
  const TriangleMesh mesh = mesh_signed_distance(sphere, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, 32);
  ASSERT_GT(mesh.vertex_count(), 300u);
  double area = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 3) {
    Vec3 p[3];
    for (int k = 0; k < 3; ++k)
      for (std::size_t d = 0; d < 3; ++d) p[k][d] = mesh.vertices[6 * (v + std::size_t(k)) + d];
    for (const Vec3& q : p) EXPECT_NEAR(length(q), r, 0.5 * h * h / r + 1e-6);  // chord sag of linear interpolation
    area += 0.5 * length(cross(p[1] - p[0], p[2] - p[0]));
  }
  EXPECT_NEAR(area, 4 * M_PI * r * r, 0.03 * 4 * M_PI * r * r);
}

TEST(SdfMesh, ColliderBoxCutToTheDomainIsClosed) {
  ColliderSpec plane;  // the half-space x > 0.6, cut to the unit box: a slab 0.4 thick
  plane.kind = ColliderSpec::Kind::plane;
  plane.point = {0.6, 0, 0}, plane.normal = {-1, 0, 0};
  const Vec3 lo = {0, 0, 0}, hi = {1, 1, 1};
  const TriangleMesh mesh = mesh_signed_distance(clip_to_box(collider_solid(collider_body(plane).collider).distance, lo, hi),
                                                 {-0.1, -0.1, -0.1}, {1.1, 1.1, 1.1}, 24);
  Vec3 min = {1e9, 1e9, 1e9}, max = {-1e9, -1e9, -1e9};
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (std::size_t d = 0; d < 3; ++d) {
      min[d] = std::min(min[d], double(mesh.vertices[6 * v + d]));
      max[d] = std::max(max[d], double(mesh.vertices[6 * v + d]));
    }
  EXPECT_NEAR(min[0], 0.6, 1e-6);
  EXPECT_NEAR(max[0], 1.0, 1e-6);
  for (std::size_t d = 1; d < 3; ++d) {
    EXPECT_NEAR(min[d], 0.0, 1e-6);
    EXPECT_NEAR(max[d], 1.0, 1e-6);
  }
}

TEST(ColorMap, ViridisAndCoolWarmEndpoints) {
  // matplotlib's viridis table: first (0.267004, 0.004874, 0.329415), last (0.993248, 0.906157,
  // 0.143936), middle (0.128729, 0.563265, 0.551229).
  const Rgb v0 = color_map_rgb(ColorMap::viridis, 0), v1 = color_map_rgb(ColorMap::viridis, 1),
            vm = color_map_rgb(ColorMap::viridis, 0.5);
  const double first[3] = {0.267004, 0.004874, 0.329415}, last[3] = {0.993248, 0.906157, 0.143936},
               middle[3] = {0.128729, 0.563265, 0.551229};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(v0[k], first[k], 0.02);
    EXPECT_NEAR(v1[k], last[k], 0.02);
    EXPECT_NEAR(vm[k], middle[k], 0.02);
  }
  const Rgb c = color_map_rgb(ColorMap::diverging, 0.5);
  for (float x : c) EXPECT_NEAR(x, 0.865, 1e-6);
}

TEST(VtpReader, ReadsWhatTheEngineWrites) {
  SimulationConfig config;
  Simulation<float, backend::Serial> sim(config);
  const int snow = sim.add_material({"snow", "neo_hookean", 400, ElasticModuli::from_E_nu(1.4e5, 0.2)});
  sim.add_particles(snow, fill_sphere(config.domain_min, config.dx, 2, {0.5, 0.5, 0.5}, 0.05), {1, -2, 0.5}, 1e-6);
  sim.prepare();
  const std::string path = scratch("frame.vtp");
  write_particles_vtp(path, sim);
  const VtpFile f = read_vtp(path);
  ASSERT_EQ(f.points, sim.particle_count());
  const ParticleView<float> pv = sim.particles();
  for (std::size_t p = 0; p < pv.n; ++p) {
    const std::size_t i = pv.id[p];  // the file is in id order
    for (std::size_t d = 0; d < 3; ++d) EXPECT_EQ(f.positions.values[3 * i + d], double(pv.x[d][p]));
  }
  EXPECT_EQ(f.arrays.at("velocity").components, 3);
  EXPECT_EQ(f.arrays.at("velocity").values[1], -2.0);
  EXPECT_EQ(f.arrays.at("J").values[0], 1.0);
  EXPECT_EQ(f.arrays.at("material").values[0], 0.0);
}

// A writer kept from frame to frame (as a run keeps it) writes a smaller frame after a larger one
// byte for byte as a fresh writer does: nothing of the larger frame's buffers leaks into it.
TEST(VtpReader, AKeptWriterWritesWhatAFreshOneDoes) {
  SimulationConfig config;
  auto sphere_sim = [&config](double radius) {
    auto sim = std::make_unique<Simulation<float, backend::Serial>>(config);
    const int snow = sim->add_material({"snow", "neo_hookean", 400, ElasticModuli::from_E_nu(1.4e5, 0.2)});
    sim->add_particles(snow, fill_sphere(config.domain_min, config.dx, 2, {0.5, 0.5, 0.5}, radius), {1, -2, 0.5}, 1e-6);
    sim->prepare();
    return sim;
  };
  const auto large = sphere_sim(0.08), small = sphere_sim(0.05);
  ASSERT_GT(large->particle_count(), small->particle_count());
  ParticleVtpWriter kept;
  kept.write(scratch("kept_large.vtp"), *large);
  kept.write(scratch("kept_small.vtp"), *small);
  write_particles_vtp(scratch("fresh_small.vtp"), *small);
  auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(scratch("kept_small.vtp")), bytes(scratch("fresh_small.vtp")));
  EXPECT_EQ(read_vtp(scratch("kept_large.vtp")).points, large->particle_count());
}

}  // namespace
}  // namespace firn::viz
