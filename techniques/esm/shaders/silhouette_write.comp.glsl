#version 450 core
// The listed silhouettes written into the map without the raster (silhouette_finding = compute),
// each texel through the raster's own texel test (silhouette_edge.glsl). Overlapping quads meet
// in image atomics: MAX of the bit patterns of the two channels, which for their non-negative
// values is the MAX blending of the raster path (esm_common.glsl), so the map is the same. On the
// GPUs we measure the raster units are few and most silhouette quads of a detailed mesh cover a
// few dozen texels: their fragments and blending, not the texels, were the cost
// (docs/results/esm.md).
//
// The quad is a rectangle in the tile's texel space: across the edge from -BAND_IN to BAND_OUT,
// along it from BAND_OUT before its first end to BAND_OUT past its second (the caps). A work
// group walks it column by column along the edge's major axis, where a column crosses the band
// over at most (BAND_IN + BAND_OUT + 2 QUAD_MARGIN) sqrt 2 = 5.6 texels: 6 texel centres, so
// eight threads a column and four columns at a time (a chunk).
//
// Two dispatches, because quads differ a thousandfold in length (a sub-texel edge of a detailed
// mesh, a fence picket across the whole map) and one work group walking a long quad alone left
// the GPU idle (fence at 2048^2: 0.31 ms for ~100 silhouettes):
//   LIST_CHUNKS  one work group per listed silhouette (indirect, counted by the finding pass):
//                a quad of at most DIRECT_CHUNKS chunks is written there; a longer one appends
//                its chunks to the chunk list, and the last group to finish sets the dispatch
//                of the second pass. Chunks beyond the list's capacity are written in place.
//   (default)    one work group per listed chunk.
layout(local_size_x = 32) in;
#include "esm_common.glsl"
#include "esm_views.glsl"
#include "silhouette_records.glsl"
#include "silhouette_edge.glsl"
layout(r32ui, binding = 0) uniform uimage2D u_edge_bits;        // the edge channel's R32F storage
layout(r32ui, binding = 1) uniform uimage2D u_edge_depth_bits;  // the edge depth's
layout(r32ui, binding = 2) uniform uimage2D u_edge_near_bits;   // the nearest edge's
layout(std430, binding = SILHOUETTE_CHUNKS_BINDING) buffer SilhouetteChunks {
  uint chunk_count;     // appended (may pass the capacity: those were written in place)
  uint groups_done;     // first-pass groups finished
  uint chunk_groups;    // glDispatchComputeIndirect of the second pass: x, y, z
  uint chunk_groups_y;
  uint chunk_groups_z;
  uint chunk_capacity;  // entries the list holds (at most the GL's largest dispatch)
  uint unused0, unused1;
  uvec2 chunks[];       // (list entry, first column)
};
const int ROWS = 8, COLUMNS = 4;
const int DIRECT_CHUNKS = 2;

// Bounds [lo, hi] on t where lo <= base + slope t <= hi holds (the whole line when slope is 0 and
// base lies within, none when outside).
vec2 slab(float base, float slope, float lo, float hi) {
  if (abs(slope) < 1e-6) return base >= lo && base <= hi ? vec2(-1e30, 1e30) : vec2(1e30, -1e30);
  vec2 t = (vec2(lo, hi) - base) / slope;
  return vec2(min(t.x, t.y), max(t.x, t.y));
}

// The quad in (major, minor) coordinates, xy or yx, and its columns within the tile.
struct QuadFrame {
  bool swap;
  vec2 end0, dir, out_dir;  // first end, along and outwards, swizzled
  vec2 u_range, v_range;    // along the edge from end0, across it outwards (texels)
  int first, last;          // columns (major texel indices) it reaches in the tile; none if last < first
};

// Clamped as floats first: an edge clipped at the near plane can reach far beyond the tile.
int texel_at_or_after(float x, int tile) { return max(int(ceil(clamp(x - 0.5, -1.0, float(tile)))), 0); }
int texel_at_or_before(float x, int tile) { return min(int(floor(clamp(x - 0.5, -1.0, float(tile)))), tile - 1); }

QuadFrame quad_frame(QuadEdge q) {
  QuadFrame f;
  vec2 along = normalize(q.end1 - q.end0);
  f.swap = abs(along.y) > abs(along.x);
  f.end0 = f.swap ? q.end0.yx : q.end0;
  f.dir = f.swap ? along.yx : along;
  f.out_dir = f.swap ? q.outward.yx : q.outward;
  f.u_range = vec2(-BAND_OUT - QUAD_MARGIN, length(q.end1 - q.end0) + BAND_OUT + QUAD_MARGIN);
  f.v_range = vec2(-BAND_IN - QUAD_MARGIN, BAND_OUT + QUAD_MARGIN);
  float c0 = f.end0.x + f.dir.x * f.u_range.x, c1 = f.end0.x + f.dir.x * f.u_range.y;
  float w0 = f.out_dir.x * f.v_range.x, w1 = f.out_dir.x * f.v_range.y;
  int tile = int(u_tile_size);
  f.first = texel_at_or_after(min(c0, c1) + min(w0, w1), tile);
  f.last = texel_at_or_before(max(c0, c1) + max(w0, w1), tile);
  return f;
}

// This thread's texels of columns from .. to (four at a time over the group).
void write_columns(QuadEdge q, QuadFrame f, int from, int to) {
  int tile = int(u_tile_size);
  int column = int(gl_LocalInvocationIndex) / ROWS, row = int(gl_LocalInvocationIndex) % ROWS;
  for (int a = from + column; a <= to; a += COLUMNS) {
    // Where the line major = a + 0.5 crosses the rectangle, as an interval of the minor axis.
    float rel = float(a) + 0.5 - f.end0.x;
    vec2 by_u = slab(rel * f.dir.x, f.dir.y, f.u_range.x, f.u_range.y);
    vec2 by_v = slab(rel * f.out_dir.x, f.out_dir.y, f.v_range.x, f.v_range.y);
    int b_first = texel_at_or_after(max(by_u.x, by_v.x) + f.end0.y, tile);
    int b_last = texel_at_or_before(min(by_u.y, by_v.y) + f.end0.y, tile);
    for (int b = b_first + row; b <= b_last; b += ROWS) {
      ivec2 t = f.swap ? ivec2(b, a) : ivec2(a, b);
      ivec2 map_texel = ivec2(u_tile_origin) + t;
      vec3 value;
      if (!silhouette_texel(q, vec2(t) + 0.5, map_texel, value)) continue;
      imageAtomicMax(u_edge_bits, map_texel, floatBitsToUint(value.x));
      imageAtomicMax(u_edge_depth_bits, map_texel, floatBitsToUint(max(value.y, 0.0)));
      imageAtomicMax(u_edge_near_bits, map_texel, floatBitsToUint(value.z));
    }
  }
}

#ifdef LIST_CHUNKS
shared uint group_base;

void main() {
  uvec2 listed = silhouettes[gl_WorkGroupID.x];
  ProjectedSilhouette s;
  bool visible = project_silhouette(listed.x, listed.y, s);  // the same in every thread
  QuadFrame f = quad_frame(s.edge);
  int chunk_total = visible && f.last >= f.first ? (f.last - f.first) / COLUMNS + 1 : 0;
  if (chunk_total <= DIRECT_CHUNKS) {
    if (chunk_total > 0) write_columns(s.edge, f, f.first, f.last);
  } else {
    if (gl_LocalInvocationIndex == 0u) group_base = atomicAdd(chunk_count, uint(chunk_total));
    barrier();
    int stored = clamp(int(chunk_capacity) - int(group_base), 0, chunk_total);
    for (int k = int(gl_LocalInvocationIndex); k < stored; k += int(gl_WorkGroupSize.x))
      chunks[group_base + uint(k)] = uvec2(gl_WorkGroupID.x, uint(f.first + k * COLUMNS));
    if (stored < chunk_total) write_columns(s.edge, f, f.first + stored * COLUMNS, f.last);
  }
  // The last group to finish knows every chunk: it sets the second pass's dispatch.
  memoryBarrierBuffer();
  barrier();
  if (gl_LocalInvocationIndex == 0u && atomicAdd(groups_done, 1u) == gl_NumWorkGroups.x - 1u)
    chunk_groups = min(atomicAdd(chunk_count, 0u), chunk_capacity);
}
#else
void main() {
  uvec2 chunk = chunks[gl_WorkGroupID.x];
  uvec2 listed = silhouettes[chunk.x];
  ProjectedSilhouette s;
  if (!project_silhouette(listed.x, listed.y, s)) return;
  QuadFrame f = quad_frame(s.edge);
  write_columns(s.edge, f, int(chunk.y), min(int(chunk.y) + COLUMNS - 1, f.last));
}
#endif
