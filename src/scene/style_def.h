#pragma once
// A style as data: which fill pass, which line pass, the stroke parameters, bloom or none,
// paper or a black screen, and how the HUD sits on it. Plain data (no GL): the style table
// (scene/style.h) fills it, the renderer builds its frame from it in one place
// (render/frame_passes.cpp); nothing else in the renderer asks which style it is drawing.
#include <cstdint>
#include <glm/glm.hpp>

namespace bz::scene {

enum class Style : std::uint8_t;  // scene/style.h

enum class FillPass {
    none,     // depth prepass only: the lines float on black (vector)
    toon,     // cel bands from a light direction (Castro & Macedo)
    pop_art,  // flat diffuse colour with halftone Ben-Day dots (Olejnik & Litchmore)
    paper,    // the object is the paper itself: it hides what is behind it (sketch, halo)
};

enum class LinePass {
    beam,     // glowing vector-monitor lines with the spine test (pass_lines)
    outline,  // solid ink outlines of a set width (toon, pop-art)
    sketch,   // jittered, overlapping pencil strokes seeded per edge
    halo,     // silhouette strokes with soft halos over a shrunk-mesh depth mask
};

// How an outline quad sits on its edge (Castro & Macedo).
enum class OutlineQuad {
    centred,    // extruded to both sides, visibility by the spine test
    one_sided,  // extruded outward only, depth-tested against the fill
};

struct OutlineParams {
    float width_px = 2.0f;  // the quad's full width
    float overdraw = 0.0f;  // extension at both ends, as a fraction of the edge length
    OutlineQuad quad = OutlineQuad::centred;
    glm::vec3 ink{0.02f, 0.02f, 0.03f};
};

struct SketchParams {
    int strokes_per_edge = 3;        // overlapping strokes with different offsets
    float jitter_px = 2.5f;          // end point displacement from the noise texture
    float min_significance = 0.12f;  // edges whose normals barely face the light are dropped
    float width_px = 1.2f;
    float darkness = 0.45f;  // one stroke's opacity; overlaps darken
};

struct HaloParams {
    float inner_px = 2.0f;        // the stroke reaches this far inside the silhouette
    float outer_px = 2.5f;        // ... and this far outside
    float halo_px = 12.0f;        // the soft halo's reach outside
    int strokes_per_edge = 3;     // strokes in one pass, each with its own offset
    float shrink_px = 3.0f;       // depth mask: the mesh shrunk along its normals by this many
                                  // pixels (at each vertex's depth)
    bool cubic_smoothing = true;  // bend each silhouette edge to meet the vertex normals
};

// How the HUD (text, radar, notices) is drawn over a style's picture.
struct HudTheme {
    // false: beam lines that glow on the dark screen (the vector look). true: ink on paper,
    // each HUD line darkened to at most `ink_luminance` in its own hue and laid over a
    // paper-toned halo `halo_px` wide, so it reads against fills and strokes behind it.
    bool ink = false;
    float ink_luminance = 0.06f;  // relative luminance (WCAG) of the darkest ink colour
    float halo_px = 2.0f;         // the paper halo's reach around each HUD stroke
};

// The objects' colours in a style. The game colours its objects for the vector screen
// (saturated, HDR greens and reds); a style with `remap` keeps each colour's hue and sets its
// saturation and value (HSV) to the style's, so enemies, shells, the saucer and wrecks sit in
// the same tones as the rest of the picture.
struct Palette {
    bool remap = false;
    float saturation = 0.5f;
    float value = 0.8f;
};

// Hidden lines in a stroke of their own, as technical drawings draw them: `levels` > 0 keeps
// them up to that occlusion level (geo::kMaxOcclusionLevel at most), `width_scale` as wide as
// the visible stroke and dashed. The dash pattern starts at each edge's first end, so it stays
// on the line as the camera moves. Drawn by the vector output (render --svg) and on the GPU
// (render/styles/pass_outline.cpp, from the peeled occlusion layers).
struct HiddenLines {
    int levels = 0;
    float width_scale = 0.5f;
    float dash_px = 6.0f;
    float gap_px = 4.0f;
};

struct StyleDef {
    Style id{};
    FillPass fill = FillPass::none;
    LinePass lines = LinePass::beam;
    bool hidden_lines_removed = true;  // false: vector-xray
    bool bloom = true;
    glm::vec3 background{0.0f};              // paper tone (display-referred RGB) for filled styles
    glm::vec3 light_dir{-0.4f, 0.6f, 0.7f};  // view space, towards the light
    int toon_bands = 3;                      // 2..4
    float halftone_cell_px = 7.0f;           // Ben-Day dot grid spacing
    float paper_tint = 0.0f;                 // paper fill: share of the object's colour in it
    OutlineParams outline;
    SketchParams sketch;
    HaloParams halo;
    HiddenLines hidden;
    HudTheme hud;
    Palette palette;
};

}  // namespace bz::scene
