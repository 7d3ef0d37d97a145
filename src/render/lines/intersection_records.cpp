#include "render/lines/intersection_records.h"

namespace bz::render {

std::vector<IntersectionRecord> intersection_records(std::span<const WorldIntersection> segments,
                                                     const FrameBatches& batches,
                                                     const std::vector<scene::DrawItem>& items,
                                                     const glm::dmat4& view) {
    // Which instances are drawn at full detail.
    std::vector<bool> full_detail(batches.instances.size(), false);
    for (const Batch& b : batches.batches)
        for (GLsizei i = 0; i < b.instance_count; ++i)
            full_detail[b.first_instance + static_cast<std::size_t>(i)] = b.lod == 0;
    auto drawn = [&](std::uint32_t item) {
        if (item >= batches.instance_of_item.size()) return false;
        const std::uint32_t inst = batches.instance_of_item[item];
        return inst < full_detail.size() && full_detail[inst];
    };
    // Normals go with the inverse transpose (the view is rigid, but nothing here relies on it).
    const glm::dmat3 normals = glm::transpose(glm::inverse(glm::dmat3(view)));
    auto unit = [](const glm::dvec3& v) {
        const double len = glm::length(v);
        return len > 0.0 ? v / len : glm::dvec3(0.0);
    };
    std::vector<IntersectionRecord> out;
    out.reserve(segments.size());
    for (const WorldIntersection& s : segments) {
        if (!drawn(s.first) || !drawn(s.second)) continue;
        IntersectionRecord r;
        r.a = glm::vec4(glm::vec3(view * glm::dvec4(s.a, 1.0)), 0.0f);
        r.b = glm::vec4(glm::vec3(view * glm::dvec4(s.b, 1.0)), 0.0f);
        r.normal_a = glm::vec4(glm::vec3(unit(normals * s.normal_first)), 0.0f);
        r.normal_b = glm::vec4(glm::vec3(unit(normals * s.normal_second)), 0.0f);
        r.ids = glm::uvec4(batches.instance_of_item[s.first], s.id, items[s.first].mesh, 0u);
        out.push_back(r);
    }
    return out;
}

}  // namespace bz::render
