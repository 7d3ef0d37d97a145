#include <array>

#include "level/kinds.h"
#include "level/sections/model_path.h"
#include "level/sections/placement.h"
#include "level/sections/sections.h"

namespace bz::level::detail {

namespace {

constexpr std::array<std::string_view, 7> kObstacleKeys = {"kind",  "model", "position", "heading",
                                                           "scale", "color", "radius"};

constexpr auto kKindNames = [] {
    std::array<std::string_view, std::size(kBuiltinKinds)> names{};
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = kBuiltinKinds[i].name;
    return names;
}();

constexpr Range kScaleRange{0.05, 100.0};
constexpr Range kRadiusRange{0.1, 1000.0};

// Reads `model` of a kind = "model" obstacle; false when it is missing or refused.
bool read_model(TableReader& r, ObjectDesc& o, ReadContext& ctx) {
    if (!r.has("model")) {
        r.missing("model");
        return false;
    }
    const auto text = r.text("model", 1024);
    if (!text) return false;
    const ModelPath path = resolve_model_path(*text, ctx.model_roots);
    if (path.watchable) ctx.dependencies.push_back(path.resolved);
    if (!path.error.empty()) {
        ctx.diag.error(r.get("model")->source(), path.error);
        return false;
    }
    o.model = path.resolved;
    return true;
}

void check_start_clear(const Level& level, const ObjectDesc& o, const BuiltinKind& kind,
                       const toml::node& position_node, Diagnostics& diag, std::size_t index) {
    const double gap =
        footprint_distance(o, kind, level.player_start, level.field_size, level.wrap);
    if (gap >= kPlayerFootprintRadius) return;
    diag.error(position_node.source(),
               "obstacle " + std::to_string(index) + " (" + o.kind +
                   ") overlaps the player start at (" + number_text(level.player_start.x) + ", " +
                   number_text(level.player_start.z) + "): it comes within " + number_text(gap) +
                   " units, and the tank needs " + number_text(kPlayerFootprintRadius));
}

}  // namespace

void read_obstacles(const toml::table& root, Level& level, glm::vec3 default_color,
                    ReadContext& ctx) {
    const toml::array* list =
        table_array(root, "obstacle", ctx.options.max_obstacles, "obstacles", ctx.diag);
    if (!list) return;
    level.obstacles.reserve(list->size());
    const double half = ctx.position_limit;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::node& item = *list->get(i);
        const std::size_t number = i + 1;
        const auto* t = item.as_table();
        if (!t) {
            ctx.diag.error(item.source(),
                           "each obstacle must be a table, not " + std::string(type_name(item)));
            continue;
        }
        TableReader r(*t, "obstacle " + std::to_string(number), kObstacleKeys, ctx.diag,
                      root_keys());
        ObjectDesc o;
        o.pos = r.where();
        o.color = default_color;
        bool ok = true;

        const BuiltinKind* kind = nullptr;
        if (!r.has("kind")) {
            r.missing("kind");
            ok = false;
        } else if (const auto name = r.choice("kind", kKindNames)) {
            kind = find_kind(*name);
            o.kind = *name;
        } else {
            ok = false;
        }
        const bool is_model = kind && kind->shape == KindShape::model;
        if (is_model) {
            ok = read_model(r, o, ctx) && ok;
        } else if (kind) {
            for (const std::string_view key : {"model", "radius"}) {
                if (const toml::node* n = r.get(key)) {
                    ctx.diag.error(n->source(), "'" + std::string(key) +
                                                    "' applies only to kind = "
                                                    "\"model\"; a " +
                                                    o.kind + " has a fixed size");
                    ok = false;
                }
            }
        }

        const toml::node* position_node = r.get("position");
        if (!position_node) {
            r.missing("position");
            ok = false;
        } else if (auto v =
                       r.vec3("position", {Range{-half, half}, kHeightRange, Range{-half, half}})) {
            o.position = *v;
        } else {
            ok = false;
        }
        if (r.has("heading")) {
            if (auto v = r.number("heading", kHeadingRange))
                o.heading_deg = *v;
            else
                ok = false;
        }
        if (r.has("scale")) {
            if (auto v = r.number("scale", kScaleRange))
                o.scale = *v;
            else
                ok = false;
        }
        if (r.has("color")) {
            if (auto v = r.color("color"))
                o.color = *v;
            else
                ok = false;
        }
        double radius = kind ? kind->footprint_radius : 0.0;
        if (is_model && r.has("radius")) {
            if (auto v = r.number("radius", kRadiusRange))
                radius = *v;
            else
                ok = false;
        }
        o.footprint_radius = radius * o.scale;

        if (!ok) continue;
        if (ctx.start_known) check_start_clear(level, o, *kind, *position_node, ctx.diag, number);
        level.obstacles.push_back(std::move(o));
    }
}

}  // namespace bz::level::detail
