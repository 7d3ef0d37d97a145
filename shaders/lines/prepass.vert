#version 450 core
// Depth prepass: positions only, instanced.
layout(location = 0) in vec3 a_position;
layout(location = 1) in mat4 a_model_view;  // locations 1-4

uniform mat4 u_proj;

void main() {
    gl_Position = u_proj * (a_model_view * vec4(a_position, 1.0));
}
