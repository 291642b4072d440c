// Evaluates every BRDF piece of shaders/brdf_pieces.glsl for every input: output[i * COUNT + p]
// is brdfPiece(p, inputs[i].dots, inputs[i].params). The C++ side of the test does the same.
#version 450
#extension GL_GOOGLE_include_directive : require

#include "brdf_pieces.glsl"

layout(local_size_x = 64) in;

struct PieceInput {
    vec4 dots;    // NoV, NoL, LoH, NxH2
    vec4 params;  // gloss, f0, unused, unused
};

layout(std430, set = 0, binding = 0) readonly buffer Inputs { PieceInput inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Outputs { float outputs[]; };
layout(push_constant) uniform Push { uint inputCount; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.inputCount) return;
    vec4 dots = inputs[i].dots;
    vec4 params = inputs[i].params;
    for (int piece = 0; piece < BRDF_PIECE_COUNT; ++piece)
        outputs[i * uint(BRDF_PIECE_COUNT) + uint(piece)] = brdfPiece(piece, dots, params);
}
