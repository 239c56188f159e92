#pragma once
// The sandbox's own GPU passes, outside any technique graph: composing the presentation image
// (a fragment pass per layer: a graph resource, a colour map, a value range) and the compare
// mode's error image (a compute pass, |a - b| of two masks). Shaders: sandbox/shaders/.
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "sandbox/view_mapping.h"
#include "exec/shader_cache.h"
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "scene/camera.h"
#include "util/error.h"
#include "metrics/mask_image.h"

namespace penumbra::sandbox {

// How the resource viewer shows a texture.
struct ViewerSettings {
  enum class Map { color, grey, heat, signed_error };  // display.frag.glsl's map_mode, in this order
  enum class Placement { full, inset };
  std::string resource;  // empty: viewer off
  Map map = Map::grey;
  Placement placement = Placement::inset;
  float min = 0.0f, max = 1.0f;  // value range mapped to [0, 1] (world units for linear depth)
  int channel = 0;               // grey/heat/signed read this channel
  unsigned channel_mask = 0x7;   // colour map: the channels shown (bit 0 red .. bit 3 alpha);
                                 // alpha alone shows alpha as grey
  bool histogram = true;         // the panel plots the viewed channel's histogram (every ~15 frames)
  std::vector<float> counts;     // that histogram over [min, max] (view_mapping.h's histogram())
  bool linearize_depth = true;   // screen-size depth -> view distance with the camera's near/far
  bool auto_range = false;       // min/max follow the resource's values (every ~15 frames)
  // Zoom and pan of what fills the frame: the final image (both sides of a compare split alike,
  // so their zoom is synced) and a full-placement resource. The inset is never zoomed.
  ViewZoom zoom;
};

const char* map_name(ViewerSettings::Map map);

class DisplayPass {
 public:
  struct Layer {
    const gl::Texture* texture = nullptr;
    glm::ivec4 viewport{0};          // x, y, width, height in pixels of the target
    glm::vec4 uv_rect{0, 0, 1, 1};   // part of the texture shown: origin, extent
    ViewerSettings::Map map = ViewerSettings::Map::color;
    int channel = 0;
    unsigned channel_mask = 0x7;
    glm::vec2 range{0.0f, 1.0f};
    bool linearize_depth = false;
    glm::vec2 near_far{0.05f, 200.0f};  // world units
    bool coverage_in_g = false;
  };

  // (Re)creates the presentation target (RGBA8) and the error image (RG16F) at this size.
  Status resize(int width, int height);
  GLuint framebuffer() const { return framebuffer_ ? framebuffer_->id() : 0; }
  const gl::Texture& target() const { return target_; }

  // Binds the presentation target and clears it to dark grey.
  void begin() const;
  // A refused frame: the whole target in kRefusedColor (the UI writes why on top).
  static constexpr float kRefusedColor[4] = {0.35f, 0.04f, 0.06f, 1.0f};
  void show_refused() const;
  Status draw(const Layer& layer);
  // Shadow-map texels per frame pixel of each receiver (texel_density.frag.glsl), over the target.
  // Receivers come from gbuffer_depth and the camera it was rendered with.
  Status texel_density(const gl::Texture& depth, const scene::Camera& camera, const glm::mat4& light_view_proj,
                       int shadow_size, const glm::vec4& uv_rect, float zoom);
  // difference.r = |a.r - b.r|, difference.g = receiver coverage (gbuffer_depth > 0).
  Status difference(const gl::Texture& a, const gl::Texture& b, const gl::Texture& depth);
  const gl::Texture& difference_texture() const { return difference_; }
  // A CPU picture of the frame's size (rows top to bottom), e.g. the pixel classes, as a texture;
  // `version` names the picture: the same version again uploads nothing.
  Status upload_picture(const metrics::RgbaImage& image, unsigned version);
  unsigned picture_version() const { return picture_version_; }
  const gl::Texture& picture_texture() const { return picture_; }

  exec::ShaderCache& shaders() { return shaders_; }
  const exec::ShaderCache& shaders() const { return shaders_; }

 private:
  gl::Buffer frame_uniforms_;  // the camera for texel_density (exec/frame_uniforms.h)
  exec::ShaderCache shaders_;
  gl::Texture target_, difference_, picture_;
  unsigned picture_version_ = 0;
  std::unique_ptr<gl::Framebuffer> framebuffer_;
  gl::GlHandle<gl::delete_vertex_array> vao_;
  gl::Sampler nearest_;
};

}  // namespace penumbra::sandbox
