#version 450 core
// One value into every texel of a colour image: a clear on the shader cores, past the raster
// back end (render/clear_image.h says where that pays). The image is write-only, so it needs
// no format qualifier: one program serves every colour format the frame clears.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_UNIT_CLEAR) writeonly uniform image2D u_image;
uniform vec4 u_value;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(texel, imageSize(u_image)))) imageStore(u_image, texel, u_value);
}
