#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow pass of alpha-masked casters: a texel the forward pass would discard (base colour alpha
// below the material's cutoff, as forward.frag tests it) casts no shadow either, so that a grate
// casts its holes near the camera as the baked shadow mask does beyond.
#include "gpu_interface.glsl"
layout(set = 0, binding = TEXTURE_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(push_constant) uniform MaskedShadowBlock { MaskedShadowPush push; };
layout(location = 0) in vec2 inUv0;
void main() {
    if (push.alpha.x * texture(baseColorTexture, inUv0).a < push.alpha.y) discard;
}
