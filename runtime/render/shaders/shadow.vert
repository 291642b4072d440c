#version 450
// Shadow pass: depth only.
layout(location = 0) in vec3 inPosition;
layout(push_constant) uniform ShadowPush { mat4 clipFromObject; } push;
void main() { gl_Position = push.clipFromObject * vec4(inPosition, 1.0); }
