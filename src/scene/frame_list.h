#pragma once
// What one frame shows, as plain data: the game and level code fill it, the renderer draws it.
// Nothing here knows about GL, and the renderer never learns what a tank is.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/style.h"

namespace bz::scene {

using MeshId = std::uint32_t;  // index into a MeshLibrary

struct Camera {
    glm::dvec3 eye{0.0, 2.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 60.0;  // vertical field of view
    double near = 0.1;
    double far = 5000.0;
};

// One object instance. The model matrix is double precision so that scenes far from the
// origin render camera-relative without jitter.
struct DrawItem {
    MeshId mesh = 0;
    glm::dmat4 model{1.0};
    glm::vec3 color{0.2f, 1.0f, 0.3f};  // linear RGB; > 1 is allowed (HDR)
    float intensity = 1.0f;
    bool occluder = true;  // writes the depth prepass (debris and shells may choose not to)
    bool smooth = false;   // filled styles: shade with smooth vertex normals, not flat faces
};

// A 2D line for the HUD, in HUD units: origin at the screen centre, y up, 1 unit = half the
// screen height (so x spans -aspect..+aspect). Drawn with the same beam shading and bloom.
struct HudLine {
    glm::vec2 a{0.0f};
    glm::vec2 b{0.0f};
    glm::vec3 color{0.2f, 1.0f, 0.3f};
    float intensity = 1.0f;
};

// The first two styles' old name; scene::Style (scene/style.h) lists every look.
using LineStyle = Style;

struct FrameList {
    Camera camera;
    std::vector<DrawItem> items;
    std::vector<HudLine> hud;
    Style style = Style::vector;
    // When this frame is shown, in seconds of game time (only differences matter: phosphor
    // decay and frame holding follow it), and the seed of its beam flicker. Both come from the
    // simulation, so replays and benchmarks draw the same pictures.
    double time_s = 0.0;
    std::uint32_t seed = 0;
    // NDC y (= HUD units) above which the scene's lines are not drawn: the play HUD's band,
    // as the 1980 cabinet's periscope view ends under its radar strip. 1: the whole screen.
    float view_top = 1.0f;
    // The picture has no past: the camera jumped, or the level was (re)loaded. The renderer
    // forgets the view's history (phosphor trails, glow) before drawing it.
    bool cut = false;
};

}  // namespace bz::scene
