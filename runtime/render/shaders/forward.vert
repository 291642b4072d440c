#version 450
#extension GL_GOOGLE_include_directive : require
// Forward pass vertex stage: world-space position, normal, tangent and both UV sets.
#include "frame_interface.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;

// The depth pre-pass draws with this shader alone: its depth must be the forward pass's exactly.
invariant gl_Position;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec4 outTangent;
layout(location = 3) out vec2 outUv0;
layout(location = 4) out vec2 outUv1;

void main() {
    vec4 world = draw.model * vec4(inPosition, 1.0);
    mat3 normalMatrix = transpose(inverse(mat3(draw.model)));
    outWorldPosition = world.xyz;
    outNormal = normalMatrix * inNormal;
    outTangent = vec4(mat3(draw.model) * inTangent.xyz, inTangent.w);
    outUv0 = inUv0;
    outUv1 = inUv1;
    gl_Position = frame.viewProj * world;
}
