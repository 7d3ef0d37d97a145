#include <array>

#include "level/sections.h"

namespace bz::level::detail {

namespace {

constexpr std::array<std::string_view, 6> kBackdropKeys = {
    "mountains", "volcano", "volcano_azimuth", "moon", "moon_azimuth", "moon_elevation"};
constexpr Range kAzimuth{0.0, 360.0};
constexpr Range kMountainHeight{0.0, 30.0};

}  // namespace

std::vector<glm::dvec2> default_mountains() {
    // A jagged ring of ranges with two gaps, in the spirit of the arcade skyline.
    return {{0, 2.0},    {12, 4.5},  {20, 3.0},  {31, 6.0},  {40, 4.0},  {52, 2.5},
            {75, 1.0},   {95, 3.5},  {104, 5.5}, {113, 3.0}, {128, 7.0}, {140, 4.0},
            {152, 2.0},  {170, 0.5}, {190, 2.5}, {205, 5.0}, {214, 3.5}, {226, 8.0},
            {238, 5.5},  {250, 3.0}, {265, 1.5}, {290, 4.0}, {302, 6.5}, {315, 3.5},
            {330, 5.0},  {345, 3.0}, {360, 2.0}};
}

void read_backdrop(const toml::table& root, Level& level, ReadContext& ctx) {
    level.backdrop.mountains = default_mountains();
    const toml::table* t = section(root, "backdrop", ctx.diag);
    if (!t) return;
    TableReader r(*t, "[backdrop]", kBackdropKeys, ctx.diag);
    Backdrop& b = level.backdrop;
    if (const toml::node* node = r.get("mountains")) {
        const auto* list = node->as_array();
        if (!list) {
            ctx.diag.error(node->source(), "'mountains' must be an array of [azimuth, height] pairs, not " +
                                               std::string(type_name(*node)));
        } else if (list->size() > ctx.options.max_mountain_points) {
            ctx.diag.error(node->source(), "too many mountain points: " + std::to_string(list->size()) +
                                               " (the limit is " +
                                               std::to_string(ctx.options.max_mountain_points) + ")");
        } else {
            std::vector<glm::dvec2> points;
            bool ok = true;
            for (std::size_t i = 0; i < list->size(); ++i) {
                const toml::node& item = *list->get(i);
                const auto* pair = item.as_array();
                if (!pair || pair->size() != 2) {
                    ctx.diag.error(item.source(), "each mountain point must be [azimuth, height], not " +
                                                      (pair ? "an array of " + std::to_string(pair->size())
                                                            : std::string(type_name(item))));
                    ok = false;
                    continue;
                }
                const auto az = read_number(*pair->get(0), "mountain azimuth", kAzimuth, ctx.diag);
                const auto h = read_number(*pair->get(1), "mountain height", kMountainHeight, ctx.diag);
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

}  // namespace bz::level::detail
