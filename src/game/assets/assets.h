#pragma once
// Every mesh the game draws, built once and shared by all instances: the enemies, shells,
// debris, the level's obstacle kinds and the horizon. Also the kind -> factory table.
#include <memory>

#include "game/assets/backdrop.h"
#include "game/world/world.h"
#include "level/level.h"
#include "scene/factory_table.h"
#include "scene/mesh_library.h"

namespace bz::game {

class Assets {
  public:
    explicit Assets(const level::Backdrop& backdrop);
    // With the level's models imported up front, confined to the level's folders (the model
    // factory alone would import a model on first use, confined to the model's own folder).
    // Throws UserError (file:line:col) when a kind is unknown or a model does not import.
    explicit Assets(const level::Level& level);
    Assets(const Assets&) = delete;
    Assets& operator=(const Assets&) = delete;

    const scene::MeshLibrary& meshes() const { return *library_; }
    // Level objects by kind; "model" imports into meshes() on first use.
    const scene::FactoryTable& factories() const { return factories_; }
    const ModelIds& models() const { return models_; }
    const backdrop::Ids& horizon() const { return horizon_; }

    // Brings the meshes up to date for an edited level, in the same library so that every id
    // stays valid and the renderer's cache sees a new version: the horizon, and each model the
    // level names (imported again: its file may have changed). Only meshes whose geometry
    // changed get a new version. Throws UserError (file:line:col) with nothing changed when
    // an object's kind is unknown or a model does not import.
    void reload(const level::Level& level);

  private:
    std::unique_ptr<scene::MeshLibrary> library_;  // stable address for the model factory
    scene::FactoryTable factories_;
    ModelIds models_;
    backdrop::Ids horizon_;
};

}  // namespace bz::game
