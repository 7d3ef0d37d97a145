#pragma once
// Culling before vertex work in the passes that draw triangles (the depth prepass, the fills):
// each instance's triangle clusters (geometry/derived/triangle_clusters.h) are tested against
// the view on the CPU, and the runs of kept clusters become indirect draws. Dropped:
//  - a cluster outside the view frustum (it would be clipped whole);
//  - a cluster whose faces all face away, where the pass culls back faces anyway (an
//    outward-closed mesh seen from outside): the picture is the same, minus the vertex work.
#include <cstdint>
#include <vector>

#include "geometry/derived/triangle_clusters.h"
#include "gl/indirect_commands.h"
#include "render/gpu_scene/cluster_culling.h"
#include "render/lines/hiz_culling.h"

namespace bz::render {

// One glMultiDrawElementsIndirect command: a run of kept clusters of one instance.
using TriangleDraw = gl::DrawElementsIndirectCommand;

struct TriangleCullStats {
    std::size_t clusters = 0;         // (instance, cluster) pairs looked at
    std::size_t outside_frustum = 0;  // dropped: outside the view
    std::size_t facing_away = 0;      // dropped: every face away, back faces culled
    std::size_t triangles = 0;        // triangles of the clusters looked at
    std::size_t triangles_drawn = 0;  // triangles of the kept clusters
    // Of those, the triangles of clusters rasterised by the compute prepass (RasterRoute).
    std::size_t triangles_computed = 0;
    // Kept clusters drawn with back faces culled where the batch keeps both.
    std::size_t one_sided = 0;
    TriangleCullStats& operator+=(const TriangleCullStats& o) {
        one_sided += o.one_sided;
        clusters += o.clusters;
        outside_frustum += o.outside_frustum;
        facing_away += o.facing_away;
        triangles += o.triangles;
        triangles_drawn += o.triangles_drawn;
        triangles_computed += o.triangles_computed;
        return *this;
    }
};

// Where the compute prepass takes the clusters it rasterises (render/lines/prepass_raster.h): a
// kept cluster whose bounding sphere lies wholly beyond the near plane and covers at most
// kMaxRasterClusterPx window pixels each way becomes a work item here instead of a draw.
inline constexpr float kMaxRasterClusterPx = 48.0f;
// One routed cluster of one instance, as prepass_raster.comp reads it (one uvec4).
struct RasterItem {
    std::uint32_t instance = 0;
    std::uint32_t first_triangle = 0;  // into the mesh's triangles and corners
    std::uint32_t triangles = 0;       // at most 255
    std::uint32_t first_vertex = 0;    // into the mesh's cluster vertex lists
    std::uint32_t vertices = 0;        // at most geo::kClusterVertices
    bool skip_back_faces = false;
};
inline glm::uvec4 pack(const RasterItem& i) {
    return {i.instance, i.first_triangle,
            i.triangles | i.vertices << 8 | (i.skip_back_faces ? 1u << 16 : 0u), i.first_vertex};
}
inline RasterItem unpack(const glm::uvec4& w) {
    return {w.x, w.y, w.z & 0xFFu, w.w, (w.z >> 8) & 0xFFu, ((w.z >> 16) & 1u) != 0u};
}

struct RasterRoute {
    explicit RasterRoute(const HizView& v) : view(v) {}
    HizView view;
    std::vector<glm::uvec4> work;  // pack(RasterItem)
    // The union of the routed clusters' rectangles (empty while lo > hi).
    glm::vec2 lo{1e30f}, hi{-1e30f};
    // Filled by draw_batch_triangles (render/passes.h): per batch with work, x the batch's
    // index in FrameBatches, y its first work item, z its count (one mesh per dispatch).
    std::vector<glm::uvec3> batches;
    void take(const RasterRoute& o);  // appends o's work and widens the union
};

// Appends one draw per run of consecutive kept clusters of instance `instance`, or with a
// `route`, one work item per small kept cluster to it and draws for the rest.
// `all`: a sphere around all the clusters (ClusteredTriangles::all). With `one_sided`, a
// cluster of outward-closed pieces seen from outside their box (geo::TriangleCluster::closed)
// goes there instead of to `draws`, for a draw with back faces culled, and is dropped when it
// faces away wholly, even where the batch keeps both faces.
void append_triangle_draws(const std::vector<geo::TriangleCluster>& clusters,
                           const geo::ClusterBounds& all, const glm::mat4& model_view,
                           bool skip_back_faces, const ViewVolume& view, std::uint32_t instance,
                           std::vector<TriangleDraw>& draws, TriangleCullStats& stats,
                           RasterRoute* route = nullptr,
                           std::vector<TriangleDraw>* one_sided = nullptr);

}  // namespace bz::render
