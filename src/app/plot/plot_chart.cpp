#include "app/plot/plot_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bz::app {

double nice_step(double range, int target) {
    if (!(range > 0.0) || target < 1) return 1.0;
    const double raw = range / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / mag;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * mag;
}

std::string tick_label(double v, double step) {
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
    return buf;
}

Axis nice_axis(double lo, double hi, std::string label, int target_ticks) {
    if (!(hi > lo)) {
        const double pad = std::max(std::abs(lo) * 0.1, 1e-3);
        lo -= pad;
        hi += pad;
    }
    const double step = nice_step(hi - lo, target_ticks);
    return {std::floor(lo / step) * step, std::ceil(hi / step) * step, std::move(label)};
}

glm::vec3 series_color(std::size_t i) {
    static constexpr glm::vec3 kColors[] = {
        {0.12f, 0.47f, 0.71f}, {1.00f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f}, {0.84f, 0.15f, 0.16f},
        {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f}, {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f},
        {0.74f, 0.74f, 0.13f}, {0.09f, 0.75f, 0.81f},
    };
    return kColors[i % std::size(kColors)];
}

Chart::Chart(Canvas& canvas, Axis x, Axis y, std::string title)
    : canvas_(canvas), x_(std::move(x)), y_(std::move(y)), title_(std::move(title)) {
    lo_ = {90.0f, 70.0f};
    hi_ = {static_cast<float>(canvas.width()) - 30.0f, static_cast<float>(canvas.height()) - 50.0f};
}

glm::vec2 Chart::map(double x, double y) const {
    const double fx = (x - x_.lo) / (x_.hi - x_.lo), fy = (y - y_.lo) / (y_.hi - y_.lo);
    return {lo_.x + static_cast<float>(fx) * (hi_.x - lo_.x),
            lo_.y + static_cast<float>(fy) * (hi_.y - lo_.y)};
}

void Chart::draw_frame() {
    const double sx = nice_step(x_.hi - x_.lo, 6), sy = nice_step(y_.hi - y_.lo, 6);
    constexpr float kTickText = 11.0f;
    for (double v = std::ceil(x_.lo / sx - 1e-9) * sx; v <= x_.hi + sx * 1e-6; v += sx) {
        const glm::vec2 p = map(v, y_.lo);
        canvas_.line({p.x, lo_.y}, {p.x, hi_.y}, kGrid);
        canvas_.line({p.x, lo_.y}, {p.x, lo_.y - 5.0f}, kInk);
        canvas_.text(tick_label(v, sx), {p.x, lo_.y - 20.0f}, kTickText, kInk,
                     scene::TextAlign::center);
    }
    for (double v = std::ceil(y_.lo / sy - 1e-9) * sy; v <= y_.hi + sy * 1e-6; v += sy) {
        const glm::vec2 p = map(x_.lo, v);
        canvas_.line({lo_.x, p.y}, {hi_.x, p.y}, kGrid);
        canvas_.line({lo_.x - 5.0f, p.y}, {lo_.x, p.y}, kInk);
        canvas_.text(tick_label(v, sy), {lo_.x - 8.0f, p.y - kTickText * 0.5f}, kTickText, kInk,
                     scene::TextAlign::right);
    }
    canvas_.line(lo_, {hi_.x, lo_.y}, kInk, 1.5f);
    canvas_.line(lo_, {lo_.x, hi_.y}, kInk, 1.5f);
    canvas_.text(x_.label, {(lo_.x + hi_.x) * 0.5f, 18.0f}, 13.0f, kInk, scene::TextAlign::center);
    canvas_.text(y_.label, {28.0f, (lo_.y + hi_.y) * 0.5f}, 13.0f, kInk, scene::TextAlign::center,
                 true);
    canvas_.text(title_, {(lo_.x + hi_.x) * 0.5f, title_baseline()}, kTitleHeight, kInk,
                 scene::TextAlign::center);
}

float Chart::title_baseline() const {
    return static_cast<float>(canvas_.height()) - 30.0f;
}

// Descenders (g, y, comma) reach about a third of the letter height below the baseline.
float Chart::title_bottom() const {
    return title_baseline() - kTitleHeight * 0.35f - 2.0f;
}

void Chart::legend_entry(int row, const std::string& name, glm::vec3 color) {
    constexpr float kRow = 18.0f, kText = 11.0f;
    const float w = canvas_.text_width(name, kText);
    const glm::vec2 at{hi_.x - w - 30.0f, hi_.y - 18.0f - kRow * static_cast<float>(row)};
    canvas_.fill_rect({at.x - 4.0f, at.y - 5.0f}, {hi_.x - 4.0f, at.y + kRow - 5.0f}, kPaper);
    canvas_.fill_rect(at, at + glm::vec2(12.0f, 10.0f), color);
    canvas_.text(name, at + glm::vec2(18.0f, 0.0f), kText, kInk);
}

}  // namespace bz::app
