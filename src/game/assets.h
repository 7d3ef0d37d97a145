#pragma once
// Every mesh the game draws, built once and shared by all instances: the enemies, shells,
// debris, the level's obstacle kinds and the horizon. Also the kind -> factory table.
#include <memory>

#include "game/backdrop.h"
#include "game/world.h"
#include "level/level.h"
#include "scene/factory_table.h"
#include "scene/mesh_library.h"

namespace bz::game {

class Assets {
  public:
    explicit Assets(const level::Backdrop& backdrop);
    Assets(const Assets&) = delete;
    Assets& operator=(const Assets&) = delete;

    const scene::MeshLibrary& meshes() const { return *library_; }
    // Level objects by kind; "model" imports into meshes() on first use.
    const scene::FactoryTable& factories() const { return factories_; }
    const ModelIds& models() const { return models_; }
    const backdrop::Ids& horizon() const { return horizon_; }

  private:
    std::unique_ptr<scene::MeshLibrary> library_;  // stable address for the model factory
    scene::FactoryTable factories_;
    ModelIds models_;
    backdrop::Ids horizon_;
};

}  // namespace bz::game
