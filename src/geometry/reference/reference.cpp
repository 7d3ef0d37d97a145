#include "geometry/reference/reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/reference/reference_bvh.h"
#include "geometry/reference/reference_edges.h"
#include "geometry/reference/reference_raster.h"

namespace bz::geo {

namespace {

using detail::ClippedEdge;
using detail::FeatureEdge;

void check_inputs(std::span<const ReferenceInstance> instances, const ReferenceView& v,
                  const ReferenceOptions& o) {
    if (v.width < 1 || v.height < 1)
        throw std::invalid_argument("reference: image size must be >= 1x1");
    if (!(v.fov_y_deg > 0.0 && v.fov_y_deg < 180.0))
        throw std::invalid_argument("reference: fov must be in (0, 180)");
    if (!(v.near > 0.0 && v.far > v.near && std::isfinite(v.far))) {
        throw std::invalid_argument("reference: need 0 < near < far < inf");
    }
    if (!(o.samples_per_pixel > 0.0) || o.refine_steps < 0 || !(o.relative_epsilon >= 0.0) ||
        o.hidden_levels < 0 || o.hidden_levels > kMaxOcclusionLevel) {
        throw std::invalid_argument("reference: bad sampling options");
    }
    for (const ReferenceInstance& i : instances) {
        if (!i.mesh) throw std::invalid_argument("reference: instance without a mesh");
    }
}

std::vector<glm::dvec3> view_positions(const ReferenceInstance& inst) {
    std::vector<glm::dvec3> out;
    out.reserve(inst.mesh->positions.size());
    for (const glm::vec3& p : inst.mesh->positions) {
        out.push_back(glm::dvec3(inst.model_view * glm::dvec4(glm::dvec3(p), 1.0)));
    }
    return out;
}

void add_occluders(const ReferenceInstance& inst, std::uint32_t index,
                   const std::vector<glm::dvec3>& vp, std::vector<detail::BvhTriangle>& out) {
    const std::vector<std::uint32_t>& t = inst.mesh->triangles;
    for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
        out.push_back({vp[t[i]], vp[t[i + 1]], vp[t[i + 2]], index, t[i], t[i + 1], t[i + 2]});
    }
}

class Visibility {
  public:
    Visibility(const detail::TriangleBvh& bvh, const detail::Projection& p,
               const ReferenceOptions& o, ReferenceStats& stats)
        : bvh_(bvh), proj_(p), options_(o), stats_(stats) {}

    // The occlusion level of the point of `e` at window parameter u (0: visible from the
    // eye), capped at options.hidden_levels (so 0 or 1 when only visibility is asked for).
    int operator()(const ClippedEdge& e, const FeatureEdge& f, double u) const {
        if (!options_.occlusion) return 0;
        ++stats_.rays;
        const glm::dvec3 point = e.at(u);
        const double depth = -point.z;
        if (!(depth > 0.0)) return 0;
        // Only what lies at or beyond the near plane is in the depth buffer the GPU tests.
        const double t_min = proj_.near / depth;
        const double t_max = 1.0 - options_.relative_epsilon;
        const detail::ExcludedEdge own{f.instance, f.va, f.vb, {f.faces[0], f.faces[1]}};
        if (!bvh_.any_hit(glm::dvec3(0.0), point, t_min, t_max, own)) return 0;
        if (options_.hidden_levels <= 1) return 1;
        const int front = bvh_.count_front_hits(glm::dvec3(0.0), point, t_min, t_max, own,
                                                options_.hidden_levels);
        return std::clamp(front, 1, options_.hidden_levels);
    }

  private:
    const detail::TriangleBvh& bvh_;
    detail::Projection proj_;
    const ReferenceOptions& options_;
    ReferenceStats& stats_;
};

// Samples the occlusion level along the on-screen part of the edge and appends each stretch of
// one level that is kept (level 0, and up to hidden_levels); where the level changes between
// two samples, bisection finds each switch.
void split_edge(const ClippedEdge& e, const FeatureEdge& f, const Visibility& level_at,
                const detail::Projection& p, const ReferenceOptions& o,
                std::vector<VisibleSegment>& out, ReferenceStats& stats) {
    const auto range =
        detail::clip_to_rect(e.sa, e.sb, {-1.0, -1.0}, {p.width + 1.0, p.height + 1.0});
    if (!range) return;
    ++stats.drawn_edges;
    const double u0 = (*range)[0], u1 = (*range)[1];
    const double edge_px = glm::length(e.sb - e.sa);
    const double len_px = edge_px * (u1 - u0);
    const int n = std::max(1, static_cast<int>(std::ceil(len_px * o.samples_per_pixel)));
    auto window = [&](double u) { return e.sa + (e.sb - e.sa) * u; };
    auto param = [&](int i) { return u0 + (u1 - u0) * (static_cast<double>(i) / n); };
    const int keep = o.occlusion ? o.hidden_levels : 0;
    const bool two_levels = o.hidden_levels <= 1;
    auto emit = [&](double from, double to, int level) {
        if (level > keep) return;
        out.push_back({window(from), window(to), f.kind, f.instance,
                       static_cast<std::uint8_t>(level), edge_px * from});
    };

    int level = level_at(e, f, u0);
    double run_start = u0;
    double prev_u = u0;
    for (int i = 1; i <= n; ++i) {
        const double u = param(i);
        const int next = level_at(e, f, u);
        // Several switches may lie between two samples (a level-2 stretch between a hidden
        // and a visible one): find them one by one, a few at most.
        double from = prev_u;
        for (int found = 0; next != level && found < kMaxOcclusionLevel + 1; ++found) {
            double lo = from, hi = u;
            for (int s = 0; s < o.refine_steps; ++s) {
                const double mid = 0.5 * (lo + hi);
                (level_at(e, f, mid) == level ? lo : hi) = mid;
            }
            emit(run_start, lo, level);
            // With two levels only, the other one is `next`: no ray needed.
            level = hi == u || two_levels ? next : level_at(e, f, hi);
            run_start = hi;
            from = hi;
        }
        if (level != next) {  // switches closer than the bisection resolves
            emit(run_start, from, level);
            level = next;
            run_start = from;
        }
        prev_u = u;
    }
    emit(run_start, u1, level);
}

}  // namespace

std::vector<VisibleSegment> reference_segments(std::span<const ReferenceInstance> instances,
                                               const ReferenceView& view,
                                               const ReferenceOptions& options,
                                               ReferenceStats* stats_out) {
    check_inputs(instances, view, options);
    ReferenceStats stats;
    std::vector<FeatureEdge> edges;
    std::vector<detail::BvhTriangle> occluders;
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const ReferenceInstance& inst = instances[i];
        const std::vector<glm::dvec3> vp = view_positions(inst);
        const auto index = static_cast<std::uint32_t>(i);
        detail::find_feature_edges(inst, index, vp, edges);
        if (inst.occluder && options.occlusion) add_occluders(inst, index, vp, occluders);
    }
    if (options.intersection_lines) detail::find_intersection_edges(instances, edges);
    stats.feature_edges = edges.size();
    stats.occluder_triangles = occluders.size();
    const detail::TriangleBvh bvh(std::move(occluders));
    const detail::Projection proj = detail::Projection::of(view);
    const Visibility visible(bvh, proj, options, stats);

    std::vector<VisibleSegment> segments;
    for (const FeatureEdge& f : edges) {
        const auto clipped = detail::clip_edge(f.a, f.b, proj);
        if (clipped) split_edge(*clipped, f, visible, proj, options, segments, stats);
    }
    if (stats_out) *stats_out = stats;
    return segments;
}

std::size_t mark_segments(std::span<const VisibleSegment> segments, int width, int height,
                          std::vector<std::uint8_t>& mask) {
    std::size_t lit = 0;
    for (const VisibleSegment& s : segments)
        if (s.level == 0) lit += detail::mark_segment(mask, width, height, s.a, s.b);
    return lit;
}

std::vector<std::uint8_t> reference_mask(std::span<const ReferenceInstance> instances,
                                         const ReferenceView& view, const ReferenceOptions& options,
                                         ReferenceStats* stats_out) {
    ReferenceStats stats;
    const std::vector<VisibleSegment> segments =
        reference_segments(instances, view, options, &stats);
    std::vector<std::uint8_t> mask(
        static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height), 0);
    stats.lit_pixels = mark_segments(segments, view.width, view.height, mask);
    if (stats_out) *stats_out = stats;
    return mask;
}

}  // namespace bz::geo
