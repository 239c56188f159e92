// Stage: index resources. Names become indices once, and every texture's size is resolved
// from the compile settings (screen, shadow) and, for `screen/$param`, the parameter's value.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

std::string where_of(const ResourceDecl& r) {
  return r.location.empty() ? "resource '" + r.name + "'" : r.location;
}

// The divisor a size expression divides by; reports a reference that cannot be one (it must
// be a structural int parameter whose whole range is a valid divisor, so every value a user
// can set compiles).
int divisor_of(CompileState& s, const ResourceDecl& r) {
  const std::string key = r.tile_list || r.per_tile ? "/tiles" : "/size";
  const std::string& name = r.size.divisor_reference;
  if (name.empty()) return r.size.divisor;
  const std::string who = "resource '" + r.name + "': " + key.substr(1) + " '" + r.size.to_string() + "'";
  const ParamDesc* d = s.params.find(name);
  if (!d) {
    s.error(GraphErrorCode::unknown_param_reference, where_of(r) + key,
            who + ": '$" + name + "' is not a parameter of graph '" + s.graph.name + "'");
    return 1;
  }
  if (d->type != ParamType::integer) {
    s.error(GraphErrorCode::param_wrong_type, where_of(r) + key,
            who + ": '$" + name + "' must be an int parameter, is " + param_type_name(d->type));
    return 1;
  }
  if (!d->structural) {
    s.error(GraphErrorCode::param_not_structural, where_of(r) + key,
            who + ": '$" + name + "' must be structural (a size change recompiles the graph)");
    return 1;
  }
  if (!d->has_range() || d->min < 1 || d->max > kMaxSizeDivisor) {
    s.error(GraphErrorCode::param_range_mismatch, where_of(r) + key,
            who + ": '$" + name + "' must have a range inside [1, " +
                std::to_string(kMaxSizeDivisor) + "] to divide a size");
    return 1;
  }
  return s.params.get_int(name);
}

// The tiles of a tile list or a per-tile texture: the tiled area divided by the tile edge,
// rounded up (a partial tile at the border is a tile). Reports an edge that is no power of two
// in kMinTileSize..kMaxTileSize.
void tile_grid(CompileState& s, const ResourceDecl& r, int& tiles_x, int& tiles_y, int* area_w = nullptr,
               int* area_h = nullptr) {
  tiles_x = tiles_y = 1;
  const int edge = divisor_of(s, r);
  if (!valid_tile_size(edge)) {
    const std::string from = r.size.divisor_reference.empty() ? "" : " ('$" + r.size.divisor_reference + "')";
    s.error(r.size.divisor_reference.empty() ? GraphErrorCode::wrong_json_type : GraphErrorCode::param_out_of_range,
            where_of(r) + "/tiles",
            std::string(r.tile_list ? "tile list '" : "per-tile texture '") + r.name + "': tile edge " +
                std::to_string(edge) + from + " must be a power of two in " + std::to_string(kMinTileSize) + ".." +
                std::to_string(kMaxTileSize) + " pixels");
    return;
  }
  int w = 0, h = 0;
  SizeExpr whole = r.size;
  whole.divisor_reference.clear();
  whole.resolve(s.settings, 1, w, h);
  if (area_w) *area_w = w;
  if (area_h) *area_h = h;
  tiles_x = (w + edge - 1) / edge;
  tiles_y = (h + edge - 1) / edge;
}

}  // namespace

void index_resources(CompileState& s) {
  const auto& res = s.graph.resources;
  s.resource_index.reserve(res.size());
  s.width.assign(res.size(), 0);
  s.height.assign(res.size(), 0);
  s.bytes.assign(res.size(), 0);
  s.tiled_width.assign(res.size(), 0);
  s.tiled_height.assign(res.size(), 0);
  s.version_of.assign(res.size(), {});
  for (size_t i = 0; i < res.size(); ++i) {
    auto [it, inserted] = s.resource_index.emplace(res[i].name, static_cast<int>(i));
    if (!inserted)
      s.error(GraphErrorCode::duplicate_name, where_of(res[i]),
              "resource '" + res[i].name + "' is declared twice");
    if (res[i].per_tile) {
      tile_grid(s, res[i], s.width[i], s.height[i]);
    } else if (res[i].kind == ResourceKind::texture || res[i].kind == ResourceKind::persistent) {
      res[i].size.resolve(s.settings, divisor_of(s, res[i]), s.width[i], s.height[i]);
    } else if (res[i].kind == ResourceKind::buffer && res[i].tile_list) {
      int tiles_x = 1, tiles_y = 1;
      tile_grid(s, res[i], tiles_x, tiles_y, &s.tiled_width[i], &s.tiled_height[i]);
      s.bytes[i] = tile_list_bytes(tiles_x, tiles_y);
    } else if (res[i].kind == ResourceKind::buffer) {
      s.bytes[i] = res[i].bytes;
    }
  }
}

}  // namespace penumbra::graph::detail
