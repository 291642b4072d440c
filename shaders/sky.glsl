// The sky image's equirectangular (latitude-longitude) mapping, the one convention of the
// baker, the reference and the runtime's background. glTF's +Y is up; the image's top row is
// the zenith, its centre looks along +X and u grows from +X towards +Z:
//   u = 1/2 + atan(z, x) / (2 pi),   v = acos(y) / pi
// (the usual latitude-longitude convention of real-time engines with +Y up).
// A texel (i, j) of a W x H image covers the solid angle (2 pi / W) (cos t0 - cos t1),
// t0 = pi i / H and t1 = pi (i + 1) / H: dw = 2 pi^2 sin(theta) du dv.
#ifndef ONELIGHT_SKY_GLSL
#define ONELIGHT_SKY_GLSL

#include "common.glsl"

// (u, v) in [0, 1]^2 of a unit direction; u is 1/2 straight up or down (where atan(0, 0)
// is undefined).
vec2 equirectUv_fromDirection(vec3 d) {
    float u = (d.x == 0.0f && d.z == 0.0f) ? 0.5f : 0.5f + atan(d.z, d.x) * (0.5f * INV_PI);
    return vec2(u, acos(clamp(d.y, -1.0f, 1.0f)) * INV_PI);
}

// The unit direction at (u, v).
vec3 direction_fromEquirectUv(vec2 uv) {
    float phi = (uv.x - 0.5f) * (2.0f * PI);
    float theta = uv.y * PI;
    float s = sin(theta);
    return vec3(s * cos(phi), cos(theta), s * sin(phi));
}

#endif
