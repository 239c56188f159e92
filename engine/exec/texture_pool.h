#pragma once
// Physical textures and buffers outlive compiled plans: a recompile (technique swap, structural
// parameter) or a screen resize takes matching textures back from the pool instead of
// allocating. Entries no plan has used for `kKeepGenerations` plan builds, or that the current
// plan has not used for `kKeepFrames` frames, are freed: the pool stays bounded however many
// plans come and go, and returns to what the current plan holds once they stop (after a window
// resize, say). Persistent (history) resources are keyed by
// name and survive recompiles while their descriptor is unchanged. One executor per pool: a plan
// build marks every entry free for the plan being built.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "gl/buffer.h"
#include "gl/texture.h"

namespace penumbra::exec {

class TexturePool {
 public:
  static constexpr int kKeepGenerations = 2;
  static constexpr int kKeepFrames = 30;  // half a second at 60 fps: a resize drag reuses, then frees

  // Starts a plan build: every pooled texture becomes free for acquire().
  void begin_generation();
  // Frees entries unused for kKeepGenerations builds.
  void end_generation();
  // Counts a frame of the current plan; frees entries it has not used for kKeepFrames frames.
  void end_frame();

  gl::Texture* acquire(gl::Format format, int width, int height);
  gl::Buffer* acquire_buffer(size_t bytes);
  // Same texture as last time for `name` when the descriptor matches; otherwise a new cleared one.
  gl::Texture* persistent(const std::string& name, gl::Format format, int width, int height,
                          bool* created = nullptr);
  void drop_persistent(const std::string& name) { persistent_.erase(name); }

  size_t texture_count() const { return textures_.size() + persistent_.size(); }
  size_t buffer_count() const { return buffers_.size(); }
  std::uint64_t bytes() const;

 private:
  struct TextureEntry {
    std::unique_ptr<gl::Texture> texture;
    int generation = 0;  // last plan build that used it
    bool in_use = false;
    int idle_frames = 0;  // frames since the current plan stopped using it
  };
  struct BufferEntry {
    std::unique_ptr<gl::Buffer> buffer;
    int generation = 0;
    bool in_use = false;
    int idle_frames = 0;
  };
  std::vector<TextureEntry> textures_;
  std::vector<BufferEntry> buffers_;
  std::map<std::string, std::unique_ptr<gl::Texture>> persistent_;
  int generation_ = 0;
};

}  // namespace penumbra::exec
