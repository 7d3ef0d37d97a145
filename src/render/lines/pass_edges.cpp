#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "core/parallel_chunks.h"
#include "render/gpu_scene/batches.h"
#include "render/gpu_scene/cluster_culling.h"
#include "render/lines/edge_culling.h"
#include "render/lines/edge_prefilter.h"
#include "render/lines/hiz_culling.h"
#include "render/passes.h"

namespace bz::render {

namespace {

// Back faces of an outward-closed mesh seen from outside hold no visible line, so their edges
// are skipped, unless the style draws hidden lines (technical: a box's back edges, dashed).
bool skips_back_faces(const PassContext& ctx, const Batch& b, const GpuMesh& mesh) {
    return ctx.occlusion && ctx.style.hidden.levels == 0 && b.eye_outside && mesh.outward_closed;
}

// The edge buffer is sized for every edge of the frame when that is small, else for this many
// and grown when a frame appends more (EdgeStorage::keep_count).
constexpr std::size_t kInitialRecords = std::size_t{1} << 16;
constexpr GLuint kMaxGroups = 65535;  // the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT allowed
// A big instance's clusters are culled (and prefiltered) by several threads, this many a job.
constexpr std::size_t kClustersPerJob = 1024;

}  // namespace

bool records_carry_normals(const StyleDef& style) {
    return style.lines == LinePass::sketch || style.lines == LinePass::halo;
}

// Edge extraction for LineMethod::compute: the CPU culls each instance's edge clusters
// (edge_culling.h) into work items, then one dispatch per batch runs one work group per item
// (edges.comp), appending the visible feature edges to the edge buffer. With the CPU
// prefilter (edge_prefilter.h, software rasterisers) the items' edges that may be feature
// edges are listed instead, EDGE_GROUP_SIZE to a group.
void pass_edges(const PassContext& ctx) {
    // The work buffer: every instance's object-space eye first, then the batches' items.
    const std::vector<InstanceData>& instances = ctx.batches.instances;
    std::vector<EdgeWorkItem> work;
    work.reserve(instances.size() * 2);
    for (const InstanceData& d : instances)
        work.push_back(glm::floatBitsToUint(object_space_eye(d.model_view)));
    const CullView view{.proj = ctx.cam.proj, .near = ctx.cam.near, .far = ctx.cam.far};
    // Hierarchical-Z: the depth tiles pass ran before this one and found the frame worth it.
    const bool hiz = frame_wrote(ctx, Resource::depth_tiles) && hiz_culls(ctx);
    const HizView hiz_view(ctx.cam.proj, ctx.cam.near, ctx.targets.width, ctx.targets.height);
    // On a software rasteriser the CPU lists the edges that may be feature edges
    // (edge_prefilter.h).
    const bool listed = uses_edge_prefilter(ctx.settings, ctx.software_rasteriser);
    EdgeCullStats cull;
    struct Dispatch {
        const Batch* batch;
        const GpuMesh* mesh;
        std::size_t first, count;  // its items in `work`
    };
    // One job per instance, or per stretch of a big instance's clusters; the meshes are
    // fetched (and uploaded) here, on the GL thread.
    struct Job {
        std::size_t dispatch;  // its batch's entry in `dispatches`
        const GpuMesh* mesh;
        GLuint instance;
        bool skip_back_faces;
        std::size_t first_cluster, end_cluster;
    };
    std::vector<Dispatch> dispatches;
    std::vector<Job> jobs;
    std::size_t clusters = 0;
    for (const Batch& b : ctx.batches.batches) {
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        if (mesh.edge_count == 0) continue;
        const bool skip_back_faces = skips_back_faces(ctx, b, mesh);
        const std::size_t n = mesh.edge_clusters.clusters.size();
        for (GLsizei i = 0; i < b.instance_count; ++i) {
            for (std::size_t first = 0; first < n; first += kClustersPerJob)
                jobs.push_back({.dispatch = dispatches.size(),
                                .mesh = &mesh,
                                .instance = b.first_instance + static_cast<GLuint>(i),
                                .skip_back_faces = skip_back_faces,
                                .first_cluster = first,
                                .end_cluster = std::min(n, first + kClustersPerJob)});
        }
        clusters += mesh.edge_clusters.clusters.size() * static_cast<std::size_t>(b.instance_count);
        dispatches.push_back({.batch = &b, .mesh = &mesh, .first = 0, .count = 0});
    }
    // Culling runs on several threads when there is enough of it; chunks keep job order, so
    // the items are the same as one thread's.
    const std::size_t threads = clusters >= kCullPairsPerThread ? ctx.workers.max_threads() : 1;
    const std::size_t chunks = chunk_count(jobs.size(), 1, threads);
    std::vector<std::vector<EdgeWorkItem>> chunk_work(chunks);
    std::vector<std::vector<HizBounds>> chunk_bounds(chunks);
    std::vector<EdgeCullStats> chunk_stats(chunks);
    std::vector<std::size_t> job_items(jobs.size());
    parallel_chunks(ctx.workers, jobs.size(), 1, threads, [&](std::size_t j, std::size_t c) {
        const Job& job = jobs[j];
        const std::size_t before = chunk_work[c].size();
        append_edge_work(job.mesh->edge_clusters, instances[job.instance].model_view,
                         instances[job.instance].params.x, job.skip_back_faces, view, job.instance,
                         chunk_work[c], chunk_stats[c],
                         {.hiz = hiz ? &hiz_view : nullptr,
                          .bounds = &chunk_bounds[c],
                          .prefilter = listed ? &job.mesh->edge_facing : nullptr,
                          .first_cluster = job.first_cluster,
                          .end_cluster = job.end_cluster});
        job_items[j] = chunk_work[c].size() - before;
    });
    // Listed entries name their bounds record by its place among the chunk's; the records
    // follow one (unread) per eye, as an item's record sits where the item sits.
    auto bounds_before = static_cast<std::uint32_t>(instances.size());
    for (std::size_t c = 0; c < chunks; ++c) {
        if (listed)
            for (EdgeWorkItem& entry : chunk_work[c]) entry.z += bounds_before;
        bounds_before += static_cast<std::uint32_t>(chunk_bounds[c].size());
        work.insert(work.end(), chunk_work[c].begin(), chunk_work[c].end());
        cull += chunk_stats[c];
    }
    std::size_t next = instances.size();  // the items follow the eyes
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        Dispatch& d = dispatches[jobs[j].dispatch];
        if (d.count == 0) d.first = next;
        d.count += job_items[j];
        next += job_items[j];
    }
    std::erase_if(dispatches, [](const Dispatch& d) { return d.count == 0; });
    if (ctx.stats) ctx.stats->edge_culling = cull;

    // A previous frame that overflowed asks for more; a frame that cannot overflow gets it all.
    const EdgeDrawCommand previous = ctx.edges.previous();
    // At most one record per dispatched edge and intersection segment.
    ctx.edges.reserve(std::min(
        cull.edges_dispatched + ctx.intersection_count,
        std::max(kInitialRecords, std::size_t{previous.vertex_count / kVerticesPerEdge} + 1024)));
    const bool samples = wants_spine_samples(ctx);
    if (samples)
        ctx.edges.reserve_samples(std::size_t{previous.samples_used} + previous.samples_used / 4);
    ctx.edges.reset();
    if (dispatches.empty()) {
        append_intersections(ctx, samples);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        return;
    }
    // With hierarchical-Z, each entry's bounds record follows the whole list (the eyes' are
    // never read).
    const auto bounds_offset = static_cast<GLuint>(work.size());
    if (hiz) {
        work.resize(work.size() + instances.size(), kNoHizTest);
        for (const std::vector<HizBounds>& b : chunk_bounds)
            work.insert(work.end(), b.begin(), b.end());
    }
    ctx.edges.set_work(work);

    const Programs& programs = ctx.programs;
    const gl::Program& program =
        records_carry_normals(ctx.style)
            ? (listed ? programs.edges_listed_normals : programs.edges_normals)
            : (listed ? programs.edges_listed : programs.edges);
    program.use();
    program.set("u_proj", ctx.cam.proj);
    program.set("u_viewport", glm::vec2(static_cast<float>(ctx.targets.width),
                                        static_cast<float>(ctx.targets.height)));
    program.set("u_near", ctx.cam.near);
    program.set("u_far", ctx.cam.far);
    program.set("u_capacity", ctx.edges.capacity());
    program.set("u_sample_capacity", samples ? ctx.edges.sample_capacity() : 0u);
    // A fragment in the viewport lies within its beam's half-width of its spine point: cover that.
    program.set("u_sample_margin", 16.0f);
    program.set("u_sample_spacing", ctx.settings.spine_sample_spacing_px);
    program.set("u_hiz", hiz ? 1 : 0);
    program.set("u_bounds_offset", bounds_offset);
    if (hiz) {
        // Four times the spine test's relative tolerances and at least 1 %: a sphere that
        // close behind the tiles' farthest surface is tested edge by edge.
        const auto& s = ctx.settings;
        program.set("u_hiz_rel", std::max(0.01f, 4.0f * (s.plane_tolerance_rel + s.depth_bias)));
        program.set("u_hiz_abs", 4.0f * spine_tolerance_abs(ctx));
        glBindTextureUnit(kTextureUnitDepthTiles, ctx.targets.depth_tiles.id());
        glBindTextureUnit(kTextureUnitDepthTilesCoarse, ctx.targets.depth_tiles_coarse.id());
    } else {
        program.set("u_hiz_rel", 0.0f);
        program.set("u_hiz_abs", 0.0f);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding, ctx.instances.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, ctx.edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, ctx.edges.spans().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeWorkBinding, ctx.edges.work().id());
    // A group takes one item, or EDGE_GROUP_SIZE listed entries.
    const std::size_t per_group = listed ? edge_group_size(ctx.software_rasteriser) : 1;
    for (const Dispatch& d : dispatches) {
        const Batch& b = *d.batch;
        const GpuMesh& mesh = *d.mesh;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeListBinding, mesh.edge_list.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgePositionsBinding, mesh.positions.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexNormalsBinding, mesh.vertex_normals.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFaceNormalsBinding, mesh.face_normals.id());
        program.set("u_skip_back_faces", skips_back_faces(ctx, b, mesh) ? 1 : 0);
        program.set("u_mesh_id", static_cast<unsigned>(b.mesh));
        program.set("u_material_lines", material_lines_for(ctx.settings, b, mesh) ? 1 : 0);
        program.set("u_work_end", static_cast<GLuint>(d.first + d.count));
        // Chunks keep the work-group count within the limit every implementation allows.
        const std::size_t chunk = kMaxGroups * per_group;
        for (std::size_t item0 = 0; item0 < d.count; item0 += chunk) {
            const std::size_t items = std::min(chunk, d.count - item0);
            program.set("u_work_base", static_cast<GLuint>(d.first + item0));
            glDispatchCompute(static_cast<GLuint>((items + per_group - 1) / per_group), 1, 1);
        }
    }
    append_intersections(ctx, samples);
    // The quad pass reads the records in its vertex shader and the count as its draw command.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace bz::render
