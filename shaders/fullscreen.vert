#version 450
// One oversized triangle covering the screen at the far plane (depth 1): drawn last with the depth test, it fills
// only the pixels nothing else covered. The fragment shader reconstructs view rays from it.
layout(location = 0) out vec2 ndc;
void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  ndc = p * 2.0 - 1.0;
  gl_Position = vec4(ndc, 1.0, 1.0);
}
