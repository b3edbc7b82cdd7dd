// A running simulation's frame (engine/scene/frame_description.hpp) as the renderer takes it:
// the position columns as they are, the colour field computed into `field_storage`, colliders as
// signed distances at the frame's time.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/frame_description.hpp"
#include "viz/render_frame.hpp"

namespace firn::viz {

// `color_by`: "material" or a field of viz/color_field.hpp.
RenderFrame engine_frame(const FrameDescription& f, const std::string& color_by, std::vector<float>& field_storage);

}  // namespace firn::viz
