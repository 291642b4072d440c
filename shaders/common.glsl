// Constants and helpers shared by every shader and by C++ (through glsl.hpp).
// Written in the common subset of GLSL 4.50 and C++20 with GLM: float literals carry an `f`
// so both sides compute in single precision; no swizzles, no in/out parameters, no
// constructors of structs.
#ifndef ONELIGHT_COMMON_GLSL
#define ONELIGHT_COMMON_GLSL

// The one definition of pi for the shaders and every single-precision C++ use (glsl::PI). C++ in
// double precision uses std::numbers::pi, of which PI is the float rounding (the common subset
// has no doubles).
const float PI = 3.14159265358979f;
const float INV_PI = 0.318309886183791f;

float saturate(float x) { return clamp(x, 0.0f, 1.0f); }
vec3 saturate(vec3 x) { return clamp(x, vec3(0.0f), vec3(1.0f)); }
float sq(float x) { return x * x; }
float pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

// Rec. 709 luminance of linear RGB (ITU-R BT.709-6, item 3.2).
float luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// 1 - x^2 for x in [0, 1] without cancellation: 1 - x is exact for x >= 0.5 (Sterbenz).
float oneMinusSq(float x) { return (1.0f - x) * (1.0f + x); }

// ln(1 - x) for x in [0, 1], accurate where x is tiny (log1p is not GLSL): below 1/16 the series
// -(x + x^2/2 + x^3/3 + x^4/4 + x^5/5) errs by < x^6/6 < 1e-8; above, 1 - x has no cancellation.
float log1m(float x) {
    if (x < 0.0625f) return -x * (1.0f + x * (0.5f + x * (0.333333333f + x * (0.25f + x * 0.2f))));
    return log(1.0f - x);
}

// 2^x - 1 for x >= 0, accurate where x is tiny (expm1 is not GLSL): below 1/16, with y = x ln 2,
// the series y (1 + y/2 + y^2/6 + y^3/24 + y^4/120) errs by < y^6/720 relative < 1e-10;
// above, 2^x - 1 >= 0.044 has no harmful cancellation.
float exp2m1(float x) {
    if (x < 0.0625f) {
        float y = x * 0.693147181f;
        return y * (1.0f + y * (0.5f + y * (0.166666667f + y * (0.0416666667f + y * 0.00833333333f))));
    }
    return exp2(x) - 1.0f;
}

#endif
