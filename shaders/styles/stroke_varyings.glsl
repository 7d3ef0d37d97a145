// The varyings stroke.vert hands every stroke fragment shader.
noperspective in vec2 g_pixel;
flat in vec2 g_p0;
flat in vec2 g_p1;
flat in vec2 g_inv_depth;
flat in vec3 g_edge_plane;
flat in vec3 g_face_pos;
flat in vec3 g_face_neg;
flat in vec2 g_nudge;
flat in vec3 g_color;
flat in uint g_kind;
flat in uint g_seed;
flat in vec2 g_outward;
flat in vec2 g_slopes;
flat in float g_significance;

const uint KIND_CREASE = 0u;
const uint KIND_SILHOUETTE = 1u;
