// Binary little-endian PLY (Turk 1994 format, as Blender, MeshLab and ParaView read it): vertex
// elements with float x y z nx ny nz, face elements with a uchar count and uint indices. The surface
// comes first, then each hoar crystal as its own closed hexagonal prism (hoar_crystals.hpp), so
// the file is one closed manifold per component. Written atomically (engine/output/atomic_file.hpp).
#pragma once

#include <string>

#include "viz/surface/surface_mesh.hpp"

namespace firn::surface {

// Throws std::runtime_error when the file cannot be written.
void write_ply(const std::string& path, const SurfaceMesh& mesh);

}  // namespace firn::surface
