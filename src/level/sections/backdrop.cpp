#include <array>

#include "level/loader.h"
#include "level/sections/sections.h"

namespace bz::level {

std::vector<glm::dvec2> default_mountains() {
    // The arcade-like skyline; the same points the game draws for its built-in plain.
    return {{0, 1.2},   {14, 2.8},  {25, 1.6},  {38, 3.9},  {47, 2.2},  {80, 1.4},
            {96, 3.1},  {108, 2.0}, {125, 4.6}, {139, 2.4}, {160, 1.1}, {178, 2.9},
            {192, 1.8}, {210, 3.6}, {226, 2.1}, {244, 4.2}, {259, 2.6}, {277, 1.3},
            {292, 3.3}, {318, 1.9}, {333, 3.8}, {347, 2.0}};
}

namespace detail {

namespace {

constexpr std::array<std::string_view, 6> kBackdropKeys = {
    "mountains", "volcano", "volcano_azimuth", "moon", "moon_azimuth", "moon_elevation"};
constexpr Range kAzimuth{0.0, 360.0};
constexpr Range kMountainHeight{0.0, 30.0};

}  // namespace

void read_backdrop(const toml::table& root, Level& level, ReadContext& ctx) {
    level.backdrop.mountains = default_mountains();
    const toml::table* t = section(root, "backdrop", ctx.diag);
    if (!t) return;
    TableReader r(*t, "[backdrop]", kBackdropKeys, ctx.diag, root_keys());
    Backdrop& b = level.backdrop;
    if (const toml::node* node = r.get("mountains")) {
        const auto* list = node->as_array();
        if (!list) {
            ctx.diag.error(node->source(),
                           "'mountains' must be an array of [azimuth, height] pairs, not " +
                               std::string(type_name(*node)));
        } else if (list->size() < 2) {
            // An empty list would leave the game to pick its own skyline; say "flat" explicitly.
            ctx.diag.error(node->source(),
                           "'mountains' needs at least 2 points; for a flat horizon "
                           "write [[0, 0], [360, 0]]");
        } else if (list->size() > ctx.options.max_mountain_points) {
            ctx.diag.error(node->source(),
                           "too many mountain points: " + std::to_string(list->size()) +
                               " (the limit is " + std::to_string(ctx.options.max_mountain_points) +
                               ")");
        } else {
            std::vector<glm::dvec2> points;
            bool ok = true;
            for (std::size_t i = 0; i < list->size(); ++i) {
                const toml::node& item = *list->get(i);
                const auto* pair = item.as_array();
                if (!pair || pair->size() != 2) {
                    ctx.diag.error(item.source(),
                                   "each mountain point must be [azimuth, height], not " +
                                       (pair ? "an array of " + std::to_string(pair->size())
                                             : std::string(type_name(item))));
                    ok = false;
                    continue;
                }
                const auto az = read_number(*pair->get(0), "mountain azimuth", kAzimuth, ctx.diag);
                const auto h =
                    read_number(*pair->get(1), "mountain height", kMountainHeight, ctx.diag);
                if (!az || !h) {
                    ok = false;
                    continue;
                }
                if (!points.empty() && *az <= points.back().x) {
                    ctx.diag.error(pair->get(0)->source(),
                                   "mountain azimuths must increase: " + number_text(*az) +
                                       " follows " + number_text(points.back().x));
                    ok = false;
                    continue;
                }
                points.push_back({*az, *h});
            }
            if (ok) b.mountains = std::move(points);
        }
    }
    if (auto v = r.boolean("volcano")) b.volcano = *v;
    if (auto v = r.number("volcano_azimuth", kAzimuth)) b.volcano_azimuth_deg = *v;
    if (auto v = r.boolean("moon")) b.moon = *v;
    if (auto v = r.number("moon_azimuth", kAzimuth)) b.moon_azimuth_deg = *v;
    if (auto v = r.number("moon_elevation", {0.0, 80.0})) b.moon_elevation_deg = *v;
}

}  // namespace detail
}  // namespace bz::level
