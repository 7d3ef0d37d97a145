#include "render/styles/style_def.h"

#include <stdexcept>
#include <string>

#include "scene/style_table.h"

namespace bz::render {

const StyleDef& style_def(scene::Style style) {
    // The table's definitions, built once; indexed by the enum, which all_styles() lists whole.
    static const std::vector<StyleDef> defs = [] {
        std::vector<StyleDef> d;
        for (const scene::Style s : scene::all_styles()) d.push_back(scene::style_entry(s).def);
        return d;
    }();
    const auto i = static_cast<std::size_t>(style);
    if (i >= defs.size()) throw std::logic_error("style_def: no style number " + std::to_string(i));
    return defs[i];
}

}  // namespace bz::render
