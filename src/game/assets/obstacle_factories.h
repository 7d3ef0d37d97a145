#pragma once
// The kind -> factory table for level objects: every built-in kind of level/kinds.h plus
// "model", which imports the named mesh file once and shares it between its instances.
#include "scene/factory_table.h"
#include "scene/mesh_library.h"

namespace bz::game {

// Adds the built-in kinds' meshes to `library` and returns their factories. The table keeps a
// pointer to `library` (for "model" imports): the library must outlive it.
scene::FactoryTable make_obstacle_factories(scene::MeshLibrary& library);

}  // namespace bz::game
