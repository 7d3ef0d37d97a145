#pragma once
// Camera matrices in double precision. View-space positions are computed per instance as
// (view * model) in double before the cast to float, so scenes 1e6 units from the origin
// render camera-relative with no jitter.
#include <glm/glm.hpp>

#include "render/settings.h"
#include "scene/frame_list.h"

namespace bz::render {

struct CameraMatrices {
    glm::dmat4 view{1.0};
    glm::mat4 proj{1.0};
    // Terms of proj that map stored depth back to view depth: view_depth = b / (ndc_z + a).
    float proj_a = 0.0f;
    float proj_b = 0.0f;
    bool zero_to_one = true;  // reversed-Z uses [0,1] clip depth (glClipControl)
    float near = 0.1f;
    float far = 1000.0f;
};

CameraMatrices camera_matrices(const scene::Camera& camera, double aspect, DepthFormat depth);

}  // namespace bz::render
