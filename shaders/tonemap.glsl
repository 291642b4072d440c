// Exposure, the filmic curve and display encoding, written once for GLSL and C++. The runtime
// folds filmic + sRGB encoding into a 3D colour LUT indexed through a log2 shaper; C++ builds
// the LUT from these functions, and the forward shader applies the exposure ("pre-exposure").
#ifndef ONELIGHT_TONEMAP_GLSL
#define ONELIGHT_TONEMAP_GLSL

#include "common.glsl"

// Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", sec. 5.1 (saturation-based speed,
// lens attenuation 0.65): Lmax = 1.2 * 2^EV100, exposure = 1 / Lmax.
float exposure_fromEV100(float ev100) { return 1.0f / (1.2f * exp2(ev100)); }

// ISO 2720 incident-light meter with a flat sensor (C = 250): EV100 = log2(E * 100 / 250), E in
// lux. The automatic exposure of a level that states none.
float ev100_fromIlluminance(float lux) { return log2(max(lux, 1e-6f) * 0.4f); }

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": the ACES RRT+ODT fit
// (x (2.51 x + 0.03)) / (x (2.43 x + 0.59) + 0.14), per channel, saturated.
float filmic_ACES(float x) {
    float v = max(x, 0.0f);
    return saturate((v * (2.51f * v + 0.03f)) / (v * (2.43f * v + 0.59f) + 0.14f));
}

// IEC 61966-2-1 (sRGB) encoding of a linear value in [0, 1].
float srgbEncode(float linear) {
    float x = saturate(linear);
    if (x <= 0.0031308f) return 12.92f * x;
    return 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

// IEC 61966-2-1 (sRGB) decoding of a code in [0, 1], as the _SRGB formats do it.
float srgbDecode(float code) {
    float x = saturate(code);
    if (x <= 0.04045f) return x / 12.92f;
    return pow((x + 0.055f) / 1.055f, 2.4f);
}

// The colour LUT's shaper: exposed linear colour x maps to a coordinate in [0, 1] over
// [2^LUT_LOG2_MIN, 2^LUT_LOG2_MAX] (filmic_ACES is within 0.1% of its top at 2^4).
const float LUT_LOG2_MIN = -12.0f;
const float LUT_LOG2_MAX = 4.0f;

float lutCoordinate_fromLinear(float x) {
    return saturate((log2(max(x, 1e-12f)) - LUT_LOG2_MIN) / (LUT_LOG2_MAX - LUT_LOG2_MIN));
}

// Inverse of the shaper, for the LUT's texel centres.
float linear_fromLutCoordinate(float u) { return exp2(LUT_LOG2_MIN + u * (LUT_LOG2_MAX - LUT_LOG2_MIN)); }

// What one LUT texel stores for one channel: the display-encoded filmic value.
float displayValue(float exposedLinear) { return srgbEncode(filmic_ACES(exposedLinear)); }

#endif
