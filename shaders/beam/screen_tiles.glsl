// The screen in square tiles, for the sparse composite (pass_tiles.cpp, pass_composite.cpp):
// most of a vector frame is black, so the composite clears the target and shades only the
// tiles where the picture or its glow is lit. TILE_SIZE (pixels) comes from render/targets.h.
const int kTileSize = TILE_SIZE;
