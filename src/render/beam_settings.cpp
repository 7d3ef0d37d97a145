#include "core/error.h"
#include "render/settings.h"

namespace bz::render {

const std::vector<std::string>& beam_look_names() {
    static const std::vector<std::string> names = {"classic", "mame"};
    return names;
}

BeamSettings beam_look(std::string_view name) {
    BeamSettings b;
    b.look = std::string(name);
    if (name == "classic") return b;  // the defaults: constant width, GL_MAX, Gaussian bloom
    if (name == "mame") {
        // MAME's vector renderer with its monochrome vector preset: beam width 1 to 4 (MAME
        // measures it in 1/512 of the screen: 2.1 to 8.4 pixels on 1080 lines), intensity
        // weight 0.75, flicker 0.15, additive lines, a 9-level bloom chain with its weights.
        b.blend = BeamBlend::additive;
        b.intensity_width = true;
        b.width_min_px = 2.1f;
        b.width_max_px = 8.4f;
        b.intensity_weight = 0.75f;
        b.nominal = 0.75f;
        b.flicker = 0.15f;
        // Beyond MAME: a dot gets up to 3x the brightness of a long vector, an overdriven beam
        // spreads, and the phosphor glows on for a few frames.
        b.dwell_px = 6.0f;
        b.dwell_max = 3.0f;
        b.defocus = 1.5f;
        b.phosphor = PhosphorDecay::exponential;
        b.persistence_ms = 16.0f;
        b.bloom = BloomKind::mip_chain;
        b.mip_weights = {1.00f, 0.48f, 0.32f, 0.24f, 0.16f, 0.24f, 0.32f, 0.48f, 0.64f};
        b.bloom_threshold = 0.25f;
        b.bloom_knee = 0.2f;
        return b;
    }
    throw UserError("unknown beam look '" + std::string(name) + "' (use classic or mame)");
}

}  // namespace bz::render
