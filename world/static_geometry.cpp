#include "world/static_geometry.hpp"

#include <cmath>

namespace onelight::world {

CompileVertex interpolate(const CompileVertex& a, const CompileVertex& b, double t) {
    CompileVertex out;
    const float tf = static_cast<float>(t);
    out.position = a.position + (b.position - a.position) * t;
    out.uv0 = glm::mix(a.uv0, b.uv0, tf);
    out.uv1 = glm::mix(a.uv1, b.uv1, tf);
    const glm::vec3 n = glm::mix(a.normal, b.normal, tf);
    const float nLength = glm::length(n);
    out.normal = nLength > 1e-6f ? n / nLength : a.normal;
    const glm::vec3 tangent = glm::mix(glm::vec3(a.tangent), glm::vec3(b.tangent), tf);
    const float tLength = glm::length(tangent);
    out.tangent =
        glm::vec4(tLength > 1e-6f ? tangent / tLength : glm::vec3(a.tangent), a.tangent.w);
    return out;
}

glm::dvec3 areaVector(const StaticGeometry& geometry, const StaticTriangle& triangle) {
    const glm::dvec3& a = geometry.vertices[triangle.v[0]].position;
    const glm::dvec3& b = geometry.vertices[triangle.v[1]].position;
    const glm::dvec3& c = geometry.vertices[triangle.v[2]].position;
    return glm::cross(b - a, c - a);
}

double triangleArea(const StaticGeometry& geometry, const StaticTriangle& triangle) {
    return 0.5 * glm::length(areaVector(geometry, triangle));
}

double totalArea(const StaticGeometry& geometry) {
    double sum = 0.0, compensation = 0.0;
    for (const StaticTriangle& t : geometry.triangles) {
        const double y = triangleArea(geometry, t) - compensation;
        const double s = sum + y;
        compensation = (s - sum) - y;
        sum = s;
    }
    return sum;
}

}  // namespace onelight::world
