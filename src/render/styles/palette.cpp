#include "render/styles/palette.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

glm::vec3 palette_colour(const scene::Palette& palette, glm::vec3 colour) {
    if (!palette.remap) return colour;
    const float hi = std::max({colour.r, colour.g, colour.b});
    const float lo = std::min({colour.r, colour.g, colour.b});
    const float v = palette.value;
    if (hi <= 0.0f || (hi - lo) / hi < 0.05f) return glm::vec3(v);  // grey: no hue to keep
    // The hue, as the standard HSV hexcone sector and position.
    const float d = hi - lo;
    float h;
    if (hi == colour.r) {
        h = std::fmod((colour.g - colour.b) / d + 6.0f, 6.0f);
    } else if (hi == colour.g) {
        h = (colour.b - colour.r) / d + 2.0f;
    } else {
        h = (colour.r - colour.g) / d + 4.0f;
    }
    const float s = palette.saturation;
    const float c = v * s;
    const float x = c * (1.0f - std::abs(std::fmod(h, 2.0f) - 1.0f));
    const float m = v - c;
    glm::vec3 rgb;
    switch (static_cast<int>(h) % 6) {
        case 0:
            rgb = {c, x, 0.0f};
            break;
        case 1:
            rgb = {x, c, 0.0f};
            break;
        case 2:
            rgb = {0.0f, c, x};
            break;
        case 3:
            rgb = {0.0f, x, c};
            break;
        case 4:
            rgb = {x, 0.0f, c};
            break;
        default:
            rgb = {c, 0.0f, x};
            break;
    }
    return rgb + glm::vec3(m);
}

}  // namespace bz::render
