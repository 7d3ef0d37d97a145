// --edit shows the level as it is now: after the camera has flown, the picture is the one a
// fresh renderer draws at the same camera, in every beam look (the edit session keeps no
// past, RenderSettings::keep_history). The same flight with the history kept leaves trails in
// a look with a phosphor, so the comparison can fail. Frames go to build/test-out/edit_*.png.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/play/play_sessions.h"
#include "core/image_io.h"
#include "core/log.h"
#include "game/default_level.h"
#include "render/renderer.h"
#include "scene/presentation_clock.h"
#include "support/gl_test.h"
#include "support/tree_paths.h"

namespace {

constexpr int kTrailsW = 320, kTrailsH = 180;

// Pixels whose channels differ by more than 2/255 anywhere.
int differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    int n = 0;
    for (std::size_t i = 0; i + 3 < a.size(); i += 4) {
        for (std::size_t c = 0; c < 3; ++c) {
            if (std::abs(int(a[i + c]) - int(b[i + c])) > 2) {
                ++n;
                break;
            }
        }
    }
    return n;
}

void save(const std::string& name, const std::vector<std::uint8_t>& rgba) {
    const auto dir = bz::test::binary_dir() / "test-out";
    std::filesystem::create_directories(dir);
    bz::write_png(dir / name, bz::Image{kTrailsW, kTrailsH, 4, rgba});
}

class EditTrailsTest : public bz::test::GlTest {
  protected:
    // Flies the edit camera (turning and moving) for `frames` frames at 60 Hz, drawing each;
    // returns the last frame drawn and leaves its picture in `r`.
    bz::scene::FrameList fly(bz::app::PlaySession& s, bz::render::Renderer& r, int frames) {
        bz::scene::PresentationClock clock;
        bz::scene::FrameList f;
        for (int i = 0; i < frames; ++i) {
            bz::platform::FlyControls c;
            c.yaw = 1.0f;
            c.forward = 1.0f;
            s.update(c, 1.0 / 60.0);
            clock.advance_nominal();
            f = s.frame(1.0, double(kTrailsW) / kTrailsH);
            clock.stamp(f);
            r.render(f, s.meshes(), bz::render::Renderer::kOffscreen);
        }
        return f;
    }
};

TEST_F(EditTrailsTest, AFlownFrameEqualsAFreshOneInEveryBeamLook) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const bz::level::Level level = bz::game::default_level();
    bz::Log log;
    bz::app::SessionOptions o;
    o.level = &level;
    o.font = &font;
    for (const std::string& look : bz::render::beam_look_names()) {
        SCOPED_TRACE(look);
        bz::render::RenderSettings settings = bz::render::preset("balanced");
        settings.beam = bz::render::beam_look(look);
        const auto session = bz::app::make_edit_session(o, log);
        EXPECT_FALSE(session->keeps_history()) << "the edit session's pictures keep no past";
        settings.keep_history = session->keeps_history();  // as the play loop sets it
        bz::render::Renderer flown(settings, kTrailsW, kTrailsH, bz::gl::TimingMethod::off);
        const bz::scene::FrameList last = fly(*session, flown, 20);
        const std::vector<std::uint8_t> after = flown.read_color();

        bz::render::Renderer fresh(settings, kTrailsW, kTrailsH, bz::gl::TimingMethod::off);
        fresh.render(last, session->meshes(), bz::render::Renderer::kOffscreen);
        const std::vector<std::uint8_t> clean = fresh.read_color();
        save("edit_" + look + "_flown.png", after);
        save("edit_" + look + "_fresh.png", clean);
        ASSERT_EQ(after.size(), clean.size());
        EXPECT_EQ(differing(after, clean), 0) << "the flight left trails";

        // The same flight keeping its past: a look with a phosphor trails, so the test can
        // tell trails from none.
        if (settings.beam.phosphor != bz::render::PhosphorDecay::off) {
            const auto again = bz::app::make_edit_session(o, log);
            bz::render::RenderSettings keeping = settings;
            keeping.keep_history = true;
            bz::render::Renderer trailing(keeping, kTrailsW, kTrailsH, bz::gl::TimingMethod::off);
            fly(*again, trailing, 20);
            const std::vector<std::uint8_t> trails = trailing.read_color();
            save("edit_" + look + "_with_history.png", trails);
            EXPECT_GT(differing(trails, clean), 50);
        }
    }
}

// A beam look's history is dropped when a frame without a beam picture (a filled style) came
// between: switching back to vector shows no ghost of the frames before the switch.
TEST_F(EditTrailsTest, NoGhostAfterAFilledStyleFrame) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const bz::level::Level level = bz::game::default_level();
    bz::Log log;
    bz::app::SessionOptions o;
    o.level = &level;
    o.font = &font;
    bz::render::RenderSettings settings = bz::render::preset("balanced");
    settings.beam = bz::render::beam_look("mame");
    const auto session = bz::app::make_edit_session(o, log);
    bz::render::Renderer r(settings, kTrailsW, kTrailsH, bz::gl::TimingMethod::off);
    bz::scene::FrameList f = fly(*session, r, 10);  // a picture with a past
    f.style = bz::scene::Style::toon;
    r.render(f, session->meshes(), bz::render::Renderer::kOffscreen);
    bz::platform::FlyControls turn;
    turn.yaw = 1.0f;
    session->update(turn, 0.5);  // far from where the history was drawn
    bz::scene::FrameList back = session->frame(1.0, double(kTrailsW) / kTrailsH);
    back.time_s = f.time_s;  // no time passes: only a forgotten history leaves no ghost
    r.render(back, session->meshes(), bz::render::Renderer::kOffscreen);
    bz::render::Renderer fresh(settings, kTrailsW, kTrailsH, bz::gl::TimingMethod::off);
    fresh.render(back, session->meshes(), bz::render::Renderer::kOffscreen);
    EXPECT_EQ(differing(r.read_color(), fresh.read_color()), 0);
}

}  // namespace
