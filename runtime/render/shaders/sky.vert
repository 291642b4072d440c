#version 450
// One triangle covering the viewport on the far plane (depth 1): it survives the depth test
// (less or equal) only where the forward pass drew nothing.
layout(location = 0) out vec2 outClip;

void main() {
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    outClip = uv * 2.0 - 1.0;
    gl_Position = vec4(outClip, 1.0, 1.0);
}
