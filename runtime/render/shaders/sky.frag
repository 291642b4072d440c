#version 450
#extension GL_GOOGLE_include_directive : require
// The sky behind the level: the sky image along the pixel's view direction (shaders/sky.glsl's
// mapping, as the baker lights with it), times its scale, pre-exposed like every radiance.
#include "frame_interface.glsl"
#include "sky.glsl"

layout(location = 0) in vec2 inClip;
layout(location = 0) out vec4 outColor;

void main() {
    vec4 d = frame.skyFromClip * vec4(inClip, 1.0f, 1.0f);
    vec3 direction = normalize(d.xyz / d.w);
    // Level 0: the derivatives of u jump across the image's seam (u = 0 | 1), and a mip chosen
    // from them would draw a line of the smallest mip there.
    vec3 radiance = textureLod(skyImage, equirectUv_fromDirection(direction), 0.0f).rgb;
    outColor = vec4(min(radiance * frame.sky.rgb * frame.cameraPosition.w, vec3(HDR_MAX)), 1.0f);
}
