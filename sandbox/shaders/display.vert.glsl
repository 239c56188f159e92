#version 450 core
// Full-screen triangle (no vertex buffer). uv covers [0, 1] over the viewport and is then mapped
// into uv_rect (xy = origin, zw = extent), so a split view shows the matching part of each image.
uniform vec4 uv_rect;
out vec2 v_uv;

void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = uv_rect.xy + p * uv_rect.zw;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
