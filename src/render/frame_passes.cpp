#include "render/frame_passes.h"

namespace bz::render {

namespace {

bool counting_edges(const PassContext& ctx) {
    return ctx.settings.count_edges && ctx.stats && ctx.edge_counter;
}

// The beam line pass; with count_edges it also counts the emitted feature edges (read back
// late, EdgeCounter).
void lines_counted(const PassContext& ctx) {
    if (!counting_edges(ctx)) {
        pass_lines(ctx, false);
        return;
    }
    ctx.edge_counter->begin_primitives();
    pass_lines(ctx, false);
    ctx.edge_counter->end_primitives();
}

// The edge buffer filled completely: grown and filled again when a frame appended more
// records than it held (the mask must miss nothing; frames grow it for the next one).
void edges_complete(const PassContext& ctx) {
    pass_edges(ctx);
    const EdgeStorage::FillCounts counts = ctx.edges.counts();
    const std::size_t n = counts.records;
    const std::size_t samples = wants_spine_samples(ctx) ? counts.samples : 0;
    if (n > ctx.edges.capacity() || samples > ctx.edges.sample_capacity()) {
        ctx.edges.reserve(n);
        ctx.edges.reserve_samples(samples);
        pass_edges(ctx);
    }
}

// LineMethod::compute's edge extraction. The first fill knows nothing of the scene's size: it
// reads its counts back and fills again if the records or their spine samples did not fit,
// so that no frame depends on which records the atomic appends left without samples (those
// are tested per fragment, which differs from the samples where the spine test is a tie).
// Later frames size the buffers from the frame before without waiting.
void edges_sized(const PassContext& ctx) {
    if (ctx.edges.has_previous()) {
        pass_edges(ctx);
    } else {
        edges_complete(ctx);
    }
}

// The edge extraction; with count_edges it also counts the records it appended.
void edges_counted(const PassContext& ctx) {
    pass_edges(ctx);
    if (counting_edges(ctx)) ctx.edge_counter->count_records(ctx.edges.command());
}

// LineMethod::compute's line pass: one quad per edge-buffer record; with count_edges it also
// counts the records the edges pass appended.
void edge_quads_counted(const PassContext& ctx) {
    pass_edge_quads(ctx, false);
    if (counting_edges(ctx)) ctx.edge_counter->count_records(ctx.edges.command());
}

void edge_quads_mask(const PassContext& ctx) {
    pass_edge_quads(ctx, true);
}

void intersection_quads(const PassContext& ctx) {
    pass_intersection_quads(ctx, false);
}
void intersection_quads_mask(const PassContext& ctx) {
    pass_intersection_quads(ctx, true);
}

void sketch_strokes(const PassContext& ctx) {
    pass_sketch(ctx, false);
}
void sketch_mask(const PassContext& ctx) {
    pass_sketch(ctx, true);
}

// The beam passes hand the picture on (FramePicture). With the phosphor on, bloom and
// composite take this frame's phosphor step: the composite stores the new picture, which then
// replaces the lines target as the frame's picture.
const PhosphorStep* phosphor(const PassContext& ctx) {
    FramePicture& picture = *ctx.picture;
    if (ctx.settings.beam.phosphor == PhosphorDecay::off) return nullptr;
    if (!picture.phosphor) picture.phosphor = phosphor_step(ctx, picture.dt_seconds);
    return &*picture.phosphor;
}

void bloom_pass(const PassContext& ctx) {
    pass_bloom(ctx, *ctx.picture->texture, phosphor(ctx));
    ctx.picture->bloom = true;
}

void composite(const PassContext& ctx) {
    const PhosphorStep* step = phosphor(ctx);
    pass_composite(ctx, *ctx.picture->texture, ctx.picture->bloom, ctx.target_fbo,
                   ctx.targets.width, ctx.targets.height, step);
    if (step) ctx.picture->texture = &ctx.history.phosphor;  // updated in place
}

bool beam_blooms(const StyleDef& style, const RenderSettings& settings) {
    return style.bloom && settings.bloom_strength > 0.0f;
}

// A held frame (BeamSettings::refresh_hz): the picture the history holds, composited again
// with the bloom of the frame that drew it; no phosphor step (the picture does not change).
void held_composite(const PassContext& ctx) {
    pass_composite(ctx, *ctx.history.picture(), beam_blooms(ctx.style, ctx.settings),
                   ctx.target_fbo, ctx.targets.width, ctx.targets.height);
}

void outline_levels_mask(const PassContext& ctx) {
    pass_outline_levels_mask(ctx);
}

void outline_baseline(const PassContext& ctx) {
    pass_image_outline(ctx, false);
}
void lines_mask(const PassContext& ctx) {
    pass_lines(ctx, true);
}
void outline_mask(const PassContext& ctx) {
    pass_image_outline(ctx, true);
}

}  // namespace

namespace {

// LineMethod::automatic may draw any frame with the compute method: its meshes need edge lists.
bool may_use_edges(LineMethod method) {
    return method == LineMethod::compute || method == LineMethod::automatic;
}

bool compute_lines(const StyleDef& style, const RenderSettings& settings) {
    return style.fill == FillPass::none && may_use_edges(settings.method);
}

bool exact_mask_from_edges(const StyleDef& style, const RenderSettings& settings) {
    return may_use_edges(settings.method) && style.lines != LinePass::sketch;
}

}  // namespace

bool mask_needs_edge_buffer(const StyleDef& style, const RenderSettings& settings) {
    return exact_mask_from_edges(style, settings) || style_needs_edge_buffer(style, settings);
}

bool style_needs_edge_buffer(const StyleDef& style, const RenderSettings& settings) {
    return style.lines == LinePass::outline || style.lines == LinePass::sketch ||
           style.lines == LinePass::halo || compute_lines(style, settings);
}

namespace {

using R = Resource;

// After the geometry shader's line pass (`draws` its output): with intersection lines on, the
// segments fill the edge buffer, which that method does not use otherwise, and are drawn as
// quads over its lines with the same spine test and beam.
void add_intersection_passes(std::vector<FramePass>& list, const RenderSettings& settings,
                             ResourceSet draws, void (*quads)(const PassContext&)) {
    if (!settings.intersection_lines) return;
    list.push_back({"intersections", pass_intersection_edges, {}, {R::edges}});
    list.push_back({"intersection lines", quads, ResourceSet{R::depth, R::edges} | draws, draws});
}

// The beam frame's tail: HUD, bloom, lit tiles and composite, reading the lines whichever
// line pass drew them; `beam_tiles` says whether that pass marked the beam's tiles.
// The HUD goes after the bloom unless it glows (RenderSettings::hud_glow), so that text and
// menus keep their contrast (pass_hud.cpp); there it marks the composite's lit tiles.
void beam_tail(std::vector<FramePass>& list, const StyleDef& style, const RenderSettings& settings,
               bool beam_tiles) {
    const ResourceSet tiles = beam_tiles ? ResourceSet{R::beam_tiles} : ResourceSet{};
    const bool phosphor = settings.beam.phosphor != PhosphorDecay::off;
    const bool bloom = beam_blooms(style, settings);
    const bool sparse = bloom && settings.sparse_composite;
    if (settings.hud_glow)
        list.push_back(
            {"hud", pass_hud, ResourceSet{R::lines} | tiles, ResourceSet{R::lines} | tiles});
    if (bloom) {
        ResourceSet writes{R::bloom_chain, R::bloom_out};
        if (settings.sparse_composite) writes.add(R::lit_tiles);
        if (phosphor) writes.add(R::glow);
        list.push_back({"bloom", bloom_pass, ResourceSet{R::lines} | tiles, writes,
                        phosphor ? ResourceSet{R::glow} : ResourceSet{}});
    }
    if (!settings.hud_glow) {
        // After a bloom it adds its marks to the lit tiles the bloom marked, else to the
        // screen tiles the line pass marked (which nothing reads after it).
        const ResourceSet marks = sparse ? ResourceSet{R::lit_tiles} : tiles;
        list.push_back(
            {"hud", pass_hud, ResourceSet{R::lines} | marks, ResourceSet{R::lines} | marks});
    }
    if (sparse)
        list.push_back({"tiles",
                        pass_tiles,
                        {R::lit_tiles},
                        {R::tile_list},
                        phosphor ? ResourceSet{R::picture_lit} : ResourceSet{}});
    ResourceSet reads{R::lines};
    if (bloom) reads.add(R::bloom_out);
    if (sparse) reads.add(R::tile_list);
    ResourceSet writes{R::target, R::picture};
    ResourceSet past;
    if (phosphor) {
        writes.add(ResourceSet{R::phosphor, R::picture_lit});
        past.add(R::phosphor);
    }
    list.push_back({"composite", composite, reads, writes, past});
}

// Hidden lines by occlusion level (technical, vector-xray): the peeled layers, after the depth
// pass, read by the line or stroke pass. Other styles neither run nor allocate them.
void add_occlusion_layers(std::vector<FramePass>& list, const StyleDef& style) {
    if (style_needs_occlusion_levels(style))
        list.push_back({"layers", pass_occlusion_layers, {}, {R::peel_layers}});
}

ResourceSet layers_read(const StyleDef& style) {
    return style_needs_occlusion_levels(style) ? ResourceSet{R::peel_layers} : ResourceSet{};
}

// A held frame shows the picture its history holds, with the bloom (and the list of lit
// tiles) of the frame that drew it.
std::vector<FramePass> held_passes(const StyleDef& style, const RenderSettings& settings) {
    ResourceSet past{R::picture};
    if (beam_blooms(style, settings)) {
        past.add(R::bloom_out);
        if (settings.sparse_composite) past.add(R::tile_list);
    }
    return {{"composite", held_composite, {}, {R::target}, past}};
}

}  // namespace

ResourceSet resources_of(const std::vector<FramePass>& list) {
    ResourceSet all;
    for (const FramePass& pass : list) all.add(pass.reads | pass.writes | pass.reads_past);
    return all;
}

ResourceSet writes_of(const std::vector<FramePass>& list) {
    ResourceSet all;
    for (const FramePass& pass : list) all.add(pass.writes);
    return all;
}

std::vector<FramePass> frame_passes(const StyleDef& style, const RenderSettings& settings,
                                    FrameKind kind) {
    std::vector<FramePass> list;
    // Where the depth comes from, and what the lines go onto.
    if (style.fill == FillPass::none) {
        if (kind == FrameKind::held) return held_passes(style, settings);
        bool beam_tiles = true;
        if (settings.method == LineMethod::image_outline) {
            // The image-space baseline finds no edges as such: feature_edges stays 0.
            list.push_back({"prepass", pass_outline_prepass, {}, {R::depth, R::normals}});
            list.push_back({"outline", outline_baseline, {R::depth, R::normals}, {R::lines}});
            beam_tiles = false;
        } else if (settings.method == LineMethod::compute) {
            // The edges pass appends every visible feature edge, the visibility pass runs the
            // spine test once per spine sample of each, and the quads draw the count the edges
            // pass appended (indirect dispatch and draw, no read-back).
            list.push_back({"prepass", pass_prepass, {}, {R::depth}});
            add_occlusion_layers(list, style);
            // Hierarchical-Z: the edges pass skips the clusters the prepass hides wholly.
            ResourceSet edges_read;
            if (settings.hiz_culling) {
                list.push_back({"hiz", pass_depth_tiles, {R::depth}, {R::depth_tiles}});
                edges_read.add(R::depth_tiles);
            }
            list.push_back({"edges", edges_sized, edges_read, {R::edges}});
            list.push_back({"visibility", pass_spine_visibility, {R::depth, R::edges}, {R::edges}});
            list.push_back({"lines",
                            edge_quads_counted,
                            ResourceSet{R::depth, R::edges} | layers_read(style),
                            {R::lines, R::beam_tiles}});
        } else {
            list.push_back({"prepass", pass_prepass, {}, {R::depth}});
            add_occlusion_layers(list, style);
            list.push_back({"lines",
                            lines_counted,
                            ResourceSet{R::depth} | layers_read(style),
                            {R::lines, R::beam_tiles}});
            add_intersection_passes(list, settings, {R::lines, R::beam_tiles}, intersection_quads);
        }
        beam_tail(list, style, settings, beam_tiles);
        return list;
    }
    // The fill clears the lines target, which holds only the HUD in a filled style, and the
    // screen-tile marks, where the HUD marks its tiles for the ink composite.
    list.push_back({"fill", pass_fill, {}, {R::canvas, R::depth, R::lines, R::beam_tiles}});
    // Strokes are drawn from the edge buffer: the edges pass appends every visible feature edge.
    if (style_needs_edge_buffer(style, settings))
        list.push_back({"edges", edges_counted, {}, {R::edges}});
    ResourceSet strokes_read{R::depth, R::edges, R::canvas};
    // Hidden lines by occlusion level count the peeled layers in front of each line point.
    add_occlusion_layers(list, style);
    strokes_read.add(layers_read(style));
    switch (style.lines) {
        case LinePass::outline:
            list.push_back({"outline", pass_outline, strokes_read, {R::canvas}});
            break;
        case LinePass::sketch:
            list.push_back({"strokes", sketch_strokes, strokes_read, {R::canvas}});
            break;
        case LinePass::halo:
            list.push_back({"shrunk", pass_shrunk_depth, {}, {R::shrunk_depth}});
            // Its quads mark the screen tiles it lays the halo over, which it clears again.
            list.push_back({"halo",
                            pass_halo,
                            strokes_read | ResourceSet{R::shrunk_depth},
                            {R::halo, R::canvas, R::beam_tiles}});
            break;
        case LinePass::beam:
            list.push_back({"lines", lines_counted, {R::depth}, {R::lines, R::beam_tiles}});
            add_intersection_passes(list, settings, {R::lines, R::beam_tiles}, intersection_quads);
            break;
    }
    list.push_back({"hud", pass_hud, {R::lines, R::beam_tiles}, {R::lines, R::beam_tiles}});
    // A copy of the canvas, then the HUD's ink over the tiles the HUD marked.
    list.push_back(
        {"composite", pass_ink_composite, {R::canvas, R::lines, R::beam_tiles}, {R::target}});
    return list;
}

std::vector<FramePass> mask_passes(const StyleDef& style, const RenderSettings& settings) {
    if (settings.mask_occlusion_levels && style.hidden.levels > 0 &&
        style.lines == LinePass::outline)
        return {{"prepass", pass_prepass, {}, {R::depth}},
                {"layers", pass_occlusion_layers, {}, {R::peel_layers}},
                {"edges", edges_complete, {}, {R::edges}},
                {"outline", outline_levels_mask, {R::depth, R::peel_layers, R::edges}, {R::mask}}};
    if (style.fill == FillPass::none && settings.method == LineMethod::image_outline)
        return {{"prepass", pass_outline_prepass, {}, {R::depth, R::normals}},
                {"outline", outline_mask, {R::depth, R::normals}, {R::mask}}};
    if (exact_mask_from_edges(style, settings))
        return {{"prepass", pass_prepass, {}, {R::depth}},
                {"edges", edges_complete, {}, {R::edges}},
                {"visibility", pass_spine_visibility, {R::depth, R::edges}, {R::edges}},
                {"lines", edge_quads_mask, {R::depth, R::edges}, {R::mask}}};
    if (style.lines == LinePass::sketch)
        return {{"prepass", pass_prepass, {}, {R::depth}},
                {"edges", edges_complete, {}, {R::edges}},
                {"strokes", sketch_mask, {R::depth, R::edges}, {R::mask}}};
    std::vector<FramePass> list{{"prepass", pass_prepass, {}, {R::depth}},
                                {"lines", lines_mask, {R::depth}, {R::mask}}};
    add_intersection_passes(list, settings, {R::mask}, intersection_quads_mask);
    return list;
}

}  // namespace bz::render
