#pragma once
// The scene budget (core/budgets.h): how many objects a level may place, how many triangles
// they may make together and how much GPU memory their meshes may take. Checked by `check` and
// whenever a level loads, after its models are imported and before anything is uploaded, so a
// level that places thousands of copies of a huge model is refused at once, with the level
// line of the object that crosses the budget, instead of growing without end.
#include <cstdint>
#include <map>
#include <string>

#include "level/level.h"

namespace bz::game {

struct SceneCost {
    std::int64_t instances = 0;
    std::int64_t triangles = 0;  // each instance's mesh (model or built-in) once per instance
    std::int64_t gpu_bytes = 0;  // distinct model meshes, estimated
};

// `model_triangles` maps each model path (ObjectDesc::model) to its triangle count; built-in
// kinds count their own meshes' triangles (and, once per kind, their GPU memory). Throws UserError
// "FILE:LINE:COL: error: ..." naming the first object that takes the scene over a budget. Returns
// the scene's cost.
SceneCost check_scene_budget(const level::Level& level,
                             const std::map<std::string, std::int64_t>& model_triangles);

}  // namespace bz::game
