#include "core/error.h"
#include "core/text/printable.h"
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
        // MAME's vector renderer with its monochrome vector preset (ini/presets/vector-mono.ini):
        // beam width 1 to 4 (in 1/512 of the screen's smaller side: 2.11 to 8.44 pixels on
        // 1080 lines, kMameBeamWidthUnitPx), intensity weight 0.75, flicker 0.15, additive
        // lines, ends lengthened by 3/8 of the width (vector.cpp), a 9-level bloom chain with
        // its weights.
        b.blend = BeamBlend::additive;
        b.intensity_width = true;
        b.width_min_px = 1.0f * kMameBeamWidthUnitPx;
        b.width_max_px = 4.0f * kMameBeamWidthUnitPx;
        b.end_lengthening = 0.375f;
        b.intensity_weight = 0.75f;
        b.nominal = 0.75f;
        b.flicker = 0.15f;
        // Beyond MAME: a dot gets up to 3x the brightness of a long vector, an overdriven beam
        // spreads, and the phosphor glows on for a few frames.
        b.dwell_px = 6.0f;
        b.dwell_max = 3.0f;
        b.defocus = 1.5f;
        b.phosphor = PhosphorDecay::exponential;
        b.persistence_ms = 10.0f;  // a 60 Hz frame later 19% is left: a short trail, no ghosts
        b.bloom = BloomKind::mip_chain;
        b.mip_weights = {1.00f, 0.48f, 0.32f, 0.24f, 0.16f, 0.24f, 0.32f, 0.48f, 0.64f};
        b.bloom_threshold = 0.25f;
        b.bloom_knee = 0.2f;
        // Without it the widest levels light every pixel of a dense scene (Bernardoni 2018's
        // hallway: 100% of pixels above 1/255). The lengthened ends add light where lines meet, and
        // with 0.02 `high` (whose chain starts at half resolution, where a thin line is
        // averaged over fewer pixels than at quarter, so more of it passes the threshold)
        // lit 70.3% of the hallway; 0.025 brings it to
        // 63.0% and fast and balanced to 55.7% (the goal: at most 70%; tools/haze), and the
        // floor grating stays lines on black.
        b.bloom_floor = 0.025f;
        return b;
    }
    throw UserError("unknown beam look '" + printable(name) + "' (use classic or mame)");
}

}  // namespace bz::render
