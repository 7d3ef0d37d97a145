#version 450 core
// Depth prepass: positions only, instanced.
layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_MODEL_VIEW) in mat4 a_model_view;  // four locations

uniform mat4 u_proj;

void main() {
    gl_Position = u_proj * (a_model_view * vec4(a_position, 1.0));
}
