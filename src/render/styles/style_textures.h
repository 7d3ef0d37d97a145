#pragma once
// The small textures the stroke styles read, made once per renderer:
//   noise:   256 x 256 RGBA8 of uniform random values (fixed seed): sketch strokes look up
//            their split point and end-point jitter at a texel chosen by the edge's id, so a
//            still camera draws the same strokes every frame (Olejnik & Litchmore);
//   profile: 64 x 4 RG16F, one row per halo stroke: r = ink across the stroke (0 = inner
//            edge, 1 = outer edge), g = the soft halo's strength outside it (Loviscach);
//   offset:  64 x 64 RG16F of smooth random offsets in pixels, read at image-space position,
//            which shifts each of the halo's strokes differently along the line (Loviscach).
#include <vector>

#include "gl/texture.h"

namespace bz::render {

struct StyleTextures {
    gl::Texture2D noise;
    gl::Texture2D profile;
    gl::Texture2D offset;
};

StyleTextures make_style_textures();

// The CPU side, for tests: the profile rows (r, g interleaved) and the noise bytes.
std::vector<float> halo_profile_texels(int width, int rows);
std::vector<unsigned char> stroke_noise_texels(int size);

}  // namespace bz::render
