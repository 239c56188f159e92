// Taps of one separable pass (section 2: "pre-computed 1D separable Gaussian weights"; Pham and
// van Vliet 2005 apply the bilateral filter one axis at a time).
//
// Kernel: a Gaussian of sigma = W / 4 pixels for a kernel of diameter W (the variance of a
// uniform disk of diameter W, so it blurs an edge as much as PCSS's disk kernel), truncated at
// 3 sigma. Cost: the pass takes at most u_taps taps whatever W is. While the 6 sigma span holds
// at most u_taps pixels every pixel of it is a tap; a wider span is cut into u_taps equal strata
// with one tap each at a jittered position (interleaved gradient noise per pixel and pass), so a
// 32-pixel radius costs what an 8-pixel one does, and the second axis averages the first axis's
// jitter away instead of leaving a staircase of stride-wide steps.
uniform int u_taps;  // taps of this pass

struct AxisTaps {
  int count;
  float first;   // offset of tap 0, pixels
  float stride;  // pixels between taps
};

AxisTaps axis_taps(float width_px, float jitter) {
  float span = 0.75 * width_px;  // 3 sigma
  int whole = int(floor(span));
  AxisTaps t;
  if (2 * whole + 1 <= u_taps) {
    t.count = 2 * whole + 1;
    t.first = -float(whole);
    t.stride = 1.0;
  } else {
    t.count = u_taps;
    t.stride = 2.0 * span / float(u_taps);
    t.first = -span + jitter * t.stride;
  }
  return t;
}

// Offset of tap i along the axis, whole pixels.
int tap_offset(AxisTaps t, int i) { return int(round(t.first + float(i) * t.stride)); }

// Domain weight of a tap `offset` pixels from the centre of a kernel of diameter width_px.
float gaussian_weight(int offset, float width_px) {
  float sigma = 0.25 * width_px;
  float x = float(offset) / sigma;
  return exp(-0.5 * x * x);
}
