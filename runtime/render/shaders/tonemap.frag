#version 450
#extension GL_GOOGLE_include_directive : require
// Tonemap: the pre-exposed HDR colour through the colour LUT (filmic curve + sRGB encoding,
// built on the CPU from shaders/tonemap.glsl) indexed by its log2 shaper.
#include "gpu_interface.glsl"
#include "tonemap.glsl"

layout(set = 0, binding = BINDING_TONEMAP_HDR) uniform sampler2D hdr;  // resolved, pre-exposed
layout(set = 0, binding = BINDING_TONEMAP_LUT) uniform sampler3D lut;  // display-encoded colour

layout(location = 0) out vec4 outColor;

void main() {
    vec3 c = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 u = vec3(lutCoordinate_fromLinear(c.r), lutCoordinate_fromLinear(c.g),
                  lutCoordinate_fromLinear(c.b));
    float size = float(textureSize(lut, 0).x);
    vec3 coord = u * ((size - 1.0) / size) + 0.5 / size;
    outColor = vec4(texture(lut, coord).rgb, 1.0);
}
