#pragma once
// What the device can move, measured once per `penumbra bench` run, so that each pass's
// achieved bandwidth can be set against a peak this device reached rather than a datasheet:
//   copy:  a compute kernel copies one storage buffer into another (16 B per invocation); the
//          bytes read plus the bytes written over the time is the copy peak. On a GPU each
//          buffer is 512 MiB, far beyond any last-level cache; on a software renderer 32 MiB.
//   fetch: a compute kernel texelFetches every texel of an RGBA8 texture (8192² on a GPU,
//          1024² in software) once: texels and bytes per second through the texture path.
// Both inputs are filled with a hash first (never zeros or a clear colour, which compression
// could serve without reading memory). Each kernel runs 3 times to warm up, then 15 times;
// the median is reported.
#include <cstdint>
#include <string>

namespace penumbra::measurement {

struct MemoryPeaks {
  bool measured = false;
  std::string problem;             // why the kernels could not run, when !measured
  std::uint64_t copy_buffer_bytes = 0;
  double copy_gb_per_s = 0.0;      // (read + written) bytes / s / 1e9
  int fetch_width = 0, fetch_height = 0;
  double fetch_gtexels_per_s = 0.0;
  double fetch_gb_per_s = 0.0;
};

// Runs the two kernels in the current GL context. `gpu_timer`: time with GL timestamp queries
// (a hardware GPU); otherwise glFinish + a CPU clock (llvmpipe, where timer queries do not
// measure the work) and the small sizes. Never fails: a kernel that cannot run (no compute,
// out of memory) leaves `measured` false and says why in `problem`.
MemoryPeaks measure_memory_peaks(bool gpu_timer);

// "copy 2912.4 GB/s (2 x 512 MiB buffers), fetch 78.1 Gtexel/s = 312.4 GB/s (RGBA8 8192x8192)"
// or "not measured: ...".
std::string describe_memory_peaks(const MemoryPeaks& peaks);

}  // namespace penumbra::measurement
