// firn bench render [--particles N] [--width W] [--height H] [--gl egl|osmesa] [--frames F] [--png FILE]
// Times the sphere renderer on a synthetic set: a jittered cubic lattice of N particles in three
// material layers standing on the ground, with shadows and ambient occlusion. Each timed frame is drawn,
// read back and PNG-encoded in sequence; prints the medians:
//   ms_per_frame (draw + read-back + PNG encoding), render_ms, png_ms; the mean CPU time of the
//   process per frame (all threads, so it shows what other load on the machine hides in the wall
//   time); and the GL context.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "apps/commands.hpp"
#include "viz/camera.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/frame_renderer.hpp"
#include "engine/output/png_file.hpp"
#include "viz/synthetic_particles.hpp"

namespace firn::app {
namespace {

struct BenchRenderOptions {
  long particles = 100000;
  int width = 1280, height = 720, frames = 7;
  std::string gl, png;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void bench_render(const BenchRenderOptions& o) {
  // A cube of side 0.2 m standing on the ground, in three material layers.
  const viz::SyntheticParticles block = viz::jittered_block(o.particles, 0.2, {0, 0.0, 0});
  viz::RenderSettings s;
  s.width = o.width, s.height = o.height;
  s.particle_spacing = block.spacing;
  s.sphere_radius = 0.6 * block.spacing;
  s.domain_min = {-0.1, 0, -0.1}, s.domain_max = {0.3, 0.3, 0.3};
  viz::FrameScene scene;
  scene.positions = block.columns();
  const std::size_t n = scene.positions.count;
  for (std::size_t m = 0; m < 3; ++m) scene.ranges.push_back({m * n / 3, (m + 1) * n / 3, viz::default_material_color(int(m))});

  const auto context = viz::make_gl_context(viz::parse_gl_api(o.gl));
  viz::FrameRenderer renderer(*context, s);
  const viz::Camera camera = viz::frame_camera(s, viz::position_bounds(scene.positions));
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::vector<double> total, draw, png;
  std::size_t png_bytes = 0;
  renderer.render(scene, camera);  // warm-up: shader compilation, first allocations
  const std::clock_t cpu0 = std::clock();
  for (int f = 0; f < o.frames; ++f) {
    const auto t0 = Clock::now();
    const Image image = renderer.render(scene, camera);
    const auto t1 = Clock::now();
    png_bytes = encode_png(image).size();
    const auto t2 = Clock::now();
    draw.push_back(ms(t0, t1)), png.push_back(ms(t1, t2)), total.push_back(ms(t0, t2));
  }
  const double cpu_ms = 1e3 * double(std::clock() - cpu0) / CLOCKS_PER_SEC / o.frames;
  if (!o.png.empty()) write_png(o.png, renderer.render(scene, camera));
  const char* lp = std::getenv("LP_NUM_THREADS");
  std::printf("gl %s\nlp_num_threads %s\nparticles %zu\nwidth %d\nheight %d\nframes %d\n",
              context->description().c_str(), lp ? lp : "default", n, o.width, o.height, o.frames);
  std::printf("render_ms %.2f\npng_ms %.2f\npng_bytes %zu\ncpu_ms_per_frame %.2f\nms_per_frame %.2f\n", median(draw),
              median(png), png_bytes, cpu_ms, median(total));
}

}  // namespace

void add_bench_render_command(CLI::App& bench) {
  auto o = std::make_shared<BenchRenderOptions>();
  CLI::App* c = bench.add_subcommand("render", "time the sphere renderer on a synthetic particle set");
  c->add_option("--particles", o->particles, "particles")->check(CLI::PositiveNumber)->capture_default_str();
  c->add_option("--width", o->width, "image width")->check(CLI::Range(16, 8192))->capture_default_str();
  c->add_option("--height", o->height, "image height")->check(CLI::Range(16, 8192))->capture_default_str();
  c->add_option("--frames", o->frames, "timed frames (the median is reported)")->check(CLI::PositiveNumber)
      ->capture_default_str();
  c->add_option("--gl", o->gl, "OpenGL context: egl or osmesa")->check(CLI::IsMember({"egl", "osmesa"}));
  c->add_option("--png", o->png, "also write one frame to this PNG file");
  c->callback([o]() {
    try {
      bench_render(*o);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "firn bench render: %s\n", e.what());
      set_exit_status(1);
    }
  });
}

}  // namespace firn::app
