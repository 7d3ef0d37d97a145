#version 450 core
// Filled styles: the object's triangles with view-space position and normal, its colour and
// whether it is shaded smooth (vertex normals) or flat (face normals, in the fragment shader).
// With SHRINK the mesh is pulled in along its vertex normals: the halo's depth mask (Loviscach).
layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_MODEL_VIEW) in mat4 a_model_view;  // four locations
layout(location = ATTRIB_COLOR) in vec4 a_color;
layout(location = ATTRIB_PARAMS) in vec4 a_params;      // w: smooth shading
layout(location = ATTRIB_NORMAL) in vec3 a_normal;

uniform mat4 u_proj;
uniform float u_shrink;  // SHRINK: view-space distance per unit of view depth (pixels at any depth)

out vec3 v_view_pos;
out vec3 v_view_normal;
flat out vec3 v_color;
flat out float v_smooth;

void main() {
    vec4 view = a_model_view * vec4(a_position, 1.0);
    // Inverse transpose: stays perpendicular to the surface under non-uniform scale.
    v_view_normal = transpose(inverse(mat3(a_model_view))) * a_normal;
#ifdef SHRINK
    // Pulled in by a fixed number of pixels at its own depth: at a silhouette, where the normal
    // lies in the screen plane, the shrunk outline sits that far inside the real one, which is
    // where the halo strokes must stay visible.
    float len = length(v_view_normal);
    if (len > 0.0) view.xyz -= v_view_normal / len * (u_shrink * max(-view.z, 0.0));
#endif
    v_view_pos = view.xyz;
    v_color = a_color.rgb;
    v_smooth = a_params.w;
    gl_Position = u_proj * view;
}
