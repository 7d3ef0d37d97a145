#include "app/bench/bench_plots.h"

#include <algorithm>
#include <cstdio>

#include "app/plot/plot_chart.h"

namespace bz::app {

void plot_frame_times(const RunResult& run, const std::string& title, const scene::VectorFont* font,
                      const std::filesystem::path& out) {
    Canvas canvas(1200, 600, kPaper, font);
    const double n = static_cast<double>(std::max<std::size_t>(run.frames.size(), 1));
    double top = 0.0;
    for (const FrameRecord& f : run.frames) {
        double sum = 0.0;
        for (double ms : f.pass_ms) sum += std::max(ms, 0.0);
        top = std::max({top, sum, f.ms_between});
    }
    Chart chart(canvas, nice_axis(0.0, n, "frame"), nice_axis(0.0, top * 1.05, "milliseconds"),
                title);
    chart.draw_frame();
    const glm::vec3 other{0.8f, 0.8f, 0.8f};
    for (std::size_t i = 0; i < run.frames.size(); ++i) {
        const FrameRecord& f = run.frames[i];
        const auto x0 = static_cast<double>(i), x1 = x0 + 1.0;
        double base = 0.0;
        for (std::size_t p = 0; p < f.pass_ms.size(); ++p) {
            const double ms = std::max(f.pass_ms[p], 0.0);
            canvas.fill_rect(chart.map(x0, base), chart.map(x1, base + ms), series_color(p));
            base += ms;
        }
        if (f.ms_between > base)
            canvas.fill_rect(chart.map(x0, base), chart.map(x1, f.ms_between), other);
    }
    for (std::size_t i = 1; i < run.frames.size(); ++i) {
        canvas.line(chart.map(static_cast<double>(i) - 0.5, run.frames[i - 1].ms_between),
                    chart.map(static_cast<double>(i) + 0.5, run.frames[i].ms_between), kInk, 1.0f);
    }
    int row = 0;
    chart.legend_entry(row++, "whole frame (line)", kInk);
    chart.legend_entry(row++, "outside passes", other);
    for (std::size_t p = run.pass_names.size(); p-- > 0;)
        chart.legend_entry(row++, run.pass_names[p], series_color(p));
    canvas.save(out);
}

namespace {

struct Box {
    glm::vec2 lo, hi;
    bool overlaps(const Box& o) const {
        return lo.x < o.hi.x && o.lo.x < hi.x && lo.y < o.hi.y && o.lo.y < hi.y;
    }
};

// Puts each label next to its point where it covers no other label or point and stays between
// the canvas's sides and below `top` (the chart's title): tries places around the point, then
// further out, and keeps the first free one. Points crowd at F1 = 1, right under the title.
std::vector<glm::vec2> place_labels(const Canvas& canvas, const std::vector<glm::vec2>& points,
                                    const std::vector<std::string>& labels, float height,
                                    float top) {
    std::vector<Box> taken;
    for (const glm::vec2& p : points) taken.push_back({p - 6.0f, p + 6.0f});
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float w = canvas.text_width(labels[i], height);
        // With no free place (a crowd of points), below the point: above it is the title.
        glm::vec2 best = points[i] + glm::vec2(9.0f, -height - 8.0f);
        bool found = false;
        for (float ring = 1.0f; ring <= 20.0f && !found; ring += 1.0f) {
            const float dy = (height + 4.0f) * ring;
            const glm::vec2 offsets[] = {
                {9.0f, dy - height - 2.0f}, {9.0f, -dy + 2.0f},     {-9.0f - w, dy - height - 2.0f},
                {-9.0f - w, -dy + 2.0f},    {-w * 0.5f, dy + 4.0f}, {-w * 0.5f, -dy - height}};
            for (const glm::vec2& o : offsets) {
                const glm::vec2 at = points[i] + o;
                const Box b{at - glm::vec2(2.0f), at + glm::vec2(w + 2.0f, height + 2.0f)};
                if (b.lo.x < 0.0f || b.hi.x > static_cast<float>(canvas.width())) continue;
                if (b.lo.y < 0.0f || b.hi.y > top) continue;
                if (std::any_of(taken.begin(), taken.end(),
                                [&](const Box& t) { return t.overlaps(b); }))
                    continue;
                best = at;
                taken.push_back(b);
                found = true;
                break;
            }
        }
        out.push_back(best);
    }
    return out;
}

}  // namespace

void plot_tradeoff(const std::vector<TradeoffPoint>& points, const std::string& title,
                   const scene::VectorFont* font, const std::filesystem::path& out) {
    Canvas canvas(1000, 700, kPaper, font);
    double xmax = 0.0, ymin = 1.0;
    for (const TradeoffPoint& p : points) {
        xmax = std::max(xmax, p.p50_ms);
        ymin = std::min(ymin, p.min_f1);
    }
    const double pad = std::max((1.0 - ymin) * 0.25, 0.002);
    Chart chart(canvas, nice_axis(0.0, xmax * 1.15, "p50 frame time (ms)"),
                nice_axis(std::max(0.0, ymin - pad), 1.0,
                          "F1 against the exact reference (mean, bar to min)"),
                title);
    chart.draw_frame();
    std::vector<glm::vec2> at;
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const TradeoffPoint& p = points[i];
        const glm::vec3 c = series_color(i);
        canvas.line(chart.map(p.p50_ms, p.min_f1), chart.map(p.p50_ms, p.mean_f1), c, 2.0f);
        at.push_back(chart.map(p.p50_ms, p.mean_f1));
        canvas.disc(at.back(), 5.0f, c);
        labels.push_back(p.label);
    }
    constexpr float kLabel = 11.0f;
    const std::vector<glm::vec2> where =
        place_labels(canvas, at, labels, kLabel, chart.title_bottom());
    for (std::size_t i = 0; i < points.size(); ++i) {
        canvas.text(labels[i], where[i], kLabel, series_color(i));
    }
    canvas.save(out);
}

void plot_scaling(const std::vector<ScalingPoint>& points, const LineFit& fit,
                  const std::string& title, const scene::VectorFont* font,
                  const std::filesystem::path& out) {
    Canvas canvas(1000, 700, kPaper, font);
    double xmax = 0.0, ymax = 0.0;
    for (const ScalingPoint& p : points) {
        xmax = std::max(xmax, p.triangles / 1e6);
        ymax = std::max(ymax, p.p50_ms);
    }
    Chart chart(canvas, nice_axis(0.0, xmax * 1.1, "triangles submitted per frame (millions)"),
                nice_axis(0.0, ymax * 1.15, "p50 frame time (ms)"), title);
    chart.draw_frame();
    const double x_end = xmax * 1.05;
    canvas.line(chart.map(0.0, fit.intercept),
                chart.map(x_end, fit.intercept + fit.slope * x_end * 1e6), series_color(1), 1.5f);
    std::vector<glm::vec2> at;
    std::vector<std::string> labels;
    for (const ScalingPoint& p : points) {
        at.push_back(chart.map(p.triangles / 1e6, p.p50_ms));
        canvas.disc(at.back(), 5.0f, series_color(0));
        labels.push_back(p.label);
    }
    const std::vector<glm::vec2> where =
        place_labels(canvas, at, labels, 11.0f, chart.title_bottom());
    for (std::size_t i = 0; i < points.size(); ++i) canvas.text(labels[i], where[i], 11.0f, kInk);
    char buf[128];
    std::snprintf(buf, sizeof buf, "fit: %.2f ms per 100k triangles + %.1f ms (r2 %.3f)",
                  fit.slope * 1e5, fit.intercept, fit.r2);
    chart.legend_entry(0, buf, series_color(1));
    canvas.save(out);
}

}  // namespace bz::app
