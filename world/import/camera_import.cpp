#include "world/import/camera_import.hpp"

#include <cmath>

#include <tiny_gltf.h>

#include "shading.hpp"
#include "world/error.hpp"

namespace onelight::world {

glm::quat rotationOf(const glm::dmat4& worldFromLocal) {
    glm::dmat3 basis(worldFromLocal);
    for (int c = 0; c < 3; ++c) {
        const double length = glm::length(basis[c]);
        basis[c] = length > 0.0 && std::isfinite(length) ? basis[c] / length
                                                         : glm::dvec3(c == 0, c == 1, c == 2);
    }
    if (glm::determinant(basis) < 0.0) basis[0] = -basis[0];
    // Orthonormalise (Gram-Schmidt) so quat_cast sees a rotation.
    basis[0] = glm::normalize(basis[0]);
    basis[1] = glm::normalize(basis[1] - basis[0] * glm::dot(basis[0], basis[1]));
    basis[2] = glm::cross(basis[0], basis[1]);
    return glm::normalize(glm::quat(glm::quat_cast(basis)));
}

Camera importCamera(const tinygltf::Camera& source, const glm::dmat4& worldFromLocal,
                    const std::string& name, const std::string& where) {
    Camera camera;
    camera.name = name;
    const auto finite = [&](double v, const char* field) {
        if (!std::isfinite(v)) throw Error(where + ": camera " + field + " is not finite");
        return static_cast<float>(v);
    };
    if (source.type == "orthographic") {
        camera.orthographic = true;
        camera.xmag = finite(source.orthographic.xmag, "xmag");
        camera.ymag = finite(source.orthographic.ymag, "ymag");
        camera.znear = finite(source.orthographic.znear, "znear");
        camera.zfar = finite(source.orthographic.zfar, "zfar");
    } else if (source.type == "perspective") {
        camera.yfov = finite(source.perspective.yfov, "yfov");
        camera.aspectRatio = finite(source.perspective.aspectRatio, "aspectRatio");
        camera.znear = finite(source.perspective.znear, "znear");
        camera.zfar = finite(source.perspective.zfar, "zfar");
        if (!(camera.yfov > 0.0f && camera.yfov < glsl::PI))
            throw Error(where + ": camera yfov " + std::to_string(camera.yfov) +
                        "; expected radians in (0, pi)");
        if (!(camera.znear > 0.0f))
            throw Error(where + ": camera znear " + std::to_string(camera.znear) +
                        "; expected > 0");
    } else {
        throw Error(where + ": camera type \"" + source.type +
                    "\"; expected \"perspective\" or \"orthographic\"");
    }
    camera.position = glm::vec3(glm::dvec3(worldFromLocal[3]));
    camera.rotation = rotationOf(worldFromLocal);
    return camera;
}

}  // namespace onelight::world
