// The kernel shape a pass-2 pixel wrote (kernel_shape.glsl): (A11, A12, dz/dx, dz/dy), with
// A = [A11 A12; A12 A22] symmetric, det 1, so A22 = (1 + A12^2) / A11.
vec3 decode_shape(vec4 k) { return vec3(k.x, k.y, (1.0 + k.y * k.y) / k.x); }

// Maps an offset on the round unit kernel to pixels through A = [a.x a.y; a.y a.z].
vec2 shape_offset(vec3 a, vec2 o) { return vec2(a.x * o.x + a.y * o.y, a.y * o.x + a.z * o.y); }
