#pragma once
// CPU meshes by id, shared by every instance that shows them. The renderer's mesh cache
// uploads each id once and re-uploads when its version changes (hot reload).
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/mesh.h"
#include "scene/frame_list.h"

namespace bz::scene {

class MeshLibrary {
  public:
    // Adds a mesh under a unique name (a model path or "builtin:cube" and so on); adding an
    // existing name replaces its mesh and bumps its version.
    MeshId add(const std::string& name, geo::AdjacencyMesh mesh);
    std::optional<MeshId> find(const std::string& name) const;
    const geo::AdjacencyMesh& mesh(MeshId id) const { return *entries_.at(id).mesh; }
    const std::string& name(MeshId id) const { return entries_.at(id).name; }
    std::uint32_t version(MeshId id) const { return entries_.at(id).version; }
    const geo::Bounds& bounds(MeshId id) const { return entries_.at(id).bounds; }
    std::size_t size() const { return entries_.size(); }

  private:
    struct Entry {
        std::string name;
        std::shared_ptr<const geo::AdjacencyMesh> mesh;
        geo::Bounds bounds;
        std::uint32_t version = 0;
    };
    std::vector<Entry> entries_;
    std::unordered_map<std::string, MeshId> by_name_;
};

}  // namespace bz::scene
