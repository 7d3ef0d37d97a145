#include "render/camera/camera_math.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace bz::render {

CameraMatrices camera_matrices(const scene::Camera& c, double aspect, DepthFormat depth) {
    CameraMatrices m;
    m.view = glm::lookAt(c.eye, c.target, c.up);
    const double n = c.near, f = c.far;
    const double cot = 1.0 / std::tan(glm::radians(c.fov_y_deg) * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = cot / aspect;
    p[1][1] = cot;
    p[2][3] = -1.0;
    if (depth == DepthFormat::reversed_f32) {
        // Near maps to depth 1 and far to 0: float precision is spent where depth is large.
        p[2][2] = n / (f - n);
        p[3][2] = n * f / (f - n);
        m.zero_to_one = true;
    } else {
        p[2][2] = -(f + n) / (f - n);
        p[3][2] = -2.0 * f * n / (f - n);
        m.zero_to_one = false;
    }
    m.proj = glm::mat4(p);
    m.proj_a = static_cast<float>(p[2][2]);
    m.proj_b = static_cast<float>(p[3][2]);
    m.near = static_cast<float>(n);
    m.far = static_cast<float>(f);
    return m;
}

}  // namespace bz::render
