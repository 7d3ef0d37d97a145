#include "render/auto_threshold.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/camera/camera_framing.h"
#include "render/renderer.h"

namespace bz::render {

namespace {

// Calibration frames: a sphere of about 1k, 4k, 16k and 48k triangles, the fastest of 4 timed
// frames each after one warm-up (the least disturbed by other processes), at a small size so
// that the passes both methods share (bloom, composite) add little noise.
constexpr int kWidth = 320, kHeight = 240;
constexpr int kTimedFrames = 4;
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
    std::vector<double> ms[2];
    for (const LineMethod method : {LineMethod::geometry_shader, LineMethod::compute}) {
        RenderSettings settings = preset("balanced");
        settings.method = method;
        settings.lod = false;  // every size drawn whole, never a simplified mesh
        Renderer renderer(settings, kWidth, kHeight, gl::TimingMethod::cpu_finish);
        for (const scene::FrameList& frame : frames) {
            std::vector<double> times;
            for (int i = 0; i <= kTimedFrames; ++i) {
                renderer.render(frame, meshes, Renderer::kOffscreen);
                double total = 0.0;
                for (const gl::PassTime& p : renderer.pass_times()) total += p.ms;
                if (i > 0) times.push_back(total);  // the first frame uploads the mesh
            }
            ms[method == LineMethod::compute].push_back(fastest(times));
        }
    }
    out.geometry_shader_ms = ms[0];
    out.compute_ms = ms[1];
    out.geometry_shader = fit_cost(out.sizes, ms[0]);
    out.compute = fit_cost(out.sizes, ms[1]);
    out.compute_from_triangles = crossing_triangles(out.geometry_shader, out.compute);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace bz::render
