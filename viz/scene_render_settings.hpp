// The renderer's settings from a scene's [render] section, its domain, lattice and materials.
#pragma once

#include "engine/scene/scene.hpp"
#include "viz/render_settings.hpp"

namespace firn::viz {

RenderSettings scene_render_settings(const SceneSpec& scene);

}  // namespace firn::viz
