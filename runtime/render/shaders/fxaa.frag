#version 450
#extension GL_GOOGLE_include_directive : require
// Post-process anti-aliasing of the tonemapped frame, FXAA's "PC" variant (Lottes 2009,
// "FXAA", NVIDIA white paper; the console variant of FXAA 3.11 is the same idea): where the
// luma of the pixel's four diagonal neighbours (bilinear taps half a pixel off) spans more than
// a threshold, blur along the edge, perpendicular to the luma gradient, with two or four taps,
// and keep the four-tap blur only while its luma stays within the neighbours'. The frame is
// display-encoded (sRGB), as FXAA expects.
#include "gpu_interface.glsl"

layout(set = 0, binding = BINDING_FXAA_INPUT) uniform sampler2D frame;  // tonemapped, bilinear

layout(location = 0) out vec4 outColor;

const float FXAA_EDGE_THRESHOLD = 1.0 / 8.0;       // of the local luma's maximum
const float FXAA_EDGE_THRESHOLD_MIN = 1.0 / 16.0;  // below it, dark noise is no edge
const float FXAA_REDUCE_MUL = 1.0 / 8.0;
const float FXAA_REDUCE_MIN = 1.0 / 128.0;
const float FXAA_SPAN_MAX = 8.0;  // pixels

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main() {
    vec2 texel = 1.0 / vec2(textureSize(frame, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec3 rgbM = texture(frame, uv).rgb;
    float lumaNW = luma(texture(frame, uv + vec2(-0.5, -0.5) * texel).rgb);
    float lumaNE = luma(texture(frame, uv + vec2(0.5, -0.5) * texel).rgb);
    float lumaSW = luma(texture(frame, uv + vec2(-0.5, 0.5) * texel).rgb);
    float lumaSE = luma(texture(frame, uv + vec2(0.5, 0.5) * texel).rgb);
    float lumaM = luma(rgbM);
    float lumaMin = min(lumaM, min(min(lumaNW, lumaNE), min(lumaSW, lumaSE)));
    float lumaMax = max(lumaM, max(max(lumaNW, lumaNE), max(lumaSW, lumaSE)));
    if (lumaMax - lumaMin < max(FXAA_EDGE_THRESHOLD_MIN, lumaMax * FXAA_EDGE_THRESHOLD)) {
        outColor = vec4(rgbM, 1.0);
        return;
    }
    vec2 dir = vec2(-((lumaNW + lumaNE) - (lumaSW + lumaSE)), (lumaNW + lumaSW) - (lumaNE + lumaSE));
    float dirReduce = max((lumaNW + lumaNE + lumaSW + lumaSE) * (0.25 * FXAA_REDUCE_MUL), FXAA_REDUCE_MIN);
    float rcpDirMin = 1.0 / (min(abs(dir.x), abs(dir.y)) + dirReduce);
    dir = clamp(dir * rcpDirMin, vec2(-FXAA_SPAN_MAX), vec2(FXAA_SPAN_MAX)) * texel;
    vec3 rgbA = 0.5 * (texture(frame, uv + dir * (1.0 / 3.0 - 0.5)).rgb +
                       texture(frame, uv + dir * (2.0 / 3.0 - 0.5)).rgb);
    vec3 rgbB = rgbA * 0.5 + 0.25 * (texture(frame, uv - dir * 0.5).rgb +
                                     texture(frame, uv + dir * 0.5).rgb);
    float lumaB = luma(rgbB);
    outColor = vec4(lumaB < lumaMin || lumaB > lumaMax ? rgbA : rgbB, 1.0);
}
