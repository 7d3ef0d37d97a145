#include "render/lines/hiz_culling.h"
#include "render/passes.h"

namespace bz::render {

namespace {

// The depth tiles read every depth texel once; the edges pass spends far more on one edge
// than on one texel. Below one submitted edge per this many pixels the tiles would cost more
// than the hidden clusters they let the edges pass skip (docs/measurements/hiz-culling.md).
constexpr std::size_t kPixelsPerEdge = 64;

std::size_t submitted_edges(const PassContext& ctx) {
    std::size_t edges = 0;
    for (const Batch& b : ctx.batches.batches) {
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        edges += mesh.edge_count * static_cast<std::size_t>(b.instance_count);
    }
    return edges;
}

}  // namespace

bool hiz_culls(const PassContext& ctx) {
    if (!ctx.occlusion || !ctx.settings.hiz_culling) return false;
    const auto pixels =
        static_cast<std::size_t>(ctx.targets.width) * static_cast<std::size_t>(ctx.targets.height);
    return submitted_edges(ctx) * kPixelsPerEdge >= pixels;
}

// Hierarchical-Z culling's tiles (hiz_culling.h): the farthest surface per fine tile from the
// prepass depth, then per coarse tile from the fine ones.
void pass_depth_tiles(const PassContext& ctx) {
    if (!hiz_culls(ctx)) return;
    const Targets& t = ctx.targets;
    const gl::Program& p = ctx.programs.depth_tiles;
    p.use();
    p.set("u_proj_a", ctx.cam.proj_a);
    p.set("u_proj_inv_b", 1.0f / ctx.cam.proj_b);
    p.set("u_depth_zero_to_one", ctx.cam.zero_to_one ? 1 : 0);
    glBindTextureUnit(kTextureUnitDepth, t.depth.id());
    glBindTextureUnit(kTextureUnitDepthTiles, t.depth_tiles.id());
    const auto level = [&](int index, const gl::Texture2D& out) {
        p.set("u_level", index);
        p.set("u_out_size", glm::ivec2(out.width(), out.height()));
        glBindImageTexture(kImageUnitDepthTiles, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        glDispatchCompute(static_cast<GLuint>((out.width() + 7) / 8),
                          static_cast<GLuint>((out.height() + 7) / 8), 1);
    };
    level(0, t.depth_tiles);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    level(1, t.depth_tiles_coarse);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace bz::render
