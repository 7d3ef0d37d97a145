#include "render/frame_passes.h"

namespace bz::render {

namespace {

// The beam line pass; with count_edges it also counts the emitted feature edges.
void lines_counted(const PassContext& ctx) {
    if (!ctx.settings.count_edges || !ctx.stats) {
        pass_lines(ctx, false);
        return;
    }
    glBeginQuery(GL_PRIMITIVES_GENERATED, ctx.edge_query);
    pass_lines(ctx, false);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 prims = 0;
    glGetQueryObjectui64v(ctx.edge_query, GL_QUERY_RESULT, &prims);
    ctx.stats->feature_edges = static_cast<std::size_t>(prims / 2);  // two triangles per quad
}

void outline_baseline(const PassContext& ctx) { pass_image_outline(ctx, false); }
void lines_mask(const PassContext& ctx) { pass_lines(ctx, true); }
void outline_mask(const PassContext& ctx) { pass_image_outline(ctx, true); }

}  // namespace

std::vector<FramePass> frame_passes(const StyleDef& style, const RenderSettings& settings) {
    std::vector<FramePass> list;
    // Where the depth comes from, and what the lines go onto.
    if (style.fill == FillPass::none) {
        if (settings.method == LineMethod::image_outline) {
            // The image-space baseline finds no edges as such: feature_edges stays 0.
            list.push_back({"prepass", pass_outline_prepass});
            list.push_back({"outline", outline_baseline});
        } else {
            list.push_back({"prepass", pass_prepass});
            list.push_back({"lines", lines_counted});
        }
        list.push_back({"hud", pass_hud});
        if (style.bloom) list.push_back({"bloom", pass_bloom});
        list.push_back({"composite", pass_composite});
        return list;
    }
    list.push_back({"fill", pass_fill});
    // The stroke passes on the edge buffer follow (outline, strokes, halo).
    switch (style.lines) {
        case LinePass::outline:
        case LinePass::sketch:
            break;
        case LinePass::halo:
            list.push_back({"shrunk", pass_shrunk_depth});
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
    return {{"prepass", pass_prepass}, {"lines", lines_mask}};
}

}  // namespace bz::render
