#include "app/plot/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bz::app {

namespace {

std::uint8_t to_byte(float v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

float segment_distance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 1e-12f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + ab * t);
}

}  // namespace

Canvas::Canvas(int width, int height, glm::vec3 background, const scene::VectorFont* font)
    : width_(std::max(width, 1)), height_(std::max(height, 1)), font_(font) {
    image_ = Image{width_, height_, 4,
                   std::vector<std::uint8_t>(static_cast<std::size_t>(width_) * height_ * 4)};
    for (std::size_t i = 0; i < image_.pixels.size(); i += 4) {
        image_.pixels[i] = to_byte(background.r);
        image_.pixels[i + 1] = to_byte(background.g);
        image_.pixels[i + 2] = to_byte(background.b);
        image_.pixels[i + 3] = 255;
    }
}

void Canvas::blend(int x, int y, glm::vec3 c, float alpha) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0.0f) return;
    alpha = std::min(alpha, 1.0f);
    // Row 0 of the image is the top.
    const std::size_t i =
        (static_cast<std::size_t>(height_ - 1 - y) * width_ + static_cast<std::size_t>(x)) * 4;
    for (int k = 0; k < 3; ++k) {
        const float old = image_.pixels[i + static_cast<std::size_t>(k)] / 255.0f;
        image_.pixels[i + static_cast<std::size_t>(k)] = to_byte(old + (c[k] - old) * alpha);
    }
}

void Canvas::fill_rect(glm::vec2 lo, glm::vec2 hi, glm::vec3 color) {
    const glm::vec2 a = glm::min(lo, hi), b = glm::max(lo, hi);
    const int x0 = std::max(0, static_cast<int>(std::floor(a.x))),
              x1 = std::min(width_ - 1, static_cast<int>(std::ceil(b.x)) - 1);
    const int y0 = std::max(0, static_cast<int>(std::floor(a.y))),
              y1 = std::min(height_ - 1, static_cast<int>(std::ceil(b.y)) - 1);
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            // Partial coverage at the rectangle's fractional edges.
            const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
            const float cx = std::clamp(std::min(b.x, fx + 1.0f) - std::max(a.x, fx), 0.0f, 1.0f);
            const float cy = std::clamp(std::min(b.y, fy + 1.0f) - std::max(a.y, fy), 0.0f, 1.0f);
            blend(x, y, color, cx * cy);
        }
    }
}

void Canvas::line(glm::vec2 a, glm::vec2 b, glm::vec3 color, float width) {
    const float r = std::max(width, 0.5f) * 0.5f;
    const glm::vec2 lo = glm::min(a, b) - (r + 1.0f), hi = glm::max(a, b) + (r + 1.0f);
    const int x0 = std::max(0, static_cast<int>(lo.x)),
              x1 = std::min(width_ - 1, static_cast<int>(hi.x));
    const int y0 = std::max(0, static_cast<int>(lo.y)),
              y1 = std::min(height_ - 1, static_cast<int>(hi.y));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const float d = segment_distance(
                {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f}, a, b);
            blend(x, y, color, std::clamp(r + 0.5f - d, 0.0f, 1.0f));
        }
    }
}

void Canvas::disc(glm::vec2 centre, float radius, glm::vec3 color) {
    line(centre, centre, color, radius * 2.0f);
}

void Canvas::text(std::string_view s, glm::vec2 origin, float height, glm::vec3 color,
                  scene::TextAlign align, bool vertical) {
    if (!font_ || s.empty()) return;
    std::vector<scene::HudLine> strokes;
    font_->draw(strokes, s, {0.0f, 0.0f}, height, color, align);
    const float stroke = std::max(1.0f, height / 9.0f);
    for (const scene::HudLine& l : strokes) {
        glm::vec2 p = l.a, q = l.b;
        if (vertical) {
            p = {-p.y, p.x};
            q = {-q.y, q.x};
        }
        line(origin + p, origin + q, color, stroke);
    }
}

float Canvas::text_width(std::string_view s, float height) const {
    return font_ ? font_->width(s, height) : 0.0f;
}

void Canvas::save(const std::filesystem::path& path) const {
    write_png(path, image_);
}

}  // namespace bz::app
