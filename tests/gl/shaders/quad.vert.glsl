#version 450 core
// Two triangles covering x in [-1, 0] at NDC depth -0.5 (window depth 0.25).
void main() {
  const vec2 c[6] = vec2[](vec2(-1, -1), vec2(0, -1), vec2(0, 1), vec2(-1, -1), vec2(0, 1), vec2(-1, 1));
  gl_Position = vec4(c[gl_VertexID], -0.5, 1.0);
}
