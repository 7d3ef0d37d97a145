#pragma once
// The game's built-in vector font, loaded once per test binary: the HUD, menu and game tests
// draw text with it. One definition here, not a copy per file, so the files of a test binary
// can share a unity batch (BEAMZONE_UNITY).
#include "scene/vector_font.h"

namespace bz::test {

inline const scene::VectorFont& default_font() {
    static const scene::VectorFont font = scene::VectorFont::load_default();
    return font;
}

}  // namespace bz::test
