// Real models nobody here made render non-empty line masks through the full pipeline, and the
// colour frames are written to build/test-out for a person to look at.
#include <gtest/gtest.h>

#include <filesystem>
#include <span>

#include "render/render_fixture.h"

using bz::test::RenderTest;

TEST_F(RenderTest, RealModelsRenderNonEmptyMasks) {
    // The first four: line_methods_test draws all of them with both line methods.
    for (const char* path : std::span(bz::test::kRealModels).first(4)) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path))
            << "install assimp-testmodels (tools/install-deps)";
        show_model(path);
        const std::string name = std::filesystem::path(path).stem().string();
        const auto m = mask(name);
        // A recognisable drawing, not a speck: lines across a good part of the frame.
        EXPECT_GT(m.count(), 400);
        save_color(name);
    }
}
