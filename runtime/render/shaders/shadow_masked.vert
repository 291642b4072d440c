#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow pass of alpha-masked casters: depth, and the base colour's uv for the coverage test.
#include "gpu_interface.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 3) in vec2 inUv0;
layout(push_constant) uniform MaskedShadowBlock { MaskedShadowPush push; };
layout(location = 0) out vec2 outUv0;
void main() {
    outUv0 = inUv0;
    gl_Position = push.clipFromObject * vec4(inPosition, 1.0);
}
