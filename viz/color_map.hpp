// Colour maps for scalar fields (sRGB components in [0, 1]) and the default material palette.
#pragma once

#include <string>

#include "engine/output/image.hpp"

namespace firn::viz {

enum class ColorMap { viridis, diverging };

// "viridis" or "diverging"; throws std::invalid_argument otherwise.
ColorMap parse_color_map(const std::string& name);

// The map at t in [0, 1] (clamped).
Rgb color_map_rgb(ColorMap map, double t);

// A distinct colour for material index m (cycles after the palette's length).
Rgb default_material_color(int m);

}  // namespace firn::viz
