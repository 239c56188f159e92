// A point light's six-face shadow map (scene/light_faces.h): the face a direction from the light
// belongs to is its major axis, in the tiles' order +X -X +Y -Y +Z -Z (light_face_of() on the CPU).
int light_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}
