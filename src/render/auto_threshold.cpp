#include "render/auto_threshold.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/camera/camera_framing.h"
#include "render/renderer.h"

namespace bz::render {

namespace {

// Calibration frames: a sphere of about 1k, 4k, 16k and 48k triangles, the fastest of 8 timed
// frames each after one warm-up (the least disturbed by other processes), at a small size so
// that the passes both methods share (bloom, composite) add little noise.
constexpr int kWidth = 320, kHeight = 240;
constexpr int kTimedFrames = 8;
constexpr std::uint32_t kRings[] = {16, 32, 64, 112};

double fastest(const std::vector<double>& v) {
    return *std::min_element(v.begin(), v.end());
}

}  // namespace

MethodCost fit_cost(const std::vector<std::size_t>& triangles, const std::vector<double>& ms) {
    const double n = static_cast<double>(triangles.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const double x = static_cast<double>(triangles[i]) / 1000.0;
        sx += x;
        sy += ms[i];
        sxx += x * x;
        sxy += x * ms[i];
    }
    const double det = n * sxx - sx * sx;
    if (!(n > 0.0)) return {};
    if (!(std::abs(det) > 0.0)) return {sy / n, 0.0};
    const double slope = (n * sxy - sx * sy) / det;
    return {(sy - slope * sx) / n, slope};
}

std::size_t crossing_triangles(const MethodCost& g, const MethodCost& c) {
    const double slope_gain = g.per_1k_ms - c.per_1k_ms;  // what compute saves per 1k triangles
    const double fixed_loss = c.fixed_ms - g.fixed_ms;    // what it costs more per frame
    if (!(slope_gain > 0.0)) return fixed_loss < 0.0 ? 0 : kNeverCompute;
    if (fixed_loss <= 0.0) return 0;
    const double k = fixed_loss / slope_gain * 1000.0;
    if (!std::isfinite(k) || k >= 1e12) return kNeverCompute;
    return static_cast<std::size_t>(std::ceil(k * (1.0 - 1e-12)));  // not up for rounding
}

std::size_t measured_crossing(const std::vector<std::size_t>& sizes,
                              const std::vector<double>& geometry_shader_ms,
                              const std::vector<double>& compute_ms) {
    const std::size_t n = std::min({sizes.size(), geometry_shader_ms.size(), compute_ms.size()});
    const MethodCost g = fit_cost(sizes, geometry_shader_ms), c = fit_cost(sizes, compute_ms);
    if (n == 0) return crossing_triangles(g, c);
    // What compute saves at each size; `from`: the first size after which it never loses.
    std::size_t from = n;
    while (from > 0 && geometry_shader_ms[from - 1] - compute_ms[from - 1] >= 0.0) --from;
    if (from == n) return crossing_triangles(g, c);  // dearer at the largest size: beyond it
    if (from == 0) return std::min(crossing_triangles(g, c), sizes[0]);
    const double lose = compute_ms[from - 1] - geometry_shader_ms[from - 1];  // > 0
    const double save = geometry_shader_ms[from] - compute_ms[from];          // >= 0
    const double a = static_cast<double>(sizes[from - 1]), b = static_cast<double>(sizes[from]);
    return static_cast<std::size_t>(std::ceil(a + (b - a) * lose / (lose + save)));
}

AutoThresholdMeasurement measure_auto_threshold() {
    const auto start = std::chrono::steady_clock::now();
    AutoThresholdMeasurement out;
    scene::MeshLibrary meshes;
    std::vector<scene::FrameList> frames;
    for (const std::uint32_t rings : kRings) {
        geo::AdjacencyMesh mesh = geo::build_line_mesh(geo::uv_sphere(1.0f, rings, rings * 2));
        out.sizes.push_back(mesh.triangle_count());
        const geo::Bounds bounds = geo::compute_bounds(mesh.positions);
        scene::FrameList frame;
        frame.items.push_back(
            {meshes.add("calibration sphere " + std::to_string(rings), std::move(mesh))});
        frame.camera = frame_bounds(bounds, 50.0, static_cast<double>(kWidth) / kHeight);
        frames.push_back(std::move(frame));
    }
    // Both methods' renderers live side by side and take turns frame by frame, so a load that
    // comes and goes while the machine is measured falls on both alike: measured one method
    // after the other, a busy spell during one alone moved the crossing to 0 or to never.
    const LineMethod methods[2] = {LineMethod::geometry_shader, LineMethod::compute};
    std::vector<std::unique_ptr<Renderer>> renderers;
    for (const LineMethod method : methods) {
        RenderSettings settings = preset("balanced");
        settings.method = method;
        settings.lod = false;  // every size drawn whole, never a simplified mesh
        renderers.push_back(
            std::make_unique<Renderer>(settings, kWidth, kHeight, gl::TimingMethod::cpu_finish));
    }
    std::vector<double> ms[2];
    for (const scene::FrameList& frame : frames) {
        std::vector<double> times[2];
        for (int i = 0; i <= kTimedFrames; ++i) {
            for (int m = 0; m < 2; ++m) {
                renderers[m]->render(frame, meshes, Renderer::kOffscreen);
                double total = 0.0;
                for (const gl::PassTime& p : renderers[m]->pass_times()) total += p.ms;
                if (i > 0) times[m].push_back(total);  // the first frame uploads the mesh
            }
        }
        for (int m = 0; m < 2; ++m) ms[m].push_back(fastest(times[m]));
    }
    out.geometry_shader_ms = ms[0];
    out.compute_ms = ms[1];
    out.geometry_shader = fit_cost(out.sizes, ms[0]);
    out.compute = fit_cost(out.sizes, ms[1]);
    out.compute_from_triangles = measured_crossing(out.sizes, ms[0], ms[1]);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace bz::render
