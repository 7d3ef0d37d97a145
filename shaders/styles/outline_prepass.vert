#version 450 core
// Image-space outline baseline: depth prepass that also writes face normals.
layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_MODEL_VIEW) in mat4 a_model_view;  // four locations

uniform mat4 u_proj;

out vec3 v_view_pos;

void main() {
    vec4 view = a_model_view * vec4(a_position, 1.0);
    v_view_pos = view.xyz;
    gl_Position = u_proj * view;
}
