#version 450 core
// The flat face normal from screen-space derivatives of the view position: exact for a
// triangle, and it needs no normals in the vertex data (meshes carry positions only). Stored
// as n * 0.5 + 0.5 in RGBA8; alpha 1 marks a surface.
in vec3 v_view_pos;

layout(location = 0) out vec4 o_normal;

void main() {
    vec3 n = cross(dFdx(v_view_pos), dFdy(v_view_pos));
    float len = length(n);
    o_normal = vec4((len > 0.0 ? n / len : vec3(0.0)) * 0.5 + 0.5, 1.0);
}
