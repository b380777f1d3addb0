#version 450
// One oversized triangle covering the screen; the fragment shader reconstructs view rays from it.
layout(location = 0) out vec2 ndc;
void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  ndc = p * 2.0 - 1.0;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
