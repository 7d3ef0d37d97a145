#include "support/gl_test.h"

#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace bz::test {

platform::GlContext& shared_context() {
    static std::unique_ptr<platform::GlContext> ctx = [] {
        setenv("SDL_VIDEODRIVER", "offscreen", 0);
        platform::ContextOptions o;
        o.mode = platform::WindowMode::hidden;
        o.width = 64;
        o.height = 64;
        return std::make_unique<platform::GlContext>(o);
    }();
    return *ctx;
}

void GlTest::SetUp() {
    shared_context().debug().clear();
}

void GlTest::TearDown() {
    auto& sink = shared_context().debug();
    EXPECT_EQ(sink.error_count(), 0) << "GL debug output reported errors";
    for (const auto& m : sink.messages()) ADD_FAILURE() << m;
    // Performance hints (vendor drivers only) are shown, not failed: see gl/debug.h.
    for (const auto& m : sink.performance_hints()) std::fprintf(stderr, "note: %s\n", m.c_str());
}

}  // namespace bz::test
