// LineMethod::automatic's crossing measured on the running machine (render/auto_threshold.h):
// the fit and the crossing on numbers where the answer is known, a measured crossing that
// replaces the built-in rule, and a real measurement on this context.
#include "render/auto_threshold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/settings.h"
#include "support/gl_test.h"

namespace bz::render {
namespace {

TEST(AutoThreshold, FitsALineThroughExactPoints) {
    const MethodCost c = fit_cost({1000, 4000, 16000}, {2.5, 4.0, 10.0});
    EXPECT_NEAR(c.fixed_ms, 2.0, 1e-9);
    EXPECT_NEAR(c.per_1k_ms, 0.5, 1e-9);
    const MethodCost flat = fit_cost({5000, 5000}, {3.0, 5.0});  // one size: the mean, no slope
    EXPECT_NEAR(flat.fixed_ms, 4.0, 1e-9);
    EXPECT_EQ(flat.per_1k_ms, 0.0);
}

TEST(AutoThreshold, CrossesWhereComputeStopsCostingMore) {
    // Geometry shader 1 ms + 0.3 ms/1k; compute 4 ms + 0.1 ms/1k: equal at 15k triangles.
    EXPECT_EQ(crossing_triangles({1.0, 0.3}, {4.0, 0.1}), 15000u);
    EXPECT_EQ(crossing_triangles({5.0, 0.3}, {4.0, 0.1}), 0u);             // compute always
    EXPECT_EQ(crossing_triangles({1.0, 0.1}, {4.0, 0.3}), kNeverCompute);  // never
    EXPECT_EQ(crossing_triangles({5.0, 0.1}, {4.0, 0.3}), 0u);             // cheaper, flatter
    EXPECT_EQ(crossing_triangles({1.0, 0.3}, {4.0, 0.3}), kNeverCompute);  // parallel, dearer
}

TEST(AutoThreshold, CrossesBetweenTheMeasuredSizesWhereComputeStopsLosing) {
    const std::vector<std::size_t> sizes = {1000, 4000, 16000, 48000};
    // Compute loses by 1 ms at 1k and saves 2 ms at 4k: a third of the way, 2k triangles.
    EXPECT_EQ(measured_crossing(sizes, {2.0, 5.0, 9.0, 20.0}, {3.0, 3.0, 5.0, 8.0}), 2000u);
    // One frame disturbed by load (the geometry shader's 4k frame at 9 ms) moves the fitted
    // lines' crossing a long way; the measured one stays between 1k and 4k.
    const std::vector<double> g = {2.0, 9.0, 9.0, 20.0}, c = {3.0, 3.0, 5.0, 8.0};
    EXPECT_EQ(measured_crossing(sizes, g, c), 1429u);  // 1000 + 3000 * 1 / 7, rounded up
    // A win at a small size that is lost again later does not count: between 4k and 16k.
    EXPECT_EQ(measured_crossing(sizes, {3.0, 3.0, 6.0, 20.0}, {2.0, 4.0, 5.0, 8.0}), 10000u);
    // Compute dearer at every size: the fitted lines decide (here parallel: never).
    EXPECT_EQ(measured_crossing(sizes, {1.0, 2.0, 3.0, 4.0}, {2.0, 3.0, 4.0, 5.0}), kNeverCompute);
    // Cheaper at every size: from at most the smallest size.
    EXPECT_LE(measured_crossing(sizes, {3.0, 5.0, 9.0, 20.0}, {2.0, 3.0, 5.0, 8.0}), 1000u);
}

TEST(AutoThreshold, AMeasuredCrossingReplacesTheBuiltInRule) {
    for (const bool software : {true, false}) {
        EXPECT_EQ(resolve_line_method(LineMethod::automatic, 999, software, 1000),
                  LineMethod::geometry_shader);
        EXPECT_EQ(resolve_line_method(LineMethod::automatic, 1000, software, 1000),
                  LineMethod::compute);
        EXPECT_EQ(resolve_line_method(LineMethod::automatic, 0, software, 0), LineMethod::compute);
        EXPECT_EQ(resolve_line_method(LineMethod::automatic, 1u << 30, software, kNeverCompute),
                  LineMethod::geometry_shader);
        EXPECT_EQ(resolve_line_method(LineMethod::geometry_shader, 1u << 30, software, 0),
                  LineMethod::geometry_shader);
    }
}

class AutoThresholdGlTest : public test::GlTest {};

TEST_F(AutoThresholdGlTest, MeasuresBothMethodsOnThisContext) {
    const AutoThresholdMeasurement m = measure_auto_threshold();
    ASSERT_EQ(m.sizes.size(), 4u);
    for (std::size_t i = 1; i < m.sizes.size(); ++i) EXPECT_GT(m.sizes[i], m.sizes[i - 1]);
    std::string points;
    for (std::size_t i = 0; i < m.sizes.size(); ++i) {
        points += std::to_string(m.sizes[i]) + ": " + std::to_string(m.geometry_shader_ms[i]) +
                  " / " + std::to_string(m.compute_ms[i]) + " ms; ";
    }
    SCOPED_TRACE(points);
    // Timings only: no test asserts on what they say (a loaded machine reorders them), only
    // that every size was timed and the fit and the crossing follow from the times.
    ASSERT_EQ(m.geometry_shader_ms.size(), m.sizes.size());
    ASSERT_EQ(m.compute_ms.size(), m.sizes.size());
    for (std::size_t i = 0; i < m.sizes.size(); ++i) {
        EXPECT_GT(m.geometry_shader_ms[i], 0.0);
        EXPECT_GT(m.compute_ms[i], 0.0);
    }
    const MethodCost g = fit_cost(m.sizes, m.geometry_shader_ms);
    EXPECT_EQ(g.fixed_ms, m.geometry_shader.fixed_ms);
    EXPECT_EQ(g.per_1k_ms, m.geometry_shader.per_1k_ms);
    for (const MethodCost& c : {m.geometry_shader, m.compute})
        EXPECT_TRUE(std::isfinite(c.fixed_ms) && std::isfinite(c.per_1k_ms));
    EXPECT_EQ(m.compute_from_triangles,
              measured_crossing(m.sizes, m.geometry_shader_ms, m.compute_ms));
    EXPECT_GT(m.seconds, 0.0);
}

}  // namespace
}  // namespace bz::render
