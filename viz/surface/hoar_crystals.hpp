// Hexagonal "surface hoar" crystals (thesis sections 4.2 and 5.3) placed on material-space sites,
// so the same piece of snow carries the same crystals from frame to frame.
//
// Sites: the rest-space lattice of spacing crystal_spacing * h; cell q holds one site at a hashed
// position inside it and carries a crystal with probability crystal_probability (hash of q). Each
// surface triangle lies in the cell of its rest-space centroid; of the triangles in an occupied
// cell, the one whose rest centroid is nearest the site (ties: lowest index) gets the crystal.
// The crystal sits at the image of the site projected onto that triangle (mapped from rest to
// current coordinates by the triangle's own affine map), its axis is the triangle normal tilted by
// a hashed angle, its hexagon rotated to follow a hashed material direction through the same map,
// and its size is hashed: all functions of q and the mesh near the site, none of the frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/surface_params.hpp"

namespace firn::surface {

// Needs positions and rest positions; h is the sampling spacing (m). Crystals come in triangle order.
std::vector<HoarCrystal> place_hoar_crystals(const SurfaceMesh& mesh, const SurfaceParams& params, double h);

// Closed hexagonal prisms for the crystals: 12 shared vertices and 20 outward triangles each,
// appended to `positions`, `normals` and `triangles` (a separate closed component per crystal).
void append_crystal_prisms(const std::vector<HoarCrystal>& crystals, std::vector<Vec3f>& positions,
                           std::vector<Vec3f>& normals, std::vector<std::uint32_t>& triangles);

}  // namespace firn::surface
