// The finished bloom is stored in 8-bit unorm as sqrt(bloom / kBloomRange): llvmpipe filters
// 8-bit textures on a fast fixed-point path, several times cheaper than half floats, and the
// composite samples this image once per screen pixel. The square root spends the 8 bits where
// the eye needs them (a faint glow has no visible steps); bilinear filtering between encoded
// texels is slightly off the linear mean, which a blur cannot show.
const float kBloomRange = 4.0;

vec3 encode_bloom(vec3 linear) { return sqrt(clamp(linear * (1.0 / kBloomRange), 0.0, 1.0)); }
vec3 decode_bloom(vec3 encoded) { return encoded * encoded * kBloomRange; }
