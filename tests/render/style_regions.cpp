#include "render/style_regions.h"

#include <algorithm>
#include <cmath>

#include "render/camera/camera_math.h"

namespace bz::test {

std::size_t Region::count() const {
    return static_cast<std::size_t>(std::count(on.begin(), on.end(), std::uint8_t{1}));
}

Region coverage(const scene::FrameList& frame, const scene::MeshLibrary& meshes, int w, int h) {
    Region out{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h, 0)};
    const render::CameraMatrices cam = render::camera_matrices(
        frame.camera, static_cast<double>(w) / h, render::DepthFormat::reversed_f32);
    const glm::dmat4 proj(cam.proj);
    for (const scene::DrawItem& item : frame.items) {
        const geo::AdjacencyMesh& mesh = meshes.mesh(item.mesh);
        const glm::dmat4 m = proj * cam.view * item.model;
        std::vector<glm::dvec2> win(mesh.positions.size());
        std::vector<bool> front(mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec4 c = m * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0);
            front[i] = c.w > 1e-9;
            win[i] = (glm::dvec2(c) / c.w * 0.5 + 0.5) * glm::dvec2(w, h);
        }
        for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
            const std::uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1],
                                c = mesh.triangles[t + 2];
            if (!front[a] || !front[b] || !front[c]) continue;  // the tests keep objects in front
            const glm::dvec2 p0 = win[a], p1 = win[b], p2 = win[c];
            const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
            if (std::abs(area) < 1e-12) continue;
            const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p0.x, p1.x, p2.x}))));
            const int x1 =
                std::min(w - 1, static_cast<int>(std::ceil(std::max({p0.x, p1.x, p2.x}))));
            const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p0.y, p1.y, p2.y}))));
            const int y1 =
                std::min(h - 1, static_cast<int>(std::ceil(std::max({p0.y, p1.y, p2.y}))));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    const glm::dvec2 q(x + 0.5, y + 0.5);
                    const double e0 = (p1.x - p0.x) * (q.y - p0.y) - (q.x - p0.x) * (p1.y - p0.y);
                    const double e1 = (p2.x - p1.x) * (q.y - p1.y) - (q.x - p1.x) * (p2.y - p1.y);
                    const double e2 = (p0.x - p2.x) * (q.y - p2.y) - (q.x - p2.x) * (p0.y - p2.y);
                    const bool inside = area > 0 ? (e0 >= 0 && e1 >= 0 && e2 >= 0)
                                                 : (e0 <= 0 && e1 <= 0 && e2 <= 0);
                    if (inside) out.on[static_cast<std::size_t>(h - 1 - y) * w + x] = 1;
                }
            }
        }
    }
    return out;
}

Region from_mask(const std::vector<std::uint8_t>& mask, int w, int h) {
    Region r{w, h, std::vector<std::uint8_t>(mask.size(), 0)};
    for (std::size_t i = 0; i < mask.size(); ++i) r.on[i] = mask[i] ? 1 : 0;
    return r;
}

namespace {

// Any (grow) or all (shrink) of the pixels within the radius; pixels off the image count as off.
Region neighbourhood(const Region& r, int radius, bool all) {
    Region out{r.width, r.height, std::vector<std::uint8_t>(r.on.size(), 0)};
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            bool result = all;
            for (int dy = -radius; dy <= radius && result == all; ++dy) {
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int u = x + dx, v = y + dy;
                    const bool on = u >= 0 && v >= 0 && u < r.width && v < r.height && r.at(u, v);
                    if (on != all) {
                        result = !all;
                        break;
                    }
                }
            }
            out.on[static_cast<std::size_t>(y) * r.width + x] = result ? 1 : 0;
        }
    }
    return out;
}

}  // namespace

Region eroded(const Region& r, int radius) {
    return neighbourhood(r, radius, true);
}
Region dilated(const Region& r, int radius) {
    return neighbourhood(r, radius, false);
}

Region minus(const Region& a, const Region& b) {
    Region out = a;
    for (std::size_t i = 0; i < out.on.size(); ++i) out.on[i] = a.on[i] && !b.on[i];
    return out;
}

Region inverted(const Region& r) {
    Region out = r;
    for (auto& v : out.on) v = v ? 0 : 1;
    return out;
}

Rgb pixel(const std::vector<std::uint8_t>& rgba, int width, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {rgba[i] / 255.0f, rgba[i + 1] / 255.0f, rgba[i + 2] / 255.0f};
}

double share(const Region& region, const std::vector<std::uint8_t>& rgba,
             const std::function<bool(const Rgb&)>& test) {
    std::size_t n = 0, pass = 0;
    for (int y = 0; y < region.height; ++y) {
        for (int x = 0; x < region.width; ++x) {
            if (!region.at(x, y)) continue;
            ++n;
            if (test(pixel(rgba, region.width, x, y))) ++pass;
        }
    }
    return n ? static_cast<double>(pass) / static_cast<double>(n) : 0.0;
}

double share_near(const Region& region, const std::vector<std::uint8_t>& rgba, int radius,
                  const std::function<bool(const Rgb&)>& test) {
    Region passing{region.width, region.height, std::vector<std::uint8_t>(region.on.size(), 0)};
    for (int y = 0; y < region.height; ++y) {
        for (int x = 0; x < region.width; ++x) {
            passing.on[static_cast<std::size_t>(y) * region.width + x] =
                test(pixel(rgba, region.width, x, y)) ? 1 : 0;
        }
    }
    const Region near = dilated(passing, radius);
    std::size_t n = 0, pass = 0;
    for (std::size_t i = 0; i < region.on.size(); ++i) {
        if (!region.on[i]) continue;
        ++n;
        if (near.on[i]) ++pass;
    }
    return n ? static_cast<double>(pass) / static_cast<double>(n) : 0.0;
}

}  // namespace bz::test
