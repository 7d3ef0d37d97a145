#include "game/default_level.h"

#include <cmath>

#include "core/rng.h"
#include "game/assets/backdrop.h"

namespace bz::game {

level::Level default_level() {
    level::Level lv;
    lv.name = "Built-in plain";
    lv.author = "beamzone";
    lv.file = kBuiltinLevelName;
    lv.field_size = 400.0;
    lv.wrap = true;
    lv.backdrop.mountains = backdrop::default_mountains();

    // A fixed generator makes the same layout every time without a table of numbers.
    Rng rng(20260101);
    const char* kinds[] = {"cube", "pyramid", "tall_box", "short_box", "cube", "pyramid"};
    const glm::vec3 colors[] = {{0.2f, 1.0f, 0.3f}, {0.25f, 0.95f, 0.35f}, {0.3f, 1.0f, 0.45f}};
    while (lv.obstacles.size() < 48) {
        const double x = rng.uniform(-190.0, 190.0);
        const double z = rng.uniform(-190.0, 190.0);
        if (std::hypot(x, z) < 25.0) continue;  // open ground around the start
        bool crowded = false;
        for (const level::ObjectDesc& o : lv.obstacles) {
            if (std::hypot(o.position.x - x, o.position.z - z) < 18.0) crowded = true;
        }
        if (crowded) continue;
        level::ObjectDesc o;
        o.kind = kinds[rng.below(static_cast<std::uint32_t>(std::size(kinds)))];
        o.position = {x, 0.0, z};
        o.heading_deg = std::floor(rng.uniform(0.0, 90.0));
        o.color = colors[rng.below(3)];
        o.pos.file = kBuiltinLevelName;
        lv.obstacles.push_back(o);
    }
    // One landmark straight ahead of the start, so the first view is never empty.
    level::ObjectDesc landmark;
    landmark.kind = "pyramid";
    landmark.position = {0.0, 0.0, -40.0};
    landmark.pos.file = kBuiltinLevelName;
    lv.obstacles.push_back(landmark);
    return lv;
}

}  // namespace bz::game
