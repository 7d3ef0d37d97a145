#pragma once
// Where the HUD puts things, in HUD units (origin at the screen centre, y up, 1 = half the
// screen height, x spans -aspect..aspect). Tests check the drawn lines against these regions.
#include <algorithm>
#include <glm/glm.hpp>

namespace bz::game::hud {

inline constexpr glm::vec2 kRadarCenter{0.0f, 0.74f};
inline constexpr float kRadarRadius = 0.2f;
inline constexpr float kReticleHalfWidth = 0.12f;
inline constexpr float kReticleHalfHeight = 0.2f;
inline constexpr float kTextHeight = 0.045f;
inline constexpr float kMargin = 0.06f;
inline constexpr float kTopLine = 0.88f;     // baseline of the first status line
inline constexpr float kSecondLine = 0.79f;  // baseline of the second
inline constexpr float kLivesLine = 0.68f;   // bottom of the reserve-tank icons

// The HUD band: the top strip above this holds radar, messages, score and lives, and the
// scene is not drawn into it (FrameList::view_top).
inline constexpr float kBandBottom = 0.52f;

// A region of the screen that one kind of HUD content owns; nothing else draws into it.
struct Box {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};
    bool contains(glm::vec2 p, float slack = 1e-4f) const {
        return p.x >= min.x - slack && p.x <= max.x + slack && p.y >= min.y - slack &&
               p.y <= max.y + slack;
    }
    float width() const { return max.x - min.x; }
    float height() const { return max.y - min.y; }
};

// The regions for a screen `aspect` wide (x spans -aspect..aspect). In the band, left to right:
// messages ("ENEMY IN RANGE"), the radar, score over lives. Under the band: the error box.
// Along the bottom: notices (screenshot saved, volume), the frame-rate readout, and the footer
// line (key hints, replay banner).
inline constexpr float kRadarGap = 0.03f;  // between the radar and its neighbours
inline Box radar_box() {
    const glm::vec2 r{kRadarRadius + 0.015f};
    return {kRadarCenter - r, kRadarCenter + r};
}
inline Box messages_box(float aspect) {
    return {{-aspect + kMargin, kBandBottom + 0.08f},
            {kRadarCenter.x - kRadarRadius - kRadarGap, 1.0f - 0.04f}};
}
inline Box score_box(float aspect) {
    return {{kRadarCenter.x + kRadarRadius + kRadarGap, kSecondLine - 0.03f},
            {aspect - kMargin, 1.0f - 0.04f}};
}
inline Box lives_box(float aspect) {
    return {{kRadarCenter.x + kRadarRadius + kRadarGap, kBandBottom + 0.08f},
            {aspect - kMargin, kSecondLine - 0.03f}};
}
inline Box error_box(float aspect) {
    return {{-aspect + kMargin, kReticleHalfHeight + 0.04f},
            {aspect - kMargin, kBandBottom - 0.02f}};
}
// The readout's strip is one line of text high, so larger text (the player's text size,
// 1 to 2) makes it taller and the notices above it start higher. Both stack on the footer's
// top: the one-line footer's (kFooterTop) on the title, pause and play screens; the --edit
// screen's footer holds more lines and grows with the text size (app/play/edit_footer.h).
inline constexpr float kReadoutGrowth = 0.055f;  // per unit of text size over 1
inline constexpr float kFooterTop = -0.88f;
// A footer taller than one line is the --edit screen's, which has no reticle (only a small
// cross at the centre): its notices may rise this far, to keep room for two of them at 2x.
inline constexpr float kEditNoticeTop = -0.08f;
inline Box notice_box(float aspect, float text_scale = 1.0f, float footer_top = kFooterTop) {
    const float lift = footer_top - kFooterTop;
    return {{-aspect + kMargin, -0.818f + (text_scale - 1.0f) * kReadoutGrowth + lift},
            {aspect - kMargin, std::clamp(-0.56f + lift, -0.56f, kEditNoticeTop)}};
}
// The frame-rate readout's own strip, between the notices and the footer: it never covers the
// key hints of the title, pause and edit screens.
inline Box readout_box(float aspect, float text_scale = 1.0f, float footer_top = kFooterTop) {
    const float lift = footer_top - kFooterTop;
    return {{-aspect + kMargin, -0.875f + lift},
            {aspect - kMargin, -0.822f + (text_scale - 1.0f) * kReadoutGrowth + lift}};
}
inline Box footer_box(float aspect) {
    return {{-aspect + kMargin, -0.98f}, {aspect - kMargin, kFooterTop}};
}

// The arcade's colour overlay: the top strip (radar, messages, score) red, the rest green.
inline constexpr glm::vec3 kRed{1.0f, 0.22f, 0.15f};
inline constexpr glm::vec3 kGreen{0.2f, 1.0f, 0.3f};
inline constexpr glm::vec3 kWhite{0.85f, 1.0f, 0.9f};

}  // namespace bz::game::hud
