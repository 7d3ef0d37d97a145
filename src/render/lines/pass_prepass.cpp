#include <optional>
#include <vector>

#include "core/parallel_chunks.h"
#include "render/gpu_scene/cluster_culling.h"
#include "render/lines/prepass_raster.h"
#include "render/passes.h"

namespace bz::render {

gl::PipelineState depth_writing_state(const PassContext& ctx, bool color_write) {
    gl::PipelineState state;
    state.depth_test = ctx.settings.depth == DepthFormat::reversed_f32 ? gl::DepthTest::greater
                                                                       : gl::DepthTest::less;
    state.depth_write = true;
    state.color_write = color_write;
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    return state;
}

double depth_clear_value(const PassContext& ctx) {
    return ctx.settings.depth == DepthFormat::reversed_f32 ? 0.0 : 1.0;
}

namespace {

// A mesh with fewer triangle clusters than this is drawn whole, one instanced draw for all its
// instances: culling could save little, and a draw per instance costs more.
constexpr std::size_t kMinClustersToCull = 4;

bool culls_clusters(const PassContext& ctx, const GpuMesh& mesh, bool moves_vertices) {
    return !moves_vertices && ctx.settings.cluster_culling && ctx.triangle_draws != nullptr &&
           mesh.triangle_clusters.size() >= kMinClustersToCull;
}

// Whether every instance of the batch lies wholly inside the view.
bool all_inside(const PassContext& ctx, const Batch& b, const GpuMesh& mesh,
                const ViewVolume& view) {
    for (GLsizei k = 0; k < b.instance_count; ++k) {
        const InstanceData& d = ctx.batches.instances[b.first_instance + static_cast<GLuint>(k)];
        if (!InstanceClusters(d.model_view).inside(mesh.triangle_bounds, view)) return false;
    }
    return true;
}

}  // namespace

TriangleCullStats draw_batch_triangles(const PassContext& ctx, gl::PipelineState state,
                                       bool occluders_only, gl::VertexArray GpuMesh::*vao,
                                       bool moves_vertices, bool front_faces_only,
                                       RasterRoute* route) {
    // Every culled batch's draws go into one buffer, uploaded once.
    const ViewVolume view(ctx.cam.proj, ctx.cam.near, ctx.cam.far, 1.0);
    TriangleCullStats stats;
    std::vector<TriangleDraw> draws;
    struct Range {
        std::size_t first = 0, count = 0;
        std::size_t first_one_sided = 0, one_sided = 0;  // closed pieces' clusters, back culled
        bool whole = false;                              // drawn whole, one instanced draw
    };
    std::vector<Range> ranges(ctx.batches.batches.size());
    // One job per instance; the meshes are fetched (and uploaded) here, on the GL thread.
    struct Job {
        std::size_t batch;
        const GpuMesh* mesh;
        GLuint instance;
        bool skip_back_faces;
    };
    std::vector<Job> jobs;
    std::size_t clusters = 0;
    for (std::size_t i = 0; i < ctx.batches.batches.size(); ++i) {
        const Batch& b = ctx.batches.batches[i];
        if (occluders_only && !b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        if (!culls_clusters(ctx, mesh, moves_vertices)) continue;
        const bool skip_back_faces = front_faces_only || (b.eye_outside && mesh.outward_closed);
        // Both faces drawn and every instance wholly in view: nothing can be dropped, so the
        // batch stays one instanced draw (unless the compute prepass may take its clusters).
        if (!route && !skip_back_faces && !mesh.has_closed_clusters &&
            all_inside(ctx, b, mesh, view)) {
            ranges[i].whole = true;
            continue;
        }
        for (GLsizei k = 0; k < b.instance_count; ++k)
            jobs.push_back({.batch = i,
                            .mesh = &mesh,
                            .instance = b.first_instance + static_cast<GLuint>(k),
                            .skip_back_faces = skip_back_faces});
        clusters += mesh.triangle_clusters.size() * static_cast<std::size_t>(b.instance_count);
    }
    // Several threads when there is enough of it; chunks keep job order (parallel_chunks.h).
    const std::size_t threads = clusters >= kCullPairsPerThread ? ctx.workers.max_threads() : 1;
    const std::size_t chunks = chunk_count(jobs.size(), 1, threads);
    std::vector<std::vector<TriangleDraw>> chunk_draws(chunks), chunk_one_sided(chunks);
    std::vector<TriangleCullStats> chunk_stats(chunks);
    std::vector<std::size_t> job_draws(jobs.size()), job_one_sided(jobs.size()),
        job_work(jobs.size());
    std::vector<RasterRoute> chunk_routes;
    if (route) chunk_routes.assign(chunks, RasterRoute(route->view));
    parallel_chunks(ctx.workers, jobs.size(), 1, threads, [&](std::size_t j, std::size_t c) {
        const Job& job = jobs[j];
        const std::size_t before = chunk_draws[c].size();
        const std::size_t one_sided_before = chunk_one_sided[c].size();
        RasterRoute* chunk_route = route ? &chunk_routes[c] : nullptr;
        const std::size_t work_before = chunk_route ? chunk_route->work.size() : 0;
        append_triangle_draws(job.mesh->triangle_clusters, job.mesh->triangle_bounds,
                              ctx.batches.instances[job.instance].model_view, job.skip_back_faces,
                              view, job.instance, chunk_draws[c], chunk_stats[c], chunk_route,
                              &chunk_one_sided[c]);
        job_draws[j] = chunk_draws[c].size() - before;
        job_one_sided[j] = chunk_one_sided[c].size() - one_sided_before;
        job_work[j] = chunk_route ? chunk_route->work.size() - work_before : 0;
    });
    for (std::size_t c = 0; c < chunks; ++c)
        draws.insert(draws.end(), chunk_draws[c].begin(), chunk_draws[c].end());
    // The one-sided draws follow the two-sided ones in the same buffer.
    std::size_t next_one_sided = draws.size();
    for (std::size_t c = 0; c < chunks; ++c) {
        draws.insert(draws.end(), chunk_one_sided[c].begin(), chunk_one_sided[c].end());
        stats += chunk_stats[c];
        if (route) route->take(chunk_routes[c]);
    }
    // Each batch's work items lie together, in job order, as its draws do.
    if (route) {
        std::size_t first = route->work.size();
        for (std::size_t j = 0; j < jobs.size(); ++j) first -= job_work[j];
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            if (job_work[j] == 0) continue;
            const auto batch = static_cast<std::uint32_t>(jobs[j].batch);
            if (route->batches.empty() || route->batches.back().x != batch)
                route->batches.emplace_back(batch, static_cast<std::uint32_t>(first), 0u);
            route->batches.back().z += static_cast<std::uint32_t>(job_work[j]);
            first += job_work[j];
        }
    }
    std::size_t next = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        Range& r = ranges[jobs[j].batch];
        if (r.count == 0) r.first = next;
        r.count += job_draws[j];
        next += job_draws[j];
        if (r.one_sided == 0) r.first_one_sided = next_one_sided;
        r.one_sided += job_one_sided[j];
        next_one_sided += job_one_sided[j];
    }
    if (!draws.empty()) {
        ctx.triangle_draws->set(std::span<const TriangleDraw>(draws), GL_STREAM_DRAW);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.triangle_draws->id());
    }
    for (std::size_t i = 0; i < ctx.batches.batches.size(); ++i) {
        const Batch& b = ctx.batches.batches[i];
        if (occluders_only && !b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        const bool culled = culls_clusters(ctx, mesh, moves_vertices) && !ranges[i].whole;
        if (culled && ranges[i].count == 0 && ranges[i].one_sided == 0) continue;
        // Back faces of an outward-closed mesh seen from outside are hidden by its front faces.
        const bool cull = front_faces_only || (b.eye_outside && mesh.outward_closed);
        if (cull != state.cull_back) {
            state.cull_back = cull;
            gl::apply(state);
        }
        (mesh.*vao).bind();
        if (culled) {
            if (ranges[i].count > 0) {
                glMultiDrawElementsIndirect(
                    GL_TRIANGLES, GL_UNSIGNED_INT,
                    reinterpret_cast<const void*>(ranges[i].first * sizeof(TriangleDraw)),
                    static_cast<GLsizei>(ranges[i].count), 0);
            }
            if (ranges[i].one_sided > 0) {
                if (!state.cull_back) {
                    state.cull_back = true;
                    gl::apply(state);
                }
                glMultiDrawElementsIndirect(
                    GL_TRIANGLES, GL_UNSIGNED_INT,
                    reinterpret_cast<const void*>(ranges[i].first_one_sided * sizeof(TriangleDraw)),
                    static_cast<GLsizei>(ranges[i].one_sided), 0);
            }
        } else {
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.triangle_index_count,
                                                GL_UNSIGNED_INT, nullptr, b.instance_count,
                                                b.first_instance);
        }
    }
    if (!draws.empty()) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    return stats;
}

// Early-Z: fill the depth texture the spine test reads. Both faces are drawn so open,
// single-sided surfaces still hide what is behind them; back faces are culled only for
// outward-closed meshes seen from outside, whose back faces their front faces hide anyway.
// On a software rasteriser the small clusters go to a compute shader (prepass_raster.h).
void pass_prepass(const PassContext& ctx) {
    ctx.targets.depth_fbo.bind();
    const gl::PipelineState state = depth_writing_state(ctx, false);
    gl::apply(state);
    glClearDepth(depth_clear_value(ctx));
    glClear(GL_DEPTH_BUFFER_BIT);
    if (!ctx.occlusion) return;
    ctx.programs.prepass.use();
    ctx.programs.prepass.set("u_proj", ctx.cam.proj);
    std::optional<RasterRoute> route;
    if (computes_prepass(ctx))
        route.emplace(HizView(ctx.cam.proj, ctx.cam.near, ctx.targets.width, ctx.targets.height));
    const TriangleCullStats culled = draw_batch_triangles(ctx, state, true, &GpuMesh::prepass_vao,
                                                          false, false, route ? &*route : nullptr);
    TriangleCullStats stats = culled;
    if (route && !raster_routed_clusters(ctx, *route, state)) stats.triangles_computed = 0;
    if (ctx.stats) ctx.stats->triangle_culling = stats;
}

}  // namespace bz::render
