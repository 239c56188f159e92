#pragma once
// Resource descriptions of the render graph: texture formats, size expressions resolved at
// compile time, and the four kinds of resource. No GL here: the executor maps Format to GL.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>
#include <string>
#include <string_view>

namespace penumbra::graph {

// The one list of texture formats; engine/gl/texture_format.cpp adds each one's GL enums.
// R16/RG16/RGBA16 are unsigned normalised, *_SNORM signed normalised (both read as floats).
enum class Format {
  R8, R16F, R32F, RG16F, RG32F, RGBA8, RGBA16F, RGBA32F, DEPTH32F,
  R16, RG16, R16_SNORM, RG16_SNORM, RGB10A2, R11G11B10F, RGBA16, RGBA16_SNORM
};
inline constexpr int kFormatCount = 17;

const char* format_name(Format format);
std::optional<Format> parse_format(std::string_view name);
std::string format_names();  // "R8, R16F, ...": every format, for messages
int bytes_per_texel(Format format);
int channel_count(Format format);
bool is_depth_format(Format format);
// Every format but the depth ones: what a colour attachment or an image may be.
std::vector<Format> colour_formats();
// The GLSL image format layout qualifier of the format ("r16f", "rgb10_a2"); "" for depth
// formats, which image load/store cannot use.
const char* image_format_qualifier(Format format);

// texture:    transient, compiler-owned, may share a physical texture with another resource
//             of the identical descriptor whose lifetime does not overlap.
// buffer:     transient storage buffer, of a byte size or a tile list (below); same reuse rule.
// imported:   provided by the executor every frame (scene, camera, light, output target).
// persistent: history kept across frames; never shared, never culled away by reuse.
enum class ResourceKind { texture, buffer, imported, persistent };
const char* resource_kind_name(ResourceKind kind);
std::optional<ResourceKind> parse_resource_kind(std::string_view name);

inline constexpr int kMaxSizeDivisor = 64;    // screen/N, shadow/N
inline constexpr int kMaxTextureSize = 16384;  // texels per side: what GL 4.5 implementations commonly allow

// Compile-time sizes, in pixels / texels.
struct CompileSettings {
  int screen_w = 1920;
  int screen_h = 1080;
  int shadow_size = 2048;  // shadow map is shadow_size x shadow_size texels
};

// `screen`, `screen/2`, `screen/4`, `shadow`, `shadow/2` (any divisor 1..64), a divisor given
// by a structural int parameter (`screen/$mask_divisor`), or `WxH`.
struct SizeExpr {
  enum class Base { screen, shadow, fixed } base = Base::screen;
  int divisor = 1;
  int width = 0, height = 0;      // fixed only
  std::string divisor_reference;  // parameter name without '$'; overrides `divisor` when set

  static SizeExpr screen(int div = 1) { return {Base::screen, div, 0, 0, {}}; }
  static SizeExpr shadow(int div = 1) { return {Base::shadow, div, 0, 0, {}}; }
  static SizeExpr fixed(int w, int h) { return {Base::fixed, 1, w, h, {}}; }
  // `screen/$name` or `shadow/$name`.
  static SizeExpr screen_by(std::string parameter) { return {Base::screen, 1, 0, 0, std::move(parameter)}; }
  static SizeExpr shadow_by(std::string parameter) { return {Base::shadow, 1, 0, 0, std::move(parameter)}; }

  static std::optional<SizeExpr> parse(std::string_view text);
  std::string to_string() const;
  // Integer division by `divisor` (the compiler passes the referenced parameter's value when
  // divisor_reference is set), never below 1 texel.
  void resolve(const CompileSettings& s, int divisor, int& w, int& h) const;
};

// A tile list is a buffer that one pass fills with the screen tiles that need work and a later
// pass dispatches over (indirect dispatch, engine/gl/shaders/tile_list.glsl): a 16-byte header,
// the dispatch arguments (tiles appended, 1, 1) and a reserved word, then one 4-byte tile
// coordinate (x | y << 16) per tile of the grid. Its size expression is the tiled area over the
// tile edge: `screen/8` is the screen in 8 x 8-pixel tiles, ceil(w / 8) x ceil(h / 8) of them.
inline constexpr std::uint64_t kTileListHeaderBytes = 16;
inline constexpr std::uint64_t kTileListEntryBytes = 4;
// The header of a list with no tile yet: dispatch arguments 0 x 1 x 1, reserved word 0.
inline constexpr std::uint32_t kEmptyTileListHeader[4] = {0, 1, 1, 0};
inline constexpr int kMinTileSize = 4, kMaxTileSize = 32;  // pixels, a power of two
bool valid_tile_size(int pixels);
std::uint64_t tile_list_bytes(int tiles_x, int tiles_y);

// A format chosen by structural parameters: `format` applies where `when` holds (the condition
// language of graph/condition.h), the first that holds wins.
struct FormatChoice {
  std::string when;
  Format format = Format::RGBA8;
};

struct ResourceDecl {
  std::string name;
  ResourceKind kind = ResourceKind::texture;
  Format format = Format::RGBA8;  // texture, persistent; with format_choices, set per compile
  SizeExpr size;                  // texture, persistent; a tile list's tiled area / tile edge
  std::uint64_t bytes = 0;        // buffer (not a tile list)
  std::string location;           // JSON pointer of the declaration ("" from C++)
  bool tile_list = false;         // buffer: a tile list sized by `size`
  bool per_tile = false;          // texture: one texel per tile of `size` (a tiled area / tile edge, rounded up)
  std::vector<FormatChoice> format_choices;  // empty: `format` is fixed
};

}  // namespace penumbra::graph
