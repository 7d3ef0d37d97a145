#include "app/play/edit_status.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/text/ascii_case.h"

namespace bz::app {

namespace {

// Taller than any footprint is wide would be unusual; objects without a height in the level
// data are taken as this many footprint radii high (a cube is 2, a tall box more).
constexpr double kHeightPerRadius = 2.5;
constexpr double kMinHeight = 2.0;

}  // namespace

std::optional<std::size_t> object_under_reticle(const level::Level& level, const glm::dvec3& eye,
                                                const glm::dvec3& dir) {
    const double inf = std::numeric_limits<double>::infinity();
    const double ground_t = dir.y < 0.0 ? -eye.y / dir.y : inf;
    const glm::dvec2 o{eye.x, eye.z};
    const glm::dvec2 d{dir.x, dir.z};
    const double a = glm::dot(d, d);
    std::optional<std::size_t> best;
    double best_t = inf;
    for (std::size_t i = 0; i < level.obstacles.size(); ++i) {
        const level::ObjectDesc& obj = level.obstacles[i];
        const double r = std::max(obj.footprint_radius, 0.5);
        const double height = std::max(kMinHeight, r * kHeightPerRadius);
        const glm::dvec2 c{obj.position.x, obj.position.z};
        const glm::dvec2 oc = o - c;
        double t = inf;
        if (glm::dot(oc, oc) <= r * r) {
            t = 0.0;  // inside the footprint: looking down at it
        } else if (a > 1e-12) {
            const double b = glm::dot(oc, d);
            const double disc = b * b - a * (glm::dot(oc, oc) - r * r);
            if (disc >= 0.0) {
                const double t0 = (-b - std::sqrt(disc)) / a;
                if (t0 >= 0.0) t = t0;
            }
        }
        if (!std::isfinite(t)) continue;
        // Where the ray enters the cylinder's side it must be below the top; from above it
        // enters through the top, which the ground test below covers.
        const double y = eye.y + t * dir.y;
        double hit_t = t;
        if (y > obj.position.y + height) {
            if (dir.y >= 0.0) continue;
            hit_t = (obj.position.y + height - eye.y) / dir.y;  // through the top
            const glm::dvec2 p = o + hit_t * d - c;
            if (glm::dot(p, p) > r * r) continue;
        }
        if (hit_t > ground_t + 1e-6 || hit_t >= best_t) continue;
        best_t = hit_t;
        best = i;
    }
    return best;
}

std::string edit_status_line(const level::Level& level, const glm::dvec3& eye, double yaw_deg,
                             double pitch_deg, const glm::dvec3& dir) {
    // The camera's yaw turns to the left; a compass bearing turns to the right.
    double heading = std::round(std::fmod(-yaw_deg, 360.0));
    if (heading < 0.0) heading += 360.0;
    if (heading >= 360.0 || heading == 0.0) heading = 0.0;  // and never "-0"
    char buf[128];
    std::snprintf(buf, sizeof buf, "X %.1f  Y %.1f  Z %.1f   HEADING %.0f   PITCH %.0f", eye.x,
                  eye.y, eye.z, heading, pitch_deg);
    std::string out = buf;
    if (const auto i = object_under_reticle(level, eye, dir)) {
        const level::ObjectDesc& o = level.obstacles[*i];
        const std::string file = std::filesystem::path(o.pos.file).filename().string();
        out += "   AIM: " + ascii_upper(o.kind) + "  " + file + ":" + std::to_string(o.pos.line);
    } else {
        out += "   AIM: NOTHING";
    }
    return out;
}

}  // namespace bz::app
