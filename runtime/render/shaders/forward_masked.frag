#version 450
#extension GL_GOOGLE_include_directive : require
// The forward pass of alpha-masked materials: the shader may discard, so the depth test (and
// write) waits for it.
#include "forward_shading.glsl"
