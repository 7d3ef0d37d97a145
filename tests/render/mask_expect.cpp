#include "render/mask_expect.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace bz::test {

int Mask::count() const {
    return static_cast<int>(
        std::count_if(pixels.begin(), pixels.end(), [](auto v) { return v != 0; }));
}

namespace {

bool crosses(glm::dvec2 c, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
    if (hi.x < c.x - 0.5 || lo.x >= c.x + 0.5 || hi.y < c.y - 0.5 || lo.y >= c.y + 0.5)
        return false;
    const glm::dvec2 d = b - a;
    const glm::dvec2 n(-d.y, d.x);
    return std::abs(glm::dot(n, c - a)) <= 0.5 * (std::abs(n.x) + std::abs(n.y));
}

}  // namespace

Mask expected_mask(const scene::Camera& cam, int width, int height,
                   const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments) {
    Mask m{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height), 0)};
    const glm::dmat4 view = glm::lookAt(cam.eye, cam.target, cam.up);
    const double f = 1.0 / std::tan(glm::radians(cam.fov_y_deg) * 0.5);
    const double aspect = static_cast<double>(width) / height;
    for (auto [pa, pb] : segments) {
        glm::dvec3 a = glm::dvec3(view * glm::dvec4(pa, 1.0));
        glm::dvec3 b = glm::dvec3(view * glm::dvec4(pb, 1.0));
        const double da = -a.z, db = -b.z;
        if (da < cam.near && db < cam.near) continue;
        if (da < cam.near) a = glm::mix(a, b, (cam.near - da) / (db - da));
        if (db < cam.near) b = glm::mix(b, a, (cam.near - db) / (da - db));
        auto to_px = [&](glm::dvec3 v) {
            const double x = v.x * f / aspect / -v.z, y = v.y * f / -v.z;
            return glm::dvec2((x * 0.5 + 0.5) * width, (y * 0.5 + 0.5) * height);
        };
        const glm::dvec2 sa = to_px(a), sb = to_px(b);
        const glm::dvec2 lo = glm::floor(glm::min(sa, sb)) - 1.0,
                         hi = glm::ceil(glm::max(sa, sb)) + 1.0;
        for (int y = std::max(0, static_cast<int>(lo.y));
             y < std::min(height, static_cast<int>(hi.y)); ++y) {
            for (int x = std::max(0, static_cast<int>(lo.x));
                 x < std::min(width, static_cast<int>(hi.x)); ++x) {
                if (crosses({x + 0.5, y + 0.5}, sa, sb)) {
                    m.pixels[static_cast<std::size_t>((height - 1 - y) * width + x)] = 255;
                }
            }
        }
    }
    return m;
}

namespace {

double fraction_near(const Mask& from, const Mask& to, int tol) {
    int total = 0, hit = 0;
    for (int y = 0; y < from.height; ++y) {
        for (int x = 0; x < from.width; ++x) {
            if (!from.lit(x, y)) continue;
            ++total;
            bool found = false;
            for (int dy = -tol; dy <= tol && !found; ++dy) {
                for (int dx = -tol; dx <= tol && !found; ++dx) found = to.lit(x + dx, y + dy);
            }
            hit += found ? 1 : 0;
        }
    }
    return total ? static_cast<double>(hit) / total : 1.0;
}

}  // namespace

MaskScore score_masks(const Mask& test, const Mask& ref, int tol) {
    return {fraction_near(test, ref, tol), fraction_near(ref, test, tol), test.count(),
            ref.count()};
}

}  // namespace bz::test
