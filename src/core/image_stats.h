#pragma once
// Simple measurements of a picture.
#include "core/image_io.h"

namespace bz {

// The share (0..1) of pixels whose brightest colour channel is above `level` (0..255; alpha is
// not counted). With level 1 it is the "haze" figure (docs/measurements/haze.md): how much of a
// vector picture is not black (pixels above 1/255).
double lit_share(const Image& image, int level = 1);

}  // namespace bz
