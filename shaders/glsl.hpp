// GLSL vocabulary for C++: the thin shim that lets shaders/*.glsl compile as C++ with GLM.
// Only what the shared files use lives here; the scalar overloads mirror GLSL's genType
// functions so that, e.g., max(x, 0.0f) reads and rounds the same in both languages.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace onelight::glsl {

// clang-format off: a table of one-line definitions reads best as a table

using glm::ivec2;
using glm::ivec4;
using glm::mat4;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = unsigned int;

[[nodiscard]] inline float abs(float x) {
    return std::fabs(x);
}
[[nodiscard]] inline float min(float a, float b) {
    return b < a ? b : a;
}
[[nodiscard]] inline float max(float a, float b) {
    return a < b ? b : a;
}
[[nodiscard]] inline int min(int a, int b) {
    return b < a ? b : a;
}
[[nodiscard]] inline int max(int a, int b) {
    return a < b ? b : a;
}
[[nodiscard]] inline float clamp(float x, float lo, float hi) {
    return min(max(x, lo), hi);
}
[[nodiscard]] inline int clamp(int x, int lo, int hi) {
    return min(max(x, lo), hi);
}
[[nodiscard]] inline float mix(float a, float b, float t) {
    return a * (1.0f - t) + b * t;
}
[[nodiscard]] inline float sqrt(float x) {
    return std::sqrt(x);
}
[[nodiscard]] inline float inversesqrt(float x) {
    return 1.0f / std::sqrt(x);
}
[[nodiscard]] inline float exp(float x) {
    return std::exp(x);
}
[[nodiscard]] inline float exp2(float x) {
    return std::exp2(x);
}
[[nodiscard]] inline float log(float x) {
    return std::log(x);
}
[[nodiscard]] inline float log2(float x) {
    return std::log2(x);
}
[[nodiscard]] inline float pow(float x, float y) {
    return std::pow(x, y);
}
[[nodiscard]] inline float floor(float x) {
    return std::floor(x);
}
[[nodiscard]] inline float atan(float y, float x) {
    return std::atan2(y, x);
}
[[nodiscard]] inline float atan(float x) {
    return std::atan(x);
}
[[nodiscard]] inline float acos(float x) {
    return std::acos(x);
}
[[nodiscard]] inline float sin(float x) {
    return std::sin(x);
}
[[nodiscard]] inline float cos(float x) {
    return std::cos(x);
}
[[nodiscard]] inline float fract(float x) {
    return x - std::floor(x);
}
[[nodiscard]] inline float step(float edge, float x) {
    return x < edge ? 0.0f : 1.0f;
}
[[nodiscard]] inline float sign(float x) {
    return float(x > 0.0f) - float(x < 0.0f);
}
[[nodiscard]] inline bool isnan(float x) {
    return std::isnan(x);
}
[[nodiscard]] inline bool isinf(float x) {
    return std::isinf(x);
}

// clang-format on

}  // namespace onelight::glsl
