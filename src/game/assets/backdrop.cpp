#include "game/assets/backdrop.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/angles.h"
#include "scene/shapes.h"

namespace bz::game::backdrop {

namespace {

constexpr double kMaxStepDeg = 2.5;     // strip bend per quad, well under any crease angle
constexpr double kMinHeightDeg = 0.25;  // keeps the silhouette off the horizon line

// The volcano's outline as (azimuth offset, height) in degrees; the crater is the flat top.
constexpr glm::dvec2 kVolcano[] = {{-8.0, 0.3}, {-5.0, 2.2}, {-2.5, 4.4}, {-1.2, 5.4},
                                   {1.2, 5.4},  {2.5, 4.4},  {5.0, 2.2},  {8.0, 0.3}};
constexpr double kVolcanoRadius = kRadius * 0.97;  // in front of the mountains
constexpr double kCraterHeightDeg = 5.4;
constexpr double kMoonRadiusDeg = 2.6;

glm::vec3 on_ring(double azimuth_deg, double height_deg, double radius) {
    const glm::dvec3 d = direction(azimuth_deg) * radius;
    const double y = radius * std::tan(height_deg * kPi / 180.0);
    return glm::vec3(static_cast<float>(d.x), static_cast<float>(y), static_cast<float>(d.z));
}

// A fixed little table of ejecta: launch angle, speed and period of each glowing rock.
struct Ejecta {
    double drift_deg_s;
    double rise_deg_s;
    double period_s;
    double offset_s;
};
constexpr Ejecta kEjecta[] = {
    {-0.9, 4.2, 2.3, 0.0}, {0.6, 5.0, 2.9, 0.7},  {1.3, 3.6, 2.1, 1.1}, {-1.6, 4.6, 3.3, 1.9},
    {0.2, 5.6, 3.7, 0.4},  {-0.4, 3.9, 2.6, 2.2}, {1.8, 4.4, 3.1, 1.5}, {-1.1, 5.2, 3.5, 2.8},
};
constexpr double kEjectaGravityDegS2 = 3.2;

}  // namespace

glm::dvec3 direction(double azimuth_deg) {
    const double a = azimuth_deg * kPi / 180.0;
    return {std::sin(a), 0.0, -std::cos(a)};
}

std::vector<glm::dvec2> default_mountains() {
    return {{0, 1.2},   {14, 2.8},  {25, 1.6},  {38, 3.9},  {47, 2.2},  {80, 1.4},
            {96, 3.1},  {108, 2.0}, {125, 4.6}, {139, 2.4}, {160, 1.1}, {178, 2.9},
            {192, 1.8}, {210, 3.6}, {226, 2.1}, {244, 4.2}, {259, 2.6}, {277, 1.3},
            {292, 3.3}, {318, 1.9}, {333, 3.8}, {347, 2.0}};
}

geo::TriMesh mountains(const std::vector<glm::dvec2>& points_in) {
    std::vector<glm::dvec2> pts = points_in.empty() ? default_mountains() : points_in;
    for (glm::dvec2& p : pts) {
        p.x = std::fmod(std::fmod(p.x, 360.0) + 360.0, 360.0);
        p.y = std::clamp(std::isfinite(p.y) ? p.y : 0.0, kMinHeightDeg, 60.0);
    }
    std::stable_sort(pts.begin(), pts.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x; });
    // Subdivide every gap (the last one wraps round to the first point) into small steps.
    std::vector<glm::vec3> lower;
    std::vector<glm::vec3> upper;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const glm::dvec2 a = pts[i];
        glm::dvec2 b = pts[(i + 1) % pts.size()];
        if (i + 1 == pts.size()) b.x += 360.0;
        const double gap = b.x - a.x;
        if (gap <= 1e-6 && pts.size() > 1) continue;  // duplicate azimuth: keep the later one
        const int steps =
            std::max(1, static_cast<int>(std::ceil((pts.size() == 1 ? 360.0 : gap) / kMaxStepDeg)));
        for (int s = 0; s < steps; ++s) {
            const double t = static_cast<double>(s) / steps;
            const double az = a.x + (pts.size() == 1 ? 360.0 : gap) * t;
            const double h = a.y + (b.y - a.y) * t;
            lower.push_back(on_ring(az, 0.0, kRadius));
            upper.push_back(on_ring(az, h, kRadius));
        }
    }
    return scene::shapes::strip(lower, upper, true);
}

geo::TriMesh volcano() {
    std::vector<glm::vec3> lower;
    std::vector<glm::vec3> upper;
    for (glm::dvec2 p : kVolcano) {
        lower.push_back(on_ring(p.x, 0.0, kVolcanoRadius));
        upper.push_back(on_ring(p.x, p.y, kVolcanoRadius));
    }
    return scene::shapes::strip(lower, upper, false);
}

geo::TriMesh moon() {
    // Lit limb: a half circle; terminator: a half ellipse. The strip between them is the
    // crescent, facing +z (towards an eye on the +z side).
    constexpr int n = 16;
    std::vector<glm::vec3> outer;
    std::vector<glm::vec3> inner;
    for (int i = 1; i < n; ++i) {  // the tips are left out: they would be degenerate
        const double t = -kPi / 2.0 + kPi * i / n;
        const auto y = static_cast<float>(std::sin(t));
        outer.push_back({static_cast<float>(std::cos(t)), y, 0.0f});
        inner.push_back({static_cast<float>(0.45 * std::cos(t)), y, 0.0f});
    }
    // Both run bottom to top with the limb on the right (+x): with the limb as the strip's
    // "lower" line the triangles wind counter-clockwise seen from +z.
    return scene::shapes::strip(outer, inner, false);
}

void append_items(std::vector<scene::DrawItem>& out, const level::Backdrop& b, const Ids& ids,
                  const glm::dvec3& eye, double seconds) {
    const glm::dmat4 at_eye = glm::translate(glm::dmat4(1.0), {eye.x, 0.0, eye.z});
    const glm::vec3 green{0.2f, 1.0f, 0.3f};
    scene::DrawItem m;
    m.mesh = ids.mountains;
    m.model = at_eye;
    m.color = green;
    m.intensity = 0.8f;
    out.push_back(m);

    if (b.volcano) {
        // The strip is built at azimuth 0; compass azimuth runs clockwise seen from above,
        // which is a negative rotation about +y.
        const glm::dmat4 turn =
            glm::rotate(at_eye, -b.volcano_azimuth_deg * kPi / 180.0, glm::dvec3(0.0, 1.0, 0.0));
        scene::DrawItem v = m;
        v.mesh = ids.volcano;
        v.model = turn;
        v.intensity = 0.9f;
        out.push_back(v);
        // Ejecta fly in parabolas from the crater, each on its own period.
        for (const Ejecta& e : kEjecta) {
            const double tau = std::fmod(seconds + e.offset_s, e.period_s);
            const double az = e.drift_deg_s * tau;
            const double el =
                kCraterHeightDeg + e.rise_deg_s * tau - 0.5 * kEjectaGravityDegS2 * tau * tau;
            if (el < 0.5) continue;
            const glm::vec3 p = on_ring(az, el, kVolcanoRadius);
            scene::DrawItem s;
            s.mesh = ids.spark;
            s.model = glm::translate(turn, glm::dvec3(p));
            s.model = glm::rotate(s.model, tau * 3.0, glm::dvec3(0.3, 1.0, 0.2));
            s.color = {1.0f, 0.6f, 0.2f};
            s.intensity = static_cast<float>(std::clamp(1.2 - tau / e.period_s, 0.2, 1.2));
            s.occluder = false;
            out.push_back(s);
        }
    }

    if (b.moon) {
        const double radius = kRadius * 0.99;
        const glm::dvec3 d = direction(b.moon_azimuth_deg);
        const double el = b.moon_elevation_deg * kPi / 180.0;
        const glm::dvec3 pos =
            glm::dvec3(d.x * std::cos(el), std::sin(el), d.z * std::cos(el)) * radius;
        // Face the eye: the mesh's +z must point back along -pos.
        glm::dmat4 place = glm::translate(at_eye, pos);
        place = glm::rotate(place, -b.moon_azimuth_deg * kPi / 180.0, glm::dvec3(0.0, 1.0, 0.0));
        place = glm::rotate(place, el, glm::dvec3(1.0, 0.0, 0.0));  // tilt down to the eye
        const double size = radius * std::tan(kMoonRadiusDeg * kPi / 180.0);
        place = glm::scale(place, glm::dvec3(size));
        scene::DrawItem moon_item;
        moon_item.mesh = ids.moon;
        moon_item.model = place;
        moon_item.color = {0.9f, 1.0f, 0.8f};
        moon_item.intensity = 0.9f;
        moon_item.occluder = false;
        out.push_back(moon_item);
    }
}

}  // namespace bz::game::backdrop
