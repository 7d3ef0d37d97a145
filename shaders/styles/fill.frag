#version 450 core
// The fill of a filled style, display-referred colour into the canvas. One file, three looks
// (compile-time FILL_TOON, FILL_POP_ART or FILL_PAPER):
//   toon:    2-4 cel bands of the object's colour from the light direction (Castro & Macedo)
//   pop-art: flat diffuse colour, then Ben-Day dots on a screen-aligned grid whose radius
//            grows as the shade darkens (Olejnik & Litchmore)
//   paper:   the paper tone itself, faintly shaded: the object hides what is behind it
in vec3 v_view_pos;
in vec3 v_view_normal;
flat in vec3 v_color;
flat in float v_smooth;

uniform vec3 u_light_dir;   // view space, towards the light, normalised
uniform int u_bands;        // toon
uniform float u_cell_px;    // pop-art dot grid spacing
uniform vec3 u_paper;       // background / paper tone
uniform float u_tint;       // paper: how much of the object's colour tints it

layout(location = 0) out vec4 o_color;

// The object's hue at full brightness: the vector palette is HDR (colour * intensity).
vec3 object_colour() {
    float peak = max(max(v_color.r, v_color.g), v_color.b);
    return peak > 1e-4 ? v_color / peak : vec3(0.8);
}

vec3 shading_normal() {
    vec3 flat_n = normalize(cross(dFdx(v_view_pos), dFdy(v_view_pos)));
    vec3 n = v_smooth > 0.5 && dot(v_view_normal, v_view_normal) > 1e-12 ? normalize(v_view_normal) : flat_n;
    // Both faces are drawn (open meshes): light the side that faces the eye.
    if (dot(n, -v_view_pos) < 0.0) n = -n;
    return n;
}

void main() {
    vec3 n = shading_normal();
    float diffuse = max(dot(n, u_light_dir), 0.0);
#if defined(FILL_TOON)
    // Band k of u_bands covers diffuse in [k/u_bands, (k+1)/u_bands); the darkest band keeps
    // some colour so the shape never drops to black.
    float band = min(floor(diffuse * float(u_bands)), float(u_bands - 1)) / float(u_bands - 1);
    o_color = vec4(object_colour() * mix(0.35, 1.0, band), 1.0);
#elif defined(FILL_POP_ART)
    vec3 base = object_colour() * mix(0.75, 1.0, step(0.5, diffuse));
    // Dots on a 45-degree screen grid; their radius covers more of the cell as it darkens.
    vec2 px = gl_FragCoord.xy;
    vec2 rot = vec2(px.x + px.y, px.x - px.y) * 0.70710678 / u_cell_px;
    vec2 cell = fract(rot) - 0.5;
    float r = 0.62 * sqrt(clamp(1.0 - diffuse, 0.0, 1.0));
    float dot_mask = 1.0 - smoothstep(r - 0.06, r + 0.06, length(cell));
    vec3 dot_colour = base * 0.35;
    o_color = vec4(mix(base, dot_colour, dot_mask), 1.0);
#else
    o_color = vec4(mix(u_paper, object_colour(), u_tint) * mix(0.9, 1.0, diffuse), 1.0);
#endif
}
