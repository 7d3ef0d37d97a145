#pragma once
// A style's palette (scene::Palette) applied to an object colour: its hue kept, its saturation
// and value (HSV) the style's. Black and greys stay grey.
#include <glm/glm.hpp>

#include "scene/style_def.h"

namespace bz::render {

glm::vec3 palette_colour(const scene::Palette& palette, glm::vec3 colour);

}  // namespace bz::render
