#include "scene/mesh_library.h"

namespace bz::scene {

MeshId MeshLibrary::add(const std::string& name, geo::AdjacencyMesh mesh) {
    const geo::Bounds bounds = geo::compute_bounds(mesh.positions);
    auto shared = std::make_shared<const geo::AdjacencyMesh>(std::move(mesh));
    if (auto it = by_name_.find(name); it != by_name_.end()) {
        Entry& e = entries_[it->second];
        e.mesh = std::move(shared);
        e.bounds = bounds;
        ++e.version;
        return it->second;
    }
    const auto id = static_cast<MeshId>(entries_.size());
    entries_.push_back({name, std::move(shared), bounds, 0});
    by_name_.emplace(name, id);
    return id;
}

std::optional<MeshId> MeshLibrary::find(const std::string& name) const {
    if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
    return std::nullopt;
}

}  // namespace bz::scene
