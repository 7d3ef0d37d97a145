// The cracked windscreen when the tank is hit: jagged cracks running from the point of impact
// to the screen edges, with a few branches and a ring of shattered glass round the hole.
#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "core/rng.h"
#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"

namespace bz::game::hud {

namespace {

constexpr double kGrowSeconds = 0.35;

// Clips a segment to the screen rectangle (Liang-Barsky); false when nothing is left.
bool clip(glm::vec2& a, glm::vec2& b, float xmax, float ymax) {
    float t0 = 0.0f, t1 = 1.0f;
    const glm::vec2 d = b - a;
    const float p[] = {-d.x, d.x, -d.y, d.y};
    const float q[] = {a.x + xmax, xmax - a.x, a.y + ymax, ymax - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0f) {
            if (q[i] < 0.0f) return false;
            continue;
        }
        const float t = q[i] / p[i];
        if (p[i] < 0.0f) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    const glm::vec2 a0 = a;
    a = a0 + d * t0;
    b = a0 + d * t1;
    return true;
}

}  // namespace

void cracks(std::vector<scene::HudLine>& out, std::uint32_t seed, double seconds, double aspect) {
    Rng rng(seed, 77);
    const auto xmax = static_cast<float>(aspect);
    const float grown = static_cast<float>(std::clamp(seconds / kGrowSeconds, 0.0, 1.0));
    const glm::vec2 hit{static_cast<float>(rng.uniform(-0.4, 0.4) * aspect),
                        static_cast<float>(rng.uniform(-0.35, 0.35))};
    const glm::vec3 color = kWhite;
    auto emit = [&](glm::vec2 a, glm::vec2 b, float intensity) {
        if (clip(a, b, xmax, 1.0f)) out.push_back({a, b, color, intensity});
    };

    // The hole: a ragged ring.
    const int ring = 9;
    glm::vec2 first{0.0f}, prev{0.0f};
    for (int i = 0; i <= ring; ++i) {
        const double a = 2.0 * kPi * i / ring;
        const float r = i == ring ? 0.0f : static_cast<float>(rng.uniform(0.03, 0.06));
        glm::vec2 p = i == ring ? first
                                : hit + r * glm::vec2(static_cast<float>(std::cos(a)),
                                                      static_cast<float>(std::sin(a)));
        if (i == 0) first = p;
        if (i > 0) emit(prev, p, 2.5f);  // overdriven: the mame beam defocuses the hole's rim
        prev = p;
    }

    // Main cracks: jagged polylines outwards, each with a chance of a branch.
    const int count = 8 + static_cast<int>(rng.below(4));
    for (int c = 0; c < count; ++c) {
        double heading = 2.0 * kPi * (c + rng.uniform(-0.3, 0.3)) / count;
        glm::vec2 p = hit;
        const float total = static_cast<float>(rng.uniform(1.2, 2.6));
        const float shown = total * grown;
        // The random walk draws the same numbers however far it has grown, so a crack keeps
        // its shape while it spreads.
        float walked = 0.0f;
        while (walked < total) {
            const float step =
                std::min(static_cast<float>(rng.uniform(0.08, 0.22)), total - walked);
            heading += rng.uniform(-0.35, 0.35);
            const glm::vec2 dir{static_cast<float>(std::cos(heading)),
                                static_cast<float>(std::sin(heading))};
            const glm::vec2 q = p + step * dir;
            if (walked < shown) emit(p, p + std::min(step, shown - walked) * dir, 1.0f);
            const bool branch = rng.below(5) == 0;
            const double bh = heading + (rng.below(2) ? 0.6 : -0.6);
            const float bl = static_cast<float>(rng.uniform(0.05, 0.18));
            if (branch && walked + step <= shown) {
                emit(q,
                     q + bl * glm::vec2(static_cast<float>(std::cos(bh)),
                                        static_cast<float>(std::sin(bh))),
                     0.7f);
            }
            p = q;
            walked += step;
            if (std::abs(p.x) > xmax || std::abs(p.y) > 1.0f) break;
        }
    }
}

}  // namespace bz::game::hud
