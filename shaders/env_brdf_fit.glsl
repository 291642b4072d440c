// Placeholder until the lab writes the fit (onelight-lab env-fit).
#ifndef ONELIGHT_ENV_BRDF_FIT_GLSL
#define ONELIGHT_ENV_BRDF_FIT_GLSL
#include "brdf.glsl"
vec2 EnvBRDF_Fit(float NoV, float gloss) { return EnvBRDF_BlackOps(NoV, gloss); }
#endif
