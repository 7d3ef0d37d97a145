#version 450 core
// Feeds the edge-finding geometry shader the least it needs: the view-space position (for
// facing, clipping and depth), the welded vertex index (to emit each crease once and to spot
// the "no neighbour" marker) and the instance index (per-instance colour and crease threshold
// are read once per triangle from the instance buffer, not carried by every vertex).
layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_MODEL_VIEW) in mat4 a_model_view;  // four locations
layout(location = ATTRIB_PARAMS) in vec4 a_params;      // y: instance index

out VertexData {
    vec3 view_pos;
    flat uint vertex_id;
    flat uint instance;
} v_out;

void main() {
    vec4 view = a_model_view * vec4(a_position, 1.0);
    v_out.view_pos = view.xyz;
    v_out.vertex_id = uint(gl_VertexID);
    v_out.instance = uint(a_params.y);
    gl_Position = view;
}
