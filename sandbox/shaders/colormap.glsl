// Colour maps of the sandbox's display pass. `t` is already normalised to [0, 1].
// heat: black -> blue -> green -> red -> white at 0, 0.25, 0.5, 0.75, 1, the same stops as
// engine/metrics/heat_map.h, so the live error view matches the CLI's PNG heat maps.
// signed: blue (t = 0) -> white (0.5) -> red (1), the stops of diverging_color() in
// sandbox/view_mapping.h, which draws the legend.
vec3 diverging_color(float t) {
  t = clamp(t, 0.0, 1.0);
  const vec3 under = vec3(0.15, 0.35, 0.95), middle = vec3(1.0), over = vec3(0.95, 0.2, 0.15);
  return t < 0.5 ? mix(under, middle, t * 2.0) : mix(middle, over, t * 2.0 - 1.0);
}

vec3 heat_color(float t) {
  t = clamp(t, 0.0, 1.0);
  const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0),
                                vec3(1.0, 0.0, 0.0), vec3(1.0));
  float x = t * 4.0;
  int i = min(int(floor(x)), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}
