#include "render/lines/prepass_raster.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace bz::render {

// prepass_raster.comp projects a cluster's vertices one per invocation of a 64-wide group.
static_assert(geo::kClusterVertices <= 64);

bool computes_prepass(const PassContext& ctx) {
    const RenderSettings& s = ctx.settings;
    if (!ctx.targets.raster_depth || !ctx.raster_work || !ctx.triangle_draws ||
        !s.cluster_culling || s.depth != DepthFormat::reversed_f32)
        return false;
    switch (s.prepass_raster) {
        case PrepassRaster::pipeline:
            return false;
        case PrepassRaster::compute:
            return true;
        case PrepassRaster::automatic:
            break;
    }
    if (!ctx.software_rasteriser) return false;
    std::size_t triangles = 0;
    for (const Batch& b : ctx.batches.batches) {
        if (!b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        triangles += mesh.triangle_count() * static_cast<std::size_t>(b.instance_count);
    }
    const auto pixels =
        static_cast<std::size_t>(ctx.targets.width) * static_cast<std::size_t>(ctx.targets.height);
    return triangles * kPixelsPerRasterTriangle >= pixels;
}

namespace {

std::size_t routed_triangles(const RasterRoute& route) {
    std::size_t n = 0;
    for (const glm::uvec4& w : route.work) n += unpack(w).triangles;
    return n;
}

// The routed clusters drawn by the pipeline after all, as the prepass draws the rest: one
// indirect draw per work item, a multi-draw per mesh.
void draw_routed_clusters(const PassContext& ctx, const RasterRoute& route,
                          gl::PipelineState state) {
    std::vector<TriangleDraw> draws;
    draws.reserve(route.work.size());
    for (const glm::uvec4& w : route.work) {
        const RasterItem item = unpack(w);
        draws.push_back({item.triangles * 3, 1, item.first_triangle * 3, 0, item.instance});
    }
    ctx.triangle_draws->set(std::span<const TriangleDraw>(draws), GL_STREAM_DRAW);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.triangle_draws->id());
    ctx.programs.prepass.use();
    for (const glm::uvec3& b : route.batches) {
        const Batch& batch = ctx.batches.batches[b.x];
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, batch.mesh, batch.lod);
        state.cull_back = unpack(route.work[b.y]).skip_back_faces;  // one batch, one rule
        gl::apply(state);
        mesh.prepass_vao.bind();
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                    reinterpret_cast<const void*>(b.y * sizeof(TriangleDraw)),
                                    static_cast<GLsizei>(b.z), 0);
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace

bool raster_routed_clusters(const PassContext& ctx, const RasterRoute& route,
                            const gl::PipelineState& depth_state) {
    if (route.work.empty()) return false;
    const Targets& t = ctx.targets;
    // The pixels whose centres the routed clusters may cover, on screen.
    const int x0 = std::max(0, static_cast<int>(std::floor(route.lo.x)));
    const int y0 = std::max(0, static_cast<int>(std::floor(route.lo.y)));
    const int x1 = std::min(t.width, static_cast<int>(std::ceil(route.hi.x)) + 1);
    const int y1 = std::min(t.height, static_cast<int>(std::ceil(route.hi.y)) + 1);
    if (x0 >= x1 || y0 >= y1) return false;
    // Too few small triangles for the rectangle's clear and merge: the pipeline draws them.
    const auto pixels = static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0);
    const std::size_t routed = routed_triangles(route);
    if (ctx.settings.prepass_raster == PrepassRaster::automatic &&
        (routed < kMinRasterTriangles || routed * kPixelsPerRasterTriangle < pixels)) {
        draw_routed_clusters(ctx, route, depth_state);
        return false;
    }
    glClearTexSubImage(t.raster_depth.id(), 0, x0, y0, 0, x1 - x0, y1 - y0, 1, GL_RED_INTEGER,
                       GL_UNSIGNED_INT, nullptr);
    ctx.raster_work->set(std::span<const glm::uvec4>(route.work), GL_STREAM_DRAW);

    const gl::Program& raster = ctx.programs.prepass_raster;
    raster.use();
    raster.set("u_proj", ctx.cam.proj);
    raster.set("u_viewport", glm::ivec2(t.width, t.height));
    glBindImageTexture(kImageUnitRasterDepth, t.raster_depth.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                       GL_R32UI);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding, ctx.instances.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRasterWorkBinding, ctx.raster_work->id());
    // One dispatch per mesh: its positions and triangles are bound as buffers.
    for (const glm::uvec3& b : route.batches) {
        const Batch& batch = ctx.batches.batches[b.x];
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, batch.mesh, batch.lod);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgePositionsBinding, mesh.positions.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRasterVerticesBinding,
                         mesh.cluster_vertices.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRasterCornersBinding,
                         mesh.cluster_corners.id());
        raster.set("u_work_base", static_cast<unsigned>(b.y));
        glDispatchCompute(b.z, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Merged under the prepass's depth test: nearer wins, with what the pipeline drew.
    gl::PipelineState merge = depth_state;
    merge.cull_back = false;
    gl::apply(merge);
    const gl::Program& resolve = ctx.programs.depth_resolve;
    resolve.use();
    resolve.set("u_rect", glm::ivec4(x0, y0, x1, y1));
    resolve.set("u_viewport", glm::ivec2(t.width, t.height));
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 6);
    return true;
}

}  // namespace bz::render
