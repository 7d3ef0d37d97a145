#include "game/assets/scene_budget.h"

#include <set>

#include "core/budgets.h"
#include "core/error.h"
#include "core/text/printable.h"
#include "game/assets/models.h"
#include "level/diagnostic.h"
#include "level/kinds.h"

namespace bz::game {

namespace {

std::string count(std::int64_t n) {
    std::string digits = std::to_string(n);
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
        digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

[[noreturn]] void over(const level::ObjectDesc& o, const std::string& what, std::int64_t total,
                       std::int64_t budget) {
    throw UserError(level::where(o.pos) + "error: this object takes the scene to " + count(total) +
                    " " + what + ", over the budget of " + count(budget) +
                    " (place fewer objects or use a smaller model)");
}

}  // namespace

SceneCost check_scene_budget(const level::Level& level,
                             const std::map<std::string, std::int64_t>& model_triangles) {
    SceneCost cost;
    // Built-in kinds are counted by their own meshes (game/assets/models.h), so the count is
    // what the GPU draws and follows any change to those meshes.
    std::map<std::string, std::int64_t> builtin_triangles;
    std::set<std::string> counted;
    for (const level::ObjectDesc& o : level.obstacles) {
        ++cost.instances;
        if (cost.instances > budget::kSceneInstances)
            over(o, "objects", cost.instances, budget::kSceneInstances);
        const std::map<std::string, std::int64_t>* table = &model_triangles;
        std::string key = o.model.string();
        if (o.model.empty()) {
            const level::BuiltinKind* kind = level::find_kind(o.kind);
            if (!kind || kind->shape == level::KindShape::model) continue;
            key = "builtin:" + o.kind;
            if (!builtin_triangles.contains(key)) {
                builtin_triangles[key] =
                    static_cast<std::int64_t>(models::obstacle(*kind).triangle_count());
            }
            table = &builtin_triangles;
        }
        const auto it = table->find(key);
        if (it == table->end()) continue;
        cost.triangles += it->second;
        if (cost.triangles > budget::kSceneTriangles)
            over(o, "triangles", cost.triangles, budget::kSceneTriangles);
        if (counted.insert(it->first).second) {
            cost.gpu_bytes += it->second * budget::kGpuBytesPerTriangle;
            if (cost.gpu_bytes > budget::kSceneGpuBytes)
                over(o, "bytes of GPU memory (estimated)", cost.gpu_bytes, budget::kSceneGpuBytes);
        }
    }
    return cost;
}

}  // namespace bz::game
