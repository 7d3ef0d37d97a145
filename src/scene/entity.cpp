#include "scene/entity.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace bz::scene {

glm::dmat4 Transform::matrix() const {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), position);
    m = glm::rotate(m, yaw, glm::dvec3(0.0, 1.0, 0.0));
    m = glm::rotate(m, pitch, glm::dvec3(1.0, 0.0, 0.0));
    m = glm::rotate(m, roll, glm::dvec3(0.0, 0.0, 1.0));
    return glm::scale(m, glm::dvec3(scale));
}

glm::dvec3 Transform::forward() const {
    return {-std::sin(yaw), 0.0, -std::cos(yaw)};
}

}  // namespace bz::scene
