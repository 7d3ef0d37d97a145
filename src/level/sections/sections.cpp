#include "level/sections/sections.h"

#include <algorithm>
#include <array>

#include "level/sections/suggest.h"
#include "scene/style.h"

namespace bz::level::detail {

namespace {

constexpr std::array<std::string_view, 13> kRootKeys = {
    "version", "name",     "author",  "description", "listed", "menu_order", "field",
    "player",  "obstacle", "enemies", "backdrop",    "render", "camera_key"};
constexpr std::array<std::string_view, 3> kFieldKeys = {"size", "wrap", "obstacle_color"};
constexpr std::array<std::string_view, 4> kPlayerKeys = {"position", "heading", "lives",
                                                         "bonus_scores"};
constexpr std::array<std::string_view, 16> kEnemyKeys = {"types",
                                                         "difficulty",
                                                         "super_tank_score",
                                                         "missile_score",
                                                         "saucer_score",
                                                         "spawn_min_distance",
                                                         "spawn_max_distance",
                                                         "spawn_rear_chance",
                                                         "aggression",
                                                         "fire_interval",
                                                         "aim_error",
                                                         "hold_fire",
                                                         "slow_tank_points",
                                                         "super_tank_points",
                                                         "missile_points",
                                                         "saucer_points"};
constexpr std::array<std::string_view, 3> kDifficulties = {"easy", "normal", "arcade"};
constexpr std::size_t kMaxBonusScores = 16;
constexpr std::array<std::string_view, 4> kEnemyTypes = {"slow_tank", "super_tank", "missile",
                                                         "saucer"};
constexpr std::array<std::string_view, 11> kRenderKeys = {
    "style",   "preset",    "line_width",  "crease_angle",   "bloom_strength",    "beam",
    "overlay", "hold_41hz", "line_method", "material_lines", "intersection_lines"};
// Must match bz::render::beam_look_names().
constexpr std::array<std::string_view, 2> kBeamLooks = {"classic", "mame"};
// Must match bz::render::parse_line_method ("geometry" is the old name of geometry_shader).
constexpr std::array<std::string_view, 4> kLineMethods = {"compute", "geometry_shader", "auto",
                                                          "geometry"};
// Must match bz::render::preset_names(); the level module may not link the renderer.
constexpr std::array<std::string_view, 3> kPresets = {"fast", "balanced", "high"};

constexpr std::int64_t kMaxScore = 10'000'000;

}  // namespace

std::span<const std::string_view> root_keys() {
    return kRootKeys;
}

const toml::table* section(const toml::table& root, std::string_view key, Diagnostics& diag) {
    const toml::node* node = root.get(key);
    if (!node) return nullptr;
    if (const auto* t = node->as_table()) return t;
    diag.error(node->source(), "'" + std::string(key) + "' must be a table ([" + std::string(key) +
                                   "]), not " + std::string(type_name(*node)));
    return nullptr;
}

const toml::array* table_array(const toml::table& root, std::string_view key, std::size_t max_count,
                               std::string_view plural, Diagnostics& diag) {
    const toml::node* node = root.get(key);
    if (!node) return nullptr;
    const auto* a = node->as_array();
    if (!a) {
        diag.error(node->source(), "'" + std::string(key) + "' must be a list of tables ([[" +
                                       std::string(key) + "]]), not " +
                                       std::string(type_name(*node)));
        return nullptr;
    }
    if (a->size() > max_count) {
        diag.error(node->source(), "too many " + std::string(plural) + ": " +
                                       std::to_string(a->size()) + " (the limit is " +
                                       std::to_string(max_count) + ")");
        return nullptr;
    }
    return a;
}

void read_field(const toml::table& root, Level& level, glm::vec3& obstacle_color,
                ReadContext& ctx) {
    ctx.position_limit = level.field_size / 2.0;
    const toml::table* t = section(root, "field", ctx.diag);
    if (!t) return;
    Diagnostics& diag = ctx.diag;
    TableReader r(*t, "[field]", kFieldKeys, diag, kRootKeys);
    if (r.has("size")) {
        const auto size = r.number("size", {kMinFieldSize, kMaxFieldSize});
        if (size) level.field_size = *size;
        ctx.position_limit = size ? *size / 2.0 : kMaxFieldSize / 2.0;
    }
    if (auto v = r.boolean("wrap")) level.wrap = *v;
    if (auto v = r.color("obstacle_color")) obstacle_color = *v;
}

namespace {

// A list of increasing scores, each giving one bonus tank; [] for none.
void read_bonus_scores(const toml::node& node, Level& level, Diagnostics& diag) {
    const auto* list = node.as_array();
    if (!list) {
        diag.error(node.source(), "'bonus_scores' must be an array of scores, not " +
                                      std::string(type_name(node)));
        return;
    }
    if (list->size() > kMaxBonusScores) {
        diag.error(node.source(), "at most " + std::to_string(kMaxBonusScores) +
                                      " bonus scores, not " + std::to_string(list->size()));
        return;
    }
    std::vector<int> scores;
    for (const auto& item : *list) {
        const auto* v = item.as_integer();
        if (!v || v->get() < 1 || v->get() > kMaxScore) {
            diag.error(item.source(),
                       "a bonus score is a whole number from 1 to " + std::to_string(kMaxScore));
            return;
        }
        if (!scores.empty() && v->get() <= scores.back()) {
            diag.error(item.source(), "bonus scores must increase: " + std::to_string(v->get()) +
                                          " comes after " + std::to_string(scores.back()));
            return;
        }
        scores.push_back(static_cast<int>(v->get()));
    }
    level.bonus_scores = std::move(scores);
}

}  // namespace

void read_player(const toml::table& root, Level& level, ReadContext& ctx) {
    const toml::table* t = section(root, "player", ctx.diag);
    if (!t) return;
    TableReader r(*t, "[player]", kPlayerKeys, ctx.diag, kRootKeys);
    const double half = ctx.position_limit;
    if (r.has("position")) {
        const auto v = r.vec3("position", {Range{-half, half}, kHeightRange, Range{-half, half}});
        if (v) level.player_start = *v;
        ctx.start_known = v.has_value();
    }
    if (auto v = r.number("heading", kHeadingRange)) level.player_heading_deg = *v;
    if (auto v = r.integer("lives", 1, 9)) level.player_lives = static_cast<int>(*v);
    if (const toml::node* node = r.get("bonus_scores")) read_bonus_scores(*node, level, ctx.diag);
}

void read_enemies(const toml::table& root, Level& level, ReadContext& ctx) {
    Diagnostics& diag = ctx.diag;
    EnemyRules& e = level.enemies;
    const double half = level.field_size / 2.0;
    // The default spawn ring suits the default field; a small field pulls it in rather than
    // making every small level spell out spawn distances.
    e.spawn_max_distance = std::min(e.spawn_max_distance, half);
    e.spawn_min_distance = std::min(e.spawn_min_distance, e.spawn_max_distance);
    const toml::table* t = section(root, "enemies", diag);
    if (!t) return;
    TableReader r(*t, "[enemies]", kEnemyKeys, diag, kRootKeys);
    if (const toml::node* node = r.get("types")) {
        if (const auto* list = node->as_array()) {
            e.slow_tank = e.super_tank = e.missile = e.saucer = false;
            std::array<bool, kEnemyTypes.size()> seen{};
            for (const auto& item : *list) {
                const auto* s = item.as_string();
                if (!s) {
                    diag.error(item.source(),
                               "enemy types are strings, not " + std::string(type_name(item)));
                    continue;
                }
                std::size_t index = kEnemyTypes.size();
                for (std::size_t i = 0; i < kEnemyTypes.size(); ++i) {
                    if (kEnemyTypes[i] == s->get()) index = i;
                }
                if (index == kEnemyTypes.size()) {
                    diag.error(item.source(),
                               "unknown enemy type " + quote(s->get()) +
                                   did_you_mean(s->get(), kEnemyTypes) +
                                   " (one of: slow_tank, super_tank, missile, saucer)");
                    continue;
                }
                if (seen[index]) {
                    diag.error(item.source(), "enemy type " + quote(s->get()) + " is listed twice");
                    continue;
                }
                seen[index] = true;
            }
            e.slow_tank = seen[0];
            e.super_tank = seen[1];
            e.missile = seen[2];
            e.saucer = seen[3];
        } else {
            diag.error(node->source(), "'types' must be an array of enemy types, not " +
                                           std::string(type_name(*node)));
        }
    }
    if (auto v = r.integer("super_tank_score", 0, kMaxScore))
        e.super_tank_score = static_cast<int>(*v);
    if (auto v = r.integer("missile_score", 0, kMaxScore)) e.missile_score = static_cast<int>(*v);
    const auto min_d = r.number("spawn_min_distance", {5.0, ctx.position_limit});
    const auto max_d = r.number("spawn_max_distance", {5.0, ctx.position_limit});
    if (min_d) e.spawn_min_distance = *min_d;
    if (max_d) e.spawn_max_distance = *max_d;
    // A default never contradicts a value the author wrote: it moves out of the way.
    if (min_d && !max_d) e.spawn_max_distance = std::max(e.spawn_max_distance, *min_d);
    if (max_d && !min_d) e.spawn_min_distance = std::min(e.spawn_min_distance, *max_d);
    if (min_d && max_d && *min_d > *max_d) {
        diag.error(r.get("spawn_max_distance")->source(),
                   "spawn_min_distance (" + number_text(e.spawn_min_distance) +
                       ") must not be larger than spawn_max_distance (" +
                       number_text(e.spawn_max_distance) + ")");
    }
    if (auto v = r.number("aggression", {0.0, 1.0})) e.aggression = *v;
    if (auto v = r.choice("difficulty", kDifficulties)) {
        e.difficulty = *v == "easy"     ? Difficulty::easy
                       : *v == "arcade" ? Difficulty::arcade
                                        : Difficulty::normal;
    }
    if (auto v = r.integer("saucer_score", 0, kMaxScore)) e.saucer_score = static_cast<int>(*v);
    if (auto v = r.number("spawn_rear_chance", {0.0, 1.0})) e.spawn_rear_chance = *v;
    if (auto v = r.number("fire_interval", {0.5, 60.0})) e.fire_interval = *v;
    if (auto v = r.number("aim_error", {0.0, 30.0})) e.aim_error_deg = *v;
    if (auto v = r.boolean("hold_fire")) e.hold_fire = *v;
    if (auto v = r.integer("slow_tank_points", 0, kMaxScore))
        e.slow_tank_points = static_cast<int>(*v);
    if (auto v = r.integer("super_tank_points", 0, kMaxScore))
        e.super_tank_points = static_cast<int>(*v);
    if (auto v = r.integer("missile_points", 0, kMaxScore)) e.missile_points = static_cast<int>(*v);
    if (auto v = r.integer("saucer_points", 0, kMaxScore)) e.saucer_points = static_cast<int>(*v);
}

void read_render(const toml::table& root, Level& level, Diagnostics& diag) {
    const toml::table* t = section(root, "render", diag);
    if (!t) return;
    TableReader r(*t, "[render]", kRenderKeys, diag, kRootKeys);
    RenderSettings& s = level.render;
    if (auto v = r.choice("style", scene::accepted_style_names())) {
        s.style = *v;
        s.style_given = true;
    }
    if (auto v = r.choice("preset", kPresets)) {
        s.preset = *v;
        s.preset_given = true;
    }
    if (auto v = r.number("line_width", {0.5, 16.0})) s.line_width_px = *v;
    if (auto v = r.number("crease_angle", {0.0, 180.0})) s.crease_angle_deg = *v;
    if (auto v = r.number("bloom_strength", {0.0, 4.0})) s.bloom_strength = *v;
    if (auto v = r.choice("beam", kBeamLooks)) s.beam = *v;
    if (auto v = r.boolean("overlay")) s.overlay = *v;
    if (auto v = r.boolean("hold_41hz")) s.hold_41hz = *v;
    if (auto v = r.choice("line_method", kLineMethods)) s.line_method = *v;
    if (auto v = r.boolean("material_lines")) s.material_lines = *v;
    if (auto v = r.boolean("intersection_lines")) s.intersection_lines = *v;
}

}  // namespace bz::level::detail
