#pragma once
// The Gaussian kernels of the multi-pass alteration (Cherry & Kooima, section 3.1), on the CPU:
// per pass a kernel size KS, the taps (pixel offsets and normalised Gaussian weights) the blur
// shader loops over, and the variance they add, which the `physical` mapping inverts to turn a
// penumbra width into a number of passes.
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::mpg {

// One tap: offset from the pixel centre in pixels (sampled bilinearly), normalised weight.
struct Tap {
  glm::vec2 offset{0.0f};
  float weight = 0.0f;
};

enum class KernelSampling { poisson, dense };

// The precomputed 2D Poisson disk of section 3.1: 64 points in [-1, 1]^2, the first fixed at the
// origin "so the center texel is always examined", the rest a best-candidate sequence
// (passes/sampling/poisson_disk.h) whose every prefix is well spread, as taking "the first N"
// needs. Generated once, from a fixed seed.
inline constexpr int kMaxPoissonPoints = 64;
const std::vector<glm::vec2>& poisson_points();

// Kernel size (pixels, odd) of blur pass `iteration` (0-based). Fixed: max_kernel every pass.
// Progressive: 3x3 on the first pass, two pixels wider each pass (one each side) up to
// max_kernel (section 3.1; Figure 5G: 3x3 up to 19x19 in 10 passes).
int pass_kernel_size(bool progressive, int iteration, int max_kernel);

// Gaussian weight of an offset for a kernel of `size` pixels: sigma = size / 3 (section 1, the
// "3-sigma rule"), unnormalised.
float gaussian_weight(glm::vec2 offset_px, int size);

// Poisson: the first `count` points of poisson_points() (1..64), scaled by (size - 1) / 2 pixels
// so that [-1, 1] spans the kernel's outer texel centres (Figure 6A: size 3, points -1..+1),
// with normalised Gaussian weights, and turned by `iteration` times the golden angle: ten passes
// of one unturned set repeat its gaps, and their sum is no Gaussian (not in the paper; ball at
// 768x768, penumbra RMSE 0.051 -> 0.032). Dense: every texel of the size x size kernel, the "entire
// Gaussian" of Figure 7 (size^2 taps), weights normalised the same way.
std::vector<Tap> kernel_taps(KernelSampling sampling, int count, int size, int iteration = 0);

// Variance along one axis, averaged over x and y (pixels^2), of what one blur with these taps
// does to an image: the taps' weighted spread about their weighted mean plus the spread that
// bilinear filtering adds at a fractional offset f (f (1 - f) per axis).
double kernel_variance(const std::vector<Tap>& taps);

// Cumulative per-axis variance after n = 0..max_passes full blur passes (element n).
std::vector<float> cumulative_pass_variance(KernelSampling sampling, int count, bool progressive,
                                            int max_kernel, int max_passes);

}  // namespace penumbra::mpg
