// The frame's per-instance data, render::InstanceData (src/render/gpu_scene/mesh_cache.h), read
// as a storage buffer of vec4. Its layout (INSTANCE_VEC4S per instance, the INSTANCE_* offsets)
// and the binding are #defines injected from src/render/shader_interface.h.
layout(std430, binding = INSTANCES_BINDING) readonly buffer Instances { vec4 instance_data[]; };

mat4 instance_model_view(uint i) {
    uint base = i * INSTANCE_VEC4S + INSTANCE_MODEL_VIEW;
    return mat4(instance_data[base], instance_data[base + 1u], instance_data[base + 2u],
                instance_data[base + 3u]);
}
vec4 instance_color(uint i) { return instance_data[i * INSTANCE_VEC4S + INSTANCE_COLOR]; }
// x: cos(crease angle), y: the instance's index, z: intensity, w: 1 = smooth shading.
vec4 instance_params(uint i) { return instance_data[i * INSTANCE_VEC4S + INSTANCE_PARAMS]; }
