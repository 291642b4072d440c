// Punctual light falloff of KHR_lights_punctual, written once for GLSL and C++ (the common
// subset of shaders/common.glsl). The baker includes it through bake/lighting/light_math.hpp;
// the runtime's lighting shader should include the same file so bake and runtime agree.
// Units: intensity in candela (point, spot) or lux (directional); irradiance in lux.
#ifndef ONELIGHT_PUNCTUAL_GLSL
#define ONELIGHT_PUNCTUAL_GLSL

#include "common.glsl"

// KHR_lights_punctual, "Range Property" (recommended window, as in Karis 2013, "Real Shading
// in Unreal Engine 4", eq. 9): saturate(1 - (d / range)^4)^2; range <= 0 means unlimited.
float rangeWindow_KHR(float distance, float range) {
    if (range <= 0.0f) return 1.0f;
    float r = distance / range;
    float r2 = r * r;
    return sq(saturate(1.0f - r2 * r2));
}

// KHR_lights_punctual, "Spot" (the extension's reference implementation): with cd the cosine
// between the spot axis and the direction to the point, t = saturate((cd - cos outer) /
// (cos inner - cos outer)), attenuation t^2. The cone edge (t = 0) is exactly the outer angle.
float spotCone_KHR(float cd, float cosOuter, float cosInner) {
    float t = saturate((cd - cosOuter) / max(cosInner - cosOuter, 1e-4f));
    return t * t;
}

// Irradiance (lux) at normal incidence at distance d from a point or spot light of intensity
// I candela: the inverse-square law E = I / d^2, with d floored at minDistance (the light's
// radius: inside its sphere the irradiance stops growing), times the range window.
float pointIrradiance_InverseSquare(float intensity, float distance, float range,
                                    float minDistance) {
    float d = max(distance, minDistance);
    return intensity * rangeWindow_KHR(distance, range) / (d * d);
}

#endif
