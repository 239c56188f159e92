#version 450 core
// The extended shadow map's depth pass (Bujnak, section 4: "rendering a depth map of the scene
// from the light point of view proceeds as in conventional shadow maps"), one face at a time.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_light_view_proj;  // the face's
out vec2 v_uv;
out vec4 v_clip;
void main() {
  v_uv = a_uv;
  v_clip = u_light_view_proj * (u_model * vec4(a_position, 1.0));
  gl_Position = v_clip;
}
