#pragma once
// The renderer's view of the style table (scene/style.h): a style's StyleDef by id.
#include "scene/style.h"
#include "scene/style_def.h"

namespace bz::render {

using scene::FillPass;
using scene::HaloParams;
using scene::HudTheme;
using scene::LinePass;
using scene::OutlineParams;
using scene::OutlineQuad;
using scene::SketchParams;
using scene::StyleDef;

// The definition of every scene::Style, from the style table.
const StyleDef& style_def(scene::Style style);

}  // namespace bz::render
