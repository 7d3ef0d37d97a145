#version 450 core
// Feeds the edge-finding geometry shader: view-space position (for facing, clipping and
// depth), object-space position (for view-independent crease normals) and the welded vertex
// index (to emit each crease once and to spot the "no neighbour" marker).
layout(location = 0) in vec3 a_position;
layout(location = 1) in mat4 a_model_view;  // locations 1-4
layout(location = 5) in vec4 a_color;       // rgb * intensity, a unused
layout(location = 6) in vec4 a_params;      // x: cos(crease angle) for this instance

out VertexData {
    vec3 view_pos;
    vec3 object_pos;
    flat uint vertex_id;
    flat vec4 color;
    flat float cos_crease;
} v_out;

void main() {
    vec4 view = a_model_view * vec4(a_position, 1.0);
    v_out.view_pos = view.xyz;
    v_out.object_pos = a_position;
    v_out.vertex_id = uint(gl_VertexID);
    v_out.color = a_color;
    v_out.cos_crease = a_params.x;
    gl_Position = view;
}
