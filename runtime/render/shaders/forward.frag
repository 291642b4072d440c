#version 450
#extension GL_GOOGLE_include_directive : require
// The forward pass of opaque and blended materials: the depth test before the shader, always (a
// fragment behind what is drawn is never shaded; llvmpipe otherwise tests after it, and a map's
// overdraw is shaded whole). Nothing here discards or writes depth, so the test is the same.
layout(early_fragment_tests) in;
#include "forward_shading.glsl"
