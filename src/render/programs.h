#pragma once
// Every shader program of the pipeline, built from one file per stage under shaders/.
#include <array>
#include <string>

#include "gl/program.h"
#include "render/settings.h"

namespace bz::render {

struct QuadPrograms {
    gl::Program sampled;
    gl::Program tested;
};

struct Programs {
    gl::Program prepass;
    gl::Program prepass_raster;   // the compute prepass's small clusters (lines/prepass_raster.h)
    gl::Program depth_resolve;    // ... merged into the depth buffer
    gl::Program occlusion_layer;  // prepass.vert + occlusion_layer.frag: one peeled layer
    gl::Program lines;
    gl::Program mask;          // lines.* with MASK_MODE
    gl::Program lines_dim;     // lines.* with OCCLUSION_LEVELS: dimmer by level (x-ray)
    gl::Program edges;         // LineMethod::compute: edges.comp fills the edge buffer
    gl::Program edges_listed;  // the same for the edges the CPU listed (lines/edge_prefilter.h)
    // ... both writing the records' normals too, for the strokes that shade by them
    // (EDGE_RECORD_NORMALS; records_carry_normals in passes.h)
    gl::Program edges_normals;
    gl::Program edges_listed_normals;
    gl::Program spine_visibility;  // ... spine test per spine sample
    gl::Program intersections;     // intersections.comp: intersection lines into the edge buffer
    gl::Program depth_tiles;       // ... hierarchical-Z culling's depth tiles
    // ... edge_quad.vert + edge_quad.frag draw it: each as two programs, for records with
    // spine samples (SPINE_SAMPLES_ONLY) and for records whose fragments run the spine test
    // (pass_edge_quads.cpp)
    QuadPrograms edge_quads;
    QuadPrograms edge_quads_mask;  // ... with MASK_MODE
    QuadPrograms edge_quads_dim;   // ... with OCCLUSION_LEVELS
    gl::Program hud;
    gl::Program hud_lit_tiles;  // ... marking the composite's lit tiles (drawn after the bloom)
    gl::Program bloom_down;
    gl::Program bloom_down_tiles;  // the first downsample under the beam's screen tiles only
    gl::Program bloom_blur;
    gl::Program bloom_blur_glow;  // ... whose last direction keeps the glow's persistence
    gl::Program composite;
    gl::Program composite_tiles;  // the same fragment stage over the listed lit tiles only
    // ... both advancing the phosphor (PHOSPHOR); [0] exponential, [1] power law (POWER_LAW):
    // the decay is compiled in, because llvmpipe runs a uniform branch's both sides per pixel
    // (about 0.5 ms at 1280x720).
    std::array<gl::Program, 2> composite_phosphor;
    std::array<gl::Program, 2> composite_tiles_phosphor;
    gl::Program tile_list;           // tile_list.comp: the lit tiles the composite shades
    gl::Program clear_image;         // clear_image.comp: a colour clear by compute (clear_image.h)
    gl::Program bloom_chain;         // bloom_chain.comp: the mip chain past level 0 in one dispatch
    gl::Program bloom_up;            // one step up the bloom chain (BloomKind::mip_chain)
    gl::Program bloom_up_glow;       // ... whose last step keeps the glow's persistence
    gl::Program outline_prepass;     // image-space baseline: depth + face normals
    gl::Program image_outline;       // ... Sobel into the lines target
    gl::Program image_outline_mask;  // ... Sobel into the mask
    // Filled styles (render/styles/): fill.vert + fill.frag per look, the halo's shrunk depth
    // mask (fill.vert with SHRINK), and the canvas composite.
    gl::Program fill_toon;
    gl::Program fill_pop_art;
    gl::Program fill_paper;
    gl::Program shrunk_depth;
    gl::Program ink_composite;
    gl::Program ink_composite_tiles;  // the same over the HUD's tiles
    // Strokes on the edge buffer: stroke.vert with each look's fragment stage.
    gl::Program outline;
    gl::Program outline_levels_mask;  // ... with MASK_MODE: each pixel's occlusion level
    gl::Program sketch;
    gl::Program sketch_mask;
    gl::Program halo_glow;
    gl::Program halo;
    gl::Program halo_apply;
    gl::Program halo_apply_tiles;  // the same over the tiles the halo marked
};

// Throws UserError naming file:line:col of every compile error. The bloom kernel is baked
// into its program as constants, so it depends on the settings.
Programs load_programs(const RenderSettings& settings);
// `glow_persistence`: the variant with GLOW_PHOSPHOR (shaders/beam/glow_persistence.glsl).
gl::Program load_bloom_blur(const RenderSettings& settings, bool glow_persistence);

}  // namespace bz::render
