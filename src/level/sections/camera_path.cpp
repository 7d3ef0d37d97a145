#include <array>

#include "level/sections/sections.h"
#include "scene/camera_check.h"

namespace bz::level::detail {

namespace {

constexpr std::array<std::string_view, 3> kCameraKeys = {"time", "eye", "target"};
constexpr Range kTimeRange{0.0, 3600.0};
constexpr Range kCoordinate{-100000.0, 100000.0};
constexpr std::array<Range, 3> kPoint = {kCoordinate, kCoordinate, kCoordinate};

}  // namespace

void read_camera_path(const toml::table& root, Level& level, ReadContext& ctx) {
    const toml::array* list =
        table_array(root, "camera_key", ctx.options.max_camera_keys, "camera keys", ctx.diag);
    if (!list) return;
    level.camera_path.reserve(list->size());
    bool have_previous = false;
    double previous_time = 0.0;
    glm::dvec3 previous_eye{}, previous_target{};
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::node& item = *list->get(i);
        const auto* t = item.as_table();
        if (!t) {
            ctx.diag.error(item.source(),
                           "each camera key must be a table, not " + std::string(type_name(item)));
            continue;
        }
        TableReader r(*t, "camera key " + std::to_string(i + 1), kCameraKeys, ctx.diag,
                      root_keys());
        bool ok = true;
        for (const std::string_view key : kCameraKeys) {
            if (!r.has(key)) {
                r.missing(key);
                ok = false;
            }
        }
        const auto time = r.number("time", kTimeRange);
        const auto eye = r.vec3("eye", kPoint);
        const auto target = r.vec3("target", kPoint);
        if (!ok || !time || !eye || !target) continue;
        if (have_previous && *time <= previous_time) {
            ctx.diag.error(r.get("time")->source(),
                           "camera key times must increase: " + number_text(*time) + " follows " +
                               number_text(previous_time));
            continue;
        }
        if (glm::length(*target - *eye) < 1e-6) {
            ctx.diag.error(r.get("target")->source(), "camera target must differ from the eye");
            continue;
        }
        // The path's camera keeps +y up: a key looking straight up or down has no picture.
        if (const std::string why = scene::view_problem(*eye, *target, {0.0, 1.0, 0.0});
            !why.empty()) {
            ctx.diag.error(r.get("target")->source(), "the camera cannot make a picture: " + why);
            continue;
        }
        // The path is played by moving eye and target linearly between keys: the views in
        // between must make a picture too, not only the keys.
        double at = 0.0;
        if (have_previous) {
            if (const std::string why = scene::path_view_problem(
                    previous_eye, previous_target, *eye, *target, {0.0, 1.0, 0.0}, &at);
                !why.empty()) {
                ctx.diag.error(r.get("time")->source(),
                               "on the way to this key from the one before (at time " +
                                   number_text(previous_time + (*time - previous_time) * at) +
                                   ") the camera cannot make a picture: " + why);
                continue;
            }
        }
        have_previous = true;
        previous_time = *time;
        previous_eye = *eye;
        previous_target = *target;
        level.camera_path.push_back({*time, *eye, *target});
    }
}

}  // namespace bz::level::detail
