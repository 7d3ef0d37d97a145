// The kept per-machine crossing (app/line_method_profile.h): the file on strings, then the
// whole cycle on a real context: measured once and kept, read back the next time, and a file
// that does not parse left as it was.
#include "app/line_method_profile.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/io/file_io.h"
#include "support/gl_test.h"
#include "support/scratch_dir.h"

namespace bz::app {
namespace {

LineMethodProfile measured(const std::string& machine, std::size_t from) {
    LineMethodProfile p;
    p.machine = machine;
    p.measurement = render::AutoThresholdMeasurement{};
    p.measurement->compute_from_triangles = from;
    p.measurement->geometry_shader = {1.5, 0.25};
    p.measurement->compute = {3.0, 0.125};
    return p;
}

TEST(LineMethodProfile, KeepsEachMachineApartAndReadsItBack) {
    const std::string one = updated_line_method_cache("", measured("llvmpipe | 2", 6000));
    const std::string both = updated_line_method_cache(one, measured("H100 | 1", 0));
    const auto a = kept_measurement(both, "llvmpipe | 2");
    ASSERT_TRUE(a.has_value());
    EXPECT_EQ(a->compute_from_triangles, 6000u);
    EXPECT_EQ(a->geometry_shader.per_1k_ms, 0.25);
    EXPECT_EQ(a->compute.fixed_ms, 3.0);
    EXPECT_EQ(kept_measurement(both, "H100 | 1")->compute_from_triangles, 0u);
    EXPECT_FALSE(kept_measurement(both, "another machine").has_value());
    // "Never compute" is kept as null and read back as such.
    const std::string never =
        updated_line_method_cache(both, measured("llvmpipe | 2", render::kNeverCompute));
    EXPECT_NE(never.find("null"), std::string::npos);
    EXPECT_EQ(kept_measurement(never, "llvmpipe | 2")->compute_from_triangles,
              render::kNeverCompute);
}

TEST(LineMethodProfile, ABrokenFileIsAnErrorWithItsPosition) {
    try {
        kept_measurement("{\"machines\": {\n  \"x\": [1,\n}", "x");
        FAIL() << "a broken file parsed";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
    }
    EXPECT_THROW(kept_measurement("[]", "x"), UserError);
    EXPECT_THROW(kept_measurement(R"({"machines": {"x": {"compute_from_triangles": -4}}})", "x"),
                 UserError);
    EXPECT_THROW(kept_measurement(R"({"machines": {"x": {"compute_from_triangles": 5,
                 "geometry_shader": {"fixed_ms": "a", "per_1k_triangles_ms": 1},
                 "compute": {"fixed_ms": 1, "per_1k_triangles_ms": 1}}}})",
                                  "x"),
                 UserError);
}

TEST(LineMethodProfile, TheMachineKeyNamesTheThreadsLlvmpipeMayUse) {
    const std::string key = line_method_machine_key("llvmpipe (LLVM 15)", "4.5 (Mesa 22)");
    EXPECT_NE(key.find("llvmpipe (LLVM 15)"), std::string::npos);
    EXPECT_NE(key.find("LP_NUM_THREADS="), std::string::npos);
    EXPECT_NE(key.find("processors"), std::string::npos);
}

class LineMethodProfileGlTest : public test::GlTest {};

TEST_F(LineMethodProfileGlTest, MeasuresOnceKeepsItAndNeverOverwritesABrokenFile) {
    const test::ScratchDir dir("bz_line_methods");
    const auto cache = dir.path() / "line-methods.json";
    const LineMethodProfile kept_only = line_method_profile(cache, Calibration::kept_only);
    EXPECT_FALSE(kept_only.measurement.has_value());
    EXPECT_FALSE(std::filesystem::exists(cache));

    const LineMethodProfile first = line_method_profile(cache, Calibration::measure_if_missing);
    ASSERT_TRUE(first.measurement.has_value());
    EXPECT_EQ(first.source.rfind("measured now", 0), 0u) << first.source;
    ASSERT_TRUE(std::filesystem::exists(cache));
    const LineMethodProfile second = line_method_profile(cache, Calibration::measure_if_missing);
    ASSERT_TRUE(second.measurement.has_value());
    EXPECT_EQ(second.source.rfind("measured earlier", 0), 0u) << second.source;
    EXPECT_EQ(second.threshold(), first.threshold());
    EXPECT_NE(second.describe().find("compute from"), std::string::npos);

    const std::string broken = "{ \"machines\": { oops";
    write_file_atomic(cache, broken);
    const LineMethodProfile third = line_method_profile(cache, Calibration::measure_if_missing);
    EXPECT_TRUE(third.measurement.has_value());
    EXPECT_NE(third.source.find("not kept"), std::string::npos) << third.source;
    EXPECT_EQ(read_file(cache), broken);
}

}  // namespace
}  // namespace bz::app
