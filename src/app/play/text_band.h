#pragma once
// The band one line of overlay text takes, shared by the play overlay and the --edit footer so
// their lines stack the same way.

namespace bz::app {

// Where the baseline sits in a line's band, and how far glyphs reach past the cap height and
// below the baseline (round tops, descenders), in text heights: a line stays in its band.
inline constexpr float kBaselineLift = 0.38f;
inline constexpr float kGlyphOvershoot = 0.15f;
inline constexpr float kTextBand = kBaselineLift + 1.0f + kGlyphOvershoot;

}  // namespace bz::app
