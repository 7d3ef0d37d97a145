#include "render/frame_resources.h"

namespace bz::render {

std::string_view resource_name(Resource r) {
    switch (r) {
        case Resource::depth:
            return "depth";
        case Resource::normals:
            return "normals";
        case Resource::edges:
            return "edges";
        case Resource::lines:
            return "lines";
        case Resource::beam_tiles:
            return "beam_tiles";
        case Resource::bloom_chain:
            return "bloom_chain";
        case Resource::bloom_out:
            return "bloom_out";
        case Resource::lit_tiles:
            return "lit_tiles";
        case Resource::tile_list:
            return "tile_list";
        case Resource::canvas:
            return "canvas";
        case Resource::shrunk_depth:
            return "shrunk_depth";
        case Resource::halo:
            return "halo";
        case Resource::mask:
            return "mask";
        case Resource::depth_tiles:
            return "depth_tiles";
        case Resource::peel_layers:
            return "peel_layers";
        case Resource::target:
            return "target";
        case Resource::phosphor:
            return "phosphor";
        case Resource::picture_lit:
            return "picture_lit";
        case Resource::glow:
            return "glow";
        case Resource::picture:
            return "picture";
    }
    return "?";
}

}  // namespace bz::render
