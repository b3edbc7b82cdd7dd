// The snow surface end to end: a ball of particles reconstructs to a closed manifold sphere of the
// right size; a rigidly translated ball gives the translated mesh with the same noise and crystals
// (temporal coherence); the PLY file reads back closed and manifold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "engine/particle_storage.hpp"
#include "kernels/backend/openmp.hpp"
#include "viz/surface/mesh_topology.hpp"
#include "viz/surface/ply_writer.hpp"
#include "viz/surface/reconstruct_surface.hpp"

namespace firn::surface {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A ball of radius `radius` about `centre` filled like a scene body: the lattice of spacing
// `spacing` (cell centres), each point jittered by up to 0.1 spacing, volume spacing^3 each.
ParticleStorage<double> particle_ball(double radius, double spacing, const double centre[3]) {
  std::vector<double> points;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.1 * spacing, 0.1 * spacing);
  const int n = int(std::ceil(radius / spacing));
  for (int i = -n; i < n; ++i)
    for (int j = -n; j < n; ++j)
      for (int k = -n; k < n; ++k) {
        const double p[3] = {(i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing};
        if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] >= radius * radius) continue;
        for (int d = 0; d < 3; ++d) points.push_back(centre[d] + p[d] + jitter(random));
      }
  ParticleStorage<double> storage;
  storage.enable(Attribute::x0);
  storage.resize(points.size() / 3);
  ParticleView<double> pv = storage.view();
  for (std::size_t p = 0; p < pv.n; ++p) {
    for (int d = 0; d < 3; ++d) pv.x[d][p] = pv.x0[d][p] = points[3 * p + d];
    pv.vol0[p] = spacing * spacing * spacing;
  }
  return storage;
}

SurfaceParams clean_params(double dx) {
  SurfaceParams params;
  params.simulation_dx = dx;
  params.noise_amplitude = 0;
  params.crystals = false;
  return params;
}

struct SphereFit {
  double volume_error;       // (V_mesh - V) / V
  double mean_radius_error;  // (mean |x_v - c| - R) / spacing
  double max_radius_deviation;  // max |(|x_v - c| - R)| / spacing
};

SphereFit fit_sphere(const SurfaceMesh& mesh, double radius, double spacing, const double centre[3]) {
  double sum = 0, worst = 0;
  for (const Vec3f& p : mesh.positions) {
    const double r = std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    sum += r;
    worst = std::fmax(worst, std::fabs(r - radius));
  }
  const double exact_volume = 4 * kPi / 3 * radius * radius * radius;
  return {(enclosed_volume(mesh.positions, mesh.triangles) - exact_volume) / exact_volume,
          (sum / double(mesh.vertex_count()) - radius) / spacing, worst / spacing};
}

// Balls of radius 15 and 11.3 particle spacings s (8 particles per simulation cell: s = dx/2),
// sampled at h = dx/2, the second off the lattice's symmetry. Tolerances, from the error sources:
// - the particles say where the boundary is only to within their spacing: an outer particle sits
//   anywhere from 0 to s inside the surface (plus the 0.1 s jitter), so a single vertex may be off
//   by about s/2 plus the field's bias: we allow s for the largest deviation;
// - those placement errors have zero mean over the ~4 pi R^2 / s^2 boundary cells (standard error
//   of the mean about 0.29 s / 50), so the mean radius error is the field's bias: the kernel average
//   over the outer layers of a curved surface, with r = s/2 and R = 2h, pulls the zero crossing
//   inward by a fraction of a spacing, and uniform smoothing shrinks a sphere by about
//   iterations lambda e^2 / (4 R_ball) = 0.01 s (edge length e ~ 0.7 h). We allow half of the
//   single-vertex bound, s/4, for the mean radius and, to first order (dV/V = 3 dR/R), 3 (s/4)/R
//   for the volume. Measured without smoothing over 36 balls (R = 8 ... 23 s, three centres each):
//   mean radius error -0.05 to -0.15 s, largest single deviation 0.70 s.
TEST(SurfaceMesh, ParticleBallReconstructsToTheSphere) {
  const double dx = 0.02, spacing = dx / 2;
  struct Ball {
    double radius, centre[3];
  };
  for (const Ball& ball_shape : {Ball{15 * spacing, {0.5, 0.5, 0.5}}, Ball{11.3 * spacing, {0.5031, 0.4977, 0.5012}}}) {
    ParticleStorage<double> ball = particle_ball(ball_shape.radius, spacing, ball_shape.centre);
    for (Smoothing smoothing : {Smoothing::uniform_laplacian, Smoothing::taubin}) {
      SurfaceParams params = clean_params(dx);
      params.smoothing = smoothing;
      const SurfaceMesh mesh = reconstruct_surface(ball.view(), params, backend::OpenMP{});
      const MeshTopology topology = analyse_topology(mesh.triangles, mesh.vertex_count());
      EXPECT_TRUE(topology.closed_manifold());
      EXPECT_EQ(topology.euler_characteristic(), 2);
      const SphereFit fit = fit_sphere(mesh, ball_shape.radius, spacing, ball_shape.centre);
      std::printf("sphere R = %.1f s (%s smoothing): %zu particles, %zu vertices, %zu triangles, volume error %+.4f, "
                  "mean radius error %+.4f s, largest radius deviation %.4f s\n",
                  ball_shape.radius / spacing, smoothing == Smoothing::taubin ? "Taubin" : "uniform", ball.size(),
                  mesh.vertex_count(), mesh.triangle_count(), fit.volume_error, fit.mean_radius_error,
                  fit.max_radius_deviation);
      EXPECT_LT(std::fabs(fit.mean_radius_error), 1.0 / 4);
      EXPECT_LT(std::fabs(fit.volume_error), 3 * (spacing / 4) / ball_shape.radius);
      EXPECT_LT(fit.max_radius_deviation, 1.0);
    }
  }
}

// The surface of a ball at dx = 0.02 with every default: smoothing, noise, crystals.
SurfaceMesh default_ball_surface(double radius) {
  const double dx = 0.02, centre[3] = {0.5, 0.5, 0.5};
  ParticleStorage<double> ball = particle_ball(radius, dx / 2, centre);
  SurfaceParams params;
  params.simulation_dx = dx;
  return reconstruct_surface(ball.view(), params, backend::OpenMP{});
}

TEST(SurfaceMesh, DefaultSurfaceWithNoiseAndCrystalsIsClosed) {
  const SurfaceMesh mesh = default_ball_surface(0.1);
  const MeshTopology topology = analyse_topology(mesh.triangles, mesh.vertex_count());
  EXPECT_TRUE(topology.closed_manifold());
  EXPECT_EQ(topology.euler_characteristic(), 2);
  EXPECT_GT(mesh.crystals.size(), 20u);
  for (const Vec3f& n : mesh.normals) EXPECT_NEAR(norm(n), 1.0f, 1e-5f);
}

double largest_difference(const Vec3f& a, const Vec3f& b, const double shift[3]) {
  double worst = 0;
  for (int d = 0; d < 3; ++d) worst = std::fmax(worst, std::fabs(double(a[d]) - double(b[d]) - shift[d]));
  return worst;
}

// Temporal coherence: the same snow moved rigidly by whole sampling cells gives the same mesh moved
// by the same amount, with the same noise and the same crystals, because both are seeded by the
// rest positions x0, which a motion does not change. The control case moves x0 instead of x (other
// material, same place): its noise and crystals must differ, so the test fails if they were seeded
// by anything but x0.
TEST(SurfaceMesh, TranslatedSnowKeepsItsNoiseAndCrystals) {
  const double dx = 0.02, h = dx / 2, centre[3] = {0.5, 0.5, 0.5};
  const double shift[3] = {3 * h, -5 * h, 7 * h}, none[3] = {0, 0, 0};
  ParticleStorage<double> ball = particle_ball(0.1, h, centre);
  ParticleStorage<double> moved = particle_ball(0.1, h, centre);
  ParticleStorage<double> other_material = particle_ball(0.1, h, centre);
  for (std::size_t p = 0; p < ball.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      moved.view().x[d][p] += shift[d];
      other_material.view().x0[d][p] += shift[d];
    }
  SurfaceParams params;
  params.simulation_dx = dx;
  params.noise_amplitude = 0.3;  // grains larger than the round-off by far
  const backend::OpenMP omp;
  const SurfaceMesh a = reconstruct_surface(ball.view(), params, omp);
  const SurfaceMesh b = reconstruct_surface(moved.view(), params, omp);
  const SurfaceMesh c = reconstruct_surface(other_material.view(), params, omp);

  const double tolerance = 1e-4 * h;  // float round-off of coordinates near 0.5 m
  ASSERT_EQ(a.triangles, b.triangles);
  double position_error = 0, normal_error = 0, rest_error = 0;
  for (std::size_t v = 0; v < a.vertex_count(); ++v) {
    position_error = std::fmax(position_error, largest_difference(b.positions[v], a.positions[v], shift));
    normal_error = std::fmax(normal_error, largest_difference(b.normals[v], a.normals[v], none));
    rest_error = std::fmax(rest_error, largest_difference(b.rest_positions[v], a.rest_positions[v], none));
  }
  EXPECT_LT(position_error, tolerance);
  EXPECT_LT(normal_error, 1e-4);
  EXPECT_LT(rest_error, tolerance);
  ASSERT_GT(a.crystals.size(), 20u);
  ASSERT_EQ(a.crystals.size(), b.crystals.size());
  std::size_t moved_faces = 0;
  double centre_error = 0, direction_error = 0, size_error = 0;
  for (std::size_t k = 0; k < a.crystals.size(); ++k) {
    moved_faces += a.crystals[k].face != b.crystals[k].face;
    centre_error = std::fmax(centre_error, largest_difference(b.crystals[k].centre, a.crystals[k].centre, shift));
    direction_error = std::fmax(direction_error, largest_difference(b.crystals[k].axis, a.crystals[k].axis, none));
    direction_error = std::fmax(direction_error, largest_difference(b.crystals[k].tangent, a.crystals[k].tangent, none));
    size_error = std::fmax(size_error, std::fabs(b.crystals[k].radius - a.crystals[k].radius));
    size_error = std::fmax(size_error, std::fabs(b.crystals[k].height - a.crystals[k].height));
  }
  EXPECT_EQ(moved_faces, 0u);
  EXPECT_LT(centre_error, tolerance);
  EXPECT_LT(direction_error, 1e-4);
  EXPECT_LT(size_error, 1e-6 * h);

  // Control: other material coordinates, same place: different grains and crystals.
  ASSERT_EQ(a.triangles, c.triangles);
  double grain_difference = 0;
  for (std::size_t v = 0; v < a.vertex_count(); ++v)
    grain_difference = std::fmax(grain_difference, largest_difference(c.positions[v], a.positions[v], none));
  EXPECT_GT(grain_difference, 0.05 * h);
  std::size_t same_crystals = 0;
  for (const HoarCrystal& x : a.crystals)
    for (const HoarCrystal& y : c.crystals) same_crystals += x.face == y.face;
  EXPECT_LT(same_crystals, a.crystals.size() / 2);
}

TEST(SurfaceMesh, PlyFileReadsBackClosedAndManifold) {
  const SurfaceMesh mesh = default_ball_surface(0.08);
  ASSERT_GT(mesh.crystals.size(), 0u);
  const std::string path = testing::TempDir() + "firn_surface_round_trip.ply";
  write_ply(path, mesh);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in.good());
  std::string line;
  std::vector<std::string> header;
  while (std::getline(in, line) && line != "end_header") header.push_back(line);
  ASSERT_EQ(line, "end_header");
  ASSERT_GE(header.size(), 2u);
  EXPECT_EQ(header[0], "ply");
  EXPECT_EQ(header[1], "format binary_little_endian 1.0");
  std::size_t vertices = 0, faces = 0;
  for (const std::string& h : header) {
    std::sscanf(h.c_str(), "element vertex %zu", &vertices);
    std::sscanf(h.c_str(), "element face %zu", &faces);
  }
  // Each crystal is a closed hexagonal prism of 12 vertices and 20 triangles.
  EXPECT_EQ(vertices, mesh.vertex_count() + 12 * mesh.crystals.size());
  EXPECT_EQ(faces, mesh.triangle_count() + 20 * mesh.crystals.size());

  std::vector<float> vertex_data(6 * vertices);
  in.read(reinterpret_cast<char*>(vertex_data.data()), std::streamsize(vertex_data.size() * sizeof(float)));
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 97)
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(vertex_data[6 * v + d], mesh.positions[v][d]);
      EXPECT_EQ(vertex_data[6 * v + 3 + d], mesh.normals[v][d]);
    }
  std::vector<std::uint32_t> triangles;
  for (std::size_t f = 0; f < faces; ++f) {
    unsigned char count = 0;
    std::uint32_t index[3];
    in.read(reinterpret_cast<char*>(&count), 1);
    in.read(reinterpret_cast<char*>(index), sizeof(index));
    ASSERT_EQ(count, 3);
    triangles.insert(triangles.end(), index, index + 3);
  }
  ASSERT_TRUE(in.good());
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
  const MeshTopology topology = analyse_topology(triangles, vertices);
  EXPECT_TRUE(topology.closed_manifold());
  EXPECT_EQ(topology.euler_characteristic(), 2 * long(1 + mesh.crystals.size()));
  std::vector<Vec3f> positions(vertices);
  for (std::size_t v = 0; v < vertices; ++v) positions[v] = {{vertex_data[6 * v], vertex_data[6 * v + 1], vertex_data[6 * v + 2]}};
  EXPECT_GT(enclosed_volume(positions, triangles), 0);  // every component outward
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace firn::surface
