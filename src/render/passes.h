#pragma once
// The passes of one frame, one file each. Which passes a frame runs, in which order, is the
// style's list (frame_passes.h). Each states the whole GL state it needs (gl::apply), so
// order is the only coupling.
#include <optional>
#include <span>
#include <vector>

#include "core/worker_pool.h"
#include "gl/state.h"
#include "gl/vertex_array.h"
#include "render/frame_history.h"
#include "render/frame_resources.h"
#include "render/gpu_scene/batches.h"
#include "render/lines/edge_counter.h"
#include "render/lines/edge_storage.h"
#include "render/programs.h"
#include "render/shader_interface.h"
#include "render/styles/style_def.h"
#include "render/styles/style_textures.h"
#include "render/targets.h"

namespace bz::render {

// One frame's step of phosphor persistence (pass_phosphor.cpp): the composite computes and
// stores the new picture, and the bloom's glow fades by glow_factor.
struct PhosphorStep {
    bool power_law = false;
    float dt = 0.0f;           // seconds, capped
    float exp_factor = 1.0f;   // exponential: exp(-dt / tau)
    float t0_inv = 0.0f;       // power law: 1 / t0
    float exponent = 1.0f;     // power law: p
    float glow_factor = 1.0f;  // the glow's decay this step (glow_persistence.glsl)
};

// What the beam passes hand on within one frame: the picture bloom and composite read (the
// lines target; after the composite with the phosphor on, the new phosphor picture), the
// phosphor step when it is on, and whether bloom ran.
struct FramePicture {
    const gl::Texture2D* texture = nullptr;
    double dt_seconds = 0.0;  // game time since the last picture (phosphor decay)
    bool bloom = false;
    std::optional<PhosphorStep> phosphor;
};

struct PassContext {
    const Programs& programs;
    Targets& targets;
    FrameHistory& history;  // what this view keeps from earlier frames (frame_history.h)
    MeshCache& gpu_meshes;
    const scene::MeshLibrary& meshes;
    const FrameBatches& batches;
    const CameraMatrices& cam;
    const RenderSettings& settings;
    bool occlusion;                       // false in the arcade style
    const gl::VertexArray& empty_vao;     // for full-screen triangles
    const gl::Buffer& instances;          // the frame's InstanceData, also read as an SSBO
    EdgeStorage& edges;                   // the edge buffer (strokes, LineMethod::compute)
    WorkerPool& workers;                  // threads for the CPU culling (parallel_chunks.h)
    const StyleDef& style;                // what the frame looks like (render/styles/)
    const StyleTextures& style_textures;  // noise and stroke profiles
    const gl::VertexArray& hud_vao;
    GLsizei hud_vertex_count = 0;
    GLuint target_fbo = 0;                // where composite writes
    FrameStats* stats = nullptr;          // passes that count something add it here
    EdgeCounter* edge_counter = nullptr;  // feature edges, when count_edges is on (edge_counter.h)
    FramePicture* picture = nullptr;      // the picture phosphor, bloom and composite pass on
    std::uint32_t seed = 0;               // the frame's beam flicker seed (FrameList::seed)
    // Pixel rows from the bottom that the scene's lines may light (FrameList::view_top); the
    // rows above belong to the HUD band. 0: all of them.
    int view_rows = 0;
    // Where draw_batch_triangles puts a frame's indirect draws; null: no cluster culling.
    gl::Buffer* triangle_draws = nullptr;
    // The compute prepass's work items (lines/prepass_raster.h); null: no compute prepass.
    gl::Buffer* raster_work = nullptr;
    bool software_rasteriser = false;  // llvmpipe and the like (gl::is_software_renderer)
    bool clears_by_compute = false;    // colour clears by a compute shader (clear_image.h)
    // The bloom's first downsample reads the whole beam image this frame, so the line and HUD
    // stages mark no beam tiles (RenderSettings::first_downsample).
    bool dense_first_downsample = false;
    // What the passes before this one wrote this frame (frame_passes.h declares it); a held
    // frame starts with what the frame it holds wrote. Null: nothing (the mask passes).
    const FrameResources* frame = nullptr;
    // The frame's intersection segments (intersection_records.h), when intersection lines are on.
    const gl::Buffer* intersections = nullptr;
    std::uint32_t intersection_count = 0;
};

// Whether an earlier pass of this frame wrote `r`.
inline bool frame_wrote(const PassContext& ctx, Resource r) {
    return ctx.frame && ctx.frame->has(r);
}

void pass_prepass(const PassContext& ctx);

// Shared by the depth-writing passes (pass_prepass.cpp): the state for the camera's depth
// convention, its clear value, and drawing every batch's triangles with the back-face culling
// that outward-closed meshes seen from outside allow.
gl::PipelineState depth_writing_state(const PassContext& ctx, bool color_write);
double depth_clear_value(const PassContext& ctx);
// `vao` picks the mesh's vertex layout: positions only (prepass) or the fill's normals and colour.
// A mesh of many clusters draws only the clusters in view, and of a closed mesh seen from
// outside only those not wholly facing away (render/gpu_scene/triangle_culling.h), unless
// `moves_vertices` (a vertex stage that displaces vertices leaves the clusters' bounds); returns
// what that culling did. `front_faces_only`: every mesh's back faces culled (the occlusion
// layers count surfaces facing the eye). With a `route`, the small clusters go to it instead
// (the compute prepass, prepass_raster.h).
TriangleCullStats draw_batch_triangles(const PassContext& ctx, gl::PipelineState state,
                                       bool occluders_only,
                                       gl::VertexArray GpuMesh::*vao = &GpuMesh::prepass_vao,
                                       bool moves_vertices = false, bool front_faces_only = false,
                                       RasterRoute* route = nullptr);
// Hidden lines by occlusion level (pass_occlusion_layers.cpp): whether the style draws them
// (technical's dashed hidden lines, vector-xray's dimmer ones), the depth peeling of the
// surfaces facing the eye into Targets::occlusion_layers, and binding those layers for
// shaders/lines/occlusion_level.glsl.
bool style_needs_occlusion_levels(const StyleDef& style);
void pass_occlusion_layers(const PassContext& ctx);
void bind_occlusion_layers(const PassContext& ctx);
// Whether the beam lines of this frame are dimmed by occlusion level (vector-xray), and the
// uniforms and layers their OCCLUSION_LEVELS programs read.
bool dims_hidden_lines(const PassContext& ctx);
void set_level_dim_uniforms(const PassContext& ctx, const gl::Program& program);
// mask_mode: draw the 1-pixel visible-spine mask into targets.mask instead of shaded lines.
void pass_lines(const PassContext& ctx, bool mask_mode);
// Shared by both line methods' draw passes (pass_lines.cpp): binds and clears the lines (or
// mask) target with the beam's blending, binds the depth texture and the instance buffer, uses
// `program` and sets the uniforms of the line fragment stage, the beam and the shared edge
// geometry.
// `clear` false draws over what an earlier pass of the frame drew there (and its tile marks).
void begin_line_target(const PassContext& ctx, const gl::Program& program, bool mask_mode,
                       bool clear = true);
// Binds Targets::beam_tiles where the beam's fragment stages mark the tiles they light
// (shaders/beam/beam_tiles.glsl, kImageUnitBeamTiles).
void bind_beam_tiles(const Targets& targets);
// The uniforms of the stages that project and clip edges to the window (u_proj, u_viewport,
// u_near, u_far: lines.geom, edges.comp, edge_quad.*, spine_visibility.comp, stroke.vert).
void set_edge_projection_uniforms(const gl::Program& program, const PassContext& ctx);
// The spine test's absolute tolerance in inverse view depth (the depth buffer's step).
float spine_tolerance_abs(const PassContext& ctx);
// The uniforms shaders/lines/spine_test.glsl declares: tolerances, depth convention, view rays.
void set_spine_test_uniforms(const gl::Program& program, const PassContext& ctx);
// Both: the programs that find or draw edges and test their spines.
void set_line_uniforms(const gl::Program& program, const PassContext& ctx);
// Whether this frame's edges pass tests its clusters against the depth tiles
// (lines/hiz_culling.h): with occlusion, RenderSettings::hiz_culling, and enough edges
// submitted for the tiles to pay (pass_depth_tiles.cpp).
bool hiz_culls(const PassContext& ctx);
// After the prepass: the depth tiles of hierarchical-Z culling, when hiz_culls.
void pass_depth_tiles(const PassContext& ctx);
// Fills the edge buffer from every batch's edge list (edges.comp): the strokes of the filled
// styles and LineMethod::compute read it.
void pass_edges(const PassContext& ctx);
// Whether a style's edge records carry their faces' and vertices' normals: the sketch strokes
// weigh creases by how lit their faces are, the halo bends silhouettes by the vertex normals
// (shaders/styles/stroke.vert). Nothing else reads them, so other frames skip their work.
bool records_carry_normals(const StyleDef& style);
// Whether the edges pass reserves spine samples: LineMethod::compute's beam lines with
// occlusion (pass_spine_visibility.cpp).
bool wants_spine_samples(const PassContext& ctx);
// LineMethod::compute: the spine test once per spine sample of every record, for the quads.
void pass_spine_visibility(const PassContext& ctx);
// LineMethod::compute: one quad per edge-buffer record (pass_edge_quads.cpp), with the same
// fragment stage as pass_lines.
void pass_edge_quads(const PassContext& ctx, bool mask_mode);
// Which of the edge buffer's indirect draws (EdgeDrawCommand) a quad draw takes.
enum class QuadDraw {
    every_record,  // the append count itself: the records have no spine samples
    sampled,       // spine_visibility.comp's: every record, when the frame's samples fit
    tested,        // ... every record, when they did not
};
// Shared by it and the intersection quads (pass_intersections.cpp): with `program` in use and
// its line target begun, one quad per edge-buffer record, drawn with the count the buffer's
// command holds; `sample_capacity` 0 when the records have no spine samples.
void draw_edge_record_quads(const PassContext& ctx, const gl::Program& program,
                            unsigned sample_capacity, QuadDraw draw = QuadDraw::every_record);
// Intersection lines (pass_intersections.cpp). Appends the frame's intersection segments to
// the edge buffer as records (intersections.comp), with spine samples when the frame wants
// them; the edges pass calls it after the meshes' edges, with the buffer's state bound.
void append_intersections(const PassContext& ctx, bool samples);
// LineMethod::geometry_shader: the edge buffer filled with the intersection segments alone...
void pass_intersection_edges(const PassContext& ctx);
// ... and drawn as quads over what the line pass drew (no clear).
void pass_intersection_quads(const PassContext& ctx, bool mask_mode);
void pass_hud(const PassContext& ctx);
// Beam passes (the vector-monitor look, BeamSettings); each reads the image it is given, so a
// style may skip any of them. Phosphor persistence is no pass of its own: on llvmpipe every
// pass costs per pixel it shades, so the composite computes the new picture where it shades
// anyway and stores it, and the bloom's last step keeps last frame's glow, decayed alike.
// phosphor_step sets up one frame's step; set_phosphor_uniforms hands it to a program
// (shaders/beam/phosphor.glsl). The composite updates the picture (FrameHistory::phosphor) in
// place; the bloom's glow persists with it (shaders/beam/glow_persistence.glsl).
PhosphorStep phosphor_step(const PassContext& ctx, double dt_seconds);
void set_phosphor_uniforms(const gl::Program& program, const PhosphorStep& step);
void pass_bloom(const PassContext& ctx, const gl::Texture2D& source,
                const PhosphorStep* phosphor = nullptr);
// The weight of one level of the bloom chain (never zero: the chain divides by it).
float mip_weight(const std::vector<float>& weights, std::size_t level);
// The list of lit tiles the sparse composite shades (pass_tiles.cpp, after bloom; needs
// Targets::lit_tiles): built from the marks the bloom made and, with the phosphor, the tiles
// where last frame's picture held light.
void pass_tiles(const PassContext& ctx);
// Draws shaders/beam/composite_tiles.vert's quads over the tiles that `tiles` marks (R8UI, one
// texel per kScreenTileSize square of a `screen`-pixel screen), read on kTextureUnitTiles,
// with `program` in use: the sparse first downsample over the beam's tiles.
void draw_tile_quads(const gl::Program& program, const gl::Texture2D& tiles, glm::ivec2 screen);
// With `program` in use (one built with LIT_TILES): binds Targets::lit_tiles for its marks,
// or, with `mark` false, tells it to mark nothing (shaders/beam/lit_tiles.glsl).
void bind_lit_tile_marks(const gl::Program& program, const Targets& targets, bool mark);
// Draws shaders/beam/lit_tiles.vert's quads over the tiles pass_tiles listed (one indirect
// draw), with `program` in use: the sparse composite.
void draw_listed_tiles(const gl::Program& program, const Targets& targets, glm::ivec2 screen);
// `bloom`: false draws the picture without glow (bloom_out is not read). With bloom and the
// tiles of pass_tiles it shades only the lit tiles (RenderSettings::sparse_composite).
// With `phosphor`, `picture` is this frame's beam image and the composite also updates the
// phosphor picture (FrameHistory::phosphor) in place.
void pass_composite(const PassContext& ctx, const gl::Texture2D& picture, bool bloom,
                    GLuint target_fbo, int width, int height,
                    const PhosphorStep* phosphor = nullptr);
// The image-space outline baseline (LineMethod::image_outline), in place of prepass + lines.
void pass_outline_prepass(const PassContext& ctx);
void pass_image_outline(const PassContext& ctx, bool mask_mode);

// Filled styles (render/styles/pass_*.cpp).
// The style's fill into the canvas and the depth texture (in place of the prepass): paper
// tone, then every object's triangles, both faces. Also clears the lines target and the
// screen-tile marks (Targets::beam_tiles) for the HUD.
void pass_fill(const PassContext& ctx);
// The halo's depth mask: every occluder shrunk along its vertex normals.
void pass_shrunk_depth(const PassContext& ctx);
// Ink outlines of the feature edges onto the canvas (toon, pop-art).
void pass_outline(const PassContext& ctx);
// The outline's 1-pixel mask of every line up to the style's hidden levels, each pixel marked
// by its occlusion level (RenderSettings::mask_occlusion_levels).
void pass_outline_levels_mask(const PassContext& ctx);
// Pencil strokes onto the canvas (sketch); mask_mode: their 1-pixel spines into targets.mask.
void pass_sketch(const PassContext& ctx, bool mask_mode);
// Soft halos (MAX blended off screen), laid over the canvas, then the silhouette strokes.
// Reads depth and shrunk depth; writes halo and canvas; uses beam_tiles for the tiles its
// halos cover and leaves them cleared.
void pass_halo(const PassContext& ctx);
// Canvas + HUD lines into the target (filled styles' composite): reads canvas, lines and the
// HUD's beam_tiles marks; a blit of the canvas, then the HUD's ink over the marked tiles.
void pass_ink_composite(const PassContext& ctx);

}  // namespace bz::render
