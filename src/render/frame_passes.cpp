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

void bloom(const PassContext& ctx) {
    pass_bloom(ctx, *ctx.picture->texture, phosphor(ctx));
    ctx.picture->bloom = true;
}

void composite(const PassContext& ctx) {
    const PhosphorStep* step = phosphor(ctx);
    if (step && !ctx.picture->bloom) ctx.targets.glow_history_valid = false;
    pass_composite(ctx, *ctx.picture->texture, ctx.picture->bloom, ctx.target_fbo,
                   ctx.targets.width, ctx.targets.height, step);
    if (step) ctx.picture->texture = &ctx.targets.phosphor;  // updated in place
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

std::vector<FramePass> frame_passes(const StyleDef& style, const RenderSettings& settings) {
    std::vector<FramePass> list;
    // Where the depth comes from, and what the lines go onto.
    if (style.fill == FillPass::none) {
        if (settings.method == LineMethod::image_outline) {
            // The image-space baseline finds no edges as such: feature_edges stays 0.
            list.push_back({"prepass", pass_outline_prepass});
            list.push_back({"outline", outline_baseline});
        } else if (settings.method == LineMethod::compute) {
            // The edges pass appends every visible feature edge, the visibility pass runs the
            // spine test once per spine sample of each, and the quads draw the count the edges
            // pass appended (indirect dispatch and draw, no read-back).
            list.push_back({"prepass", pass_prepass});
            list.push_back({"edges", edges_sized});
            list.push_back({"visibility", pass_spine_visibility});
            list.push_back({"lines", edge_quads_counted});
        } else {
            list.push_back({"prepass", pass_prepass});
            list.push_back({"lines", lines_counted});
        }
        // The HUD after the bloom unless it glows: text and menus keep their contrast
        // (pass_hud.cpp).
        const bool bloom_on = style.bloom && settings.bloom_strength > 0.0f;
        if (settings.hud_glow) list.push_back({"hud", pass_hud});
        if (bloom_on) list.push_back({"bloom", bloom});
        if (!settings.hud_glow) list.push_back({"hud", pass_hud});
        if (bloom_on && settings.sparse_composite) list.push_back({"tiles", pass_tiles});
        list.push_back({"composite", composite});
        return list;
    }
    list.push_back({"fill", pass_fill});
    // Strokes are drawn from the edge buffer: the edges pass appends every visible feature edge.
    if (style_needs_edge_buffer(style, settings)) list.push_back({"edges", edges_counted});
    switch (style.lines) {
        case LinePass::outline:
            list.push_back({"outline", pass_outline});
            break;
        case LinePass::sketch:
            list.push_back({"strokes", sketch_strokes});
            break;
        case LinePass::halo:
            list.push_back({"shrunk", pass_shrunk_depth});
            list.push_back({"halo", pass_halo});
            break;
        case LinePass::beam:
            list.push_back({"lines", lines_counted});
            break;
    }
    list.push_back({"hud", pass_hud});
    list.push_back({"composite", pass_ink_composite});
    return list;
}

std::vector<FramePass> mask_passes(const StyleDef& style, const RenderSettings& settings) {
    if (style.fill == FillPass::none && settings.method == LineMethod::image_outline)
        return {{"prepass", pass_outline_prepass}, {"outline", outline_mask}};
    if (exact_mask_from_edges(style, settings))
        return {{"prepass", pass_prepass},
                {"edges", edges_complete},
                {"visibility", pass_spine_visibility},
                {"lines", edge_quads_mask}};
    if (style.lines == LinePass::sketch)
        return {{"prepass", pass_prepass}, {"edges", edges_complete}, {"strokes", sketch_mask}};
    return {{"prepass", pass_prepass}, {"lines", lines_mask}};
}

}  // namespace bz::render
