#pragma once
// LineMethod::automatic chooses between the geometry shader and the compute method by the
// triangles a frame submits. Where the two costs cross depends on the machine: llvmpipe runs
// the geometry shader on one thread at a cost per triangle while the compute method scales
// with its threads but pays fixed costs per frame; a hardware GPU is another story again. So
// the crossing is measured on the running machine (measure_auto_threshold) and the app keeps
// it per machine (app/line_method_profile.h); kAutoComputeFromTriangles is only the fallback.
#include <cstddef>
#include <string>
#include <vector>

namespace bz::render {

// One method's frame time against triangles: ms = fixed + per_1k * triangles / 1000, a least-
// squares line through its fastest frame time at each calibration size.
struct MethodCost {
    double fixed_ms = 0.0;
    double per_1k_ms = 0.0;
};

struct AutoThresholdMeasurement {
    // The compute method from this many submitted triangles (0: always; kNeverCompute: never).
    std::size_t compute_from_triangles = 0;
    MethodCost geometry_shader, compute;
    std::vector<std::size_t> sizes;                      // triangles of the calibration frames
    std::vector<double> geometry_shader_ms, compute_ms;  // each size's fastest frame
    double seconds = 0.0;                                // how long the measurement took
};

inline constexpr std::size_t kNeverCompute = static_cast<std::size_t>(-1);

// Where two cost lines cross: the smallest triangle count from which compute costs no more.
std::size_t crossing_triangles(const MethodCost& geometry_shader, const MethodCost& compute);

// The crossing from the measured points themselves (sizes ascending, each size's fastest
// frame per method): from the first size after which compute never costs more, interpolated
// between that size and the one before; outside the measured sizes, the fitted lines'
// crossing (clamped to below the smallest size when compute already wins there). One frame
// disturbed by load moves only its neighbourhood, where a line fitted through every point
// swung its intercept and with it the crossing to 0 or to never.
std::size_t measured_crossing(const std::vector<std::size_t>& sizes,
                              const std::vector<double>& geometry_shader_ms,
                              const std::vector<double>& compute_ms);

// Least squares through (triangles, ms) points.
MethodCost fit_cost(const std::vector<std::size_t>& triangles, const std::vector<double>& ms);

// Renders spheres of a few sizes with both methods on the current GL context (a few hundred
// milliseconds on llvmpipe) and fits each method's cost. Needs a current context.
AutoThresholdMeasurement measure_auto_threshold();

}  // namespace bz::render
