#pragma once
// Level objects are made by kind name ("cube", "pyramid", "model", ...) through this table, so
// a loader never names a concrete type: adding a kind means registering one more factory.
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "scene/entity.h"

namespace bz::scene {

// Where and how to place one object; mirrors the level file's object entry without depending
// on the level module.
struct Placement {
    std::string kind;
    glm::dvec3 position{0.0};
    double heading_deg = 0.0;
    double scale = 1.0;
    glm::vec3 color{0.2f, 1.0f, 0.3f};
    std::filesystem::path model;  // only for kinds that load a model file
};

using Factory = std::function<Entity(const Placement&)>;

class FactoryTable {
  public:
    // Registers (or replaces) the factory for `kind`.
    void add(std::string kind, Factory factory);
    bool contains(std::string_view kind) const;
    // Throws UserError naming the kind and the known kinds when `kind` is not registered.
    Entity create(const Placement& placement) const;
    // Registered kinds, sorted.
    std::vector<std::string> kinds() const;

  private:
    std::map<std::string, Factory, std::less<>> factories_;
};

}  // namespace bz::scene
