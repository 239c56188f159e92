#include "exec/texture_pool.h"

#include <algorithm>

namespace penumbra::exec {

void TexturePool::begin_generation() {
  ++generation_;
  for (auto& e : textures_) e.in_use = false;
  for (auto& e : buffers_) e.in_use = false;
}

void TexturePool::end_generation() {
  auto stale = [&](const auto& e) { return !e.in_use && generation_ - e.generation >= kKeepGenerations; };
  textures_.erase(std::remove_if(textures_.begin(), textures_.end(), stale), textures_.end());
  buffers_.erase(std::remove_if(buffers_.begin(), buffers_.end(), stale), buffers_.end());
}

void TexturePool::end_frame() {
  auto idle = [](auto& e) { return !e.in_use && ++e.idle_frames >= kKeepFrames; };
  textures_.erase(std::remove_if(textures_.begin(), textures_.end(), idle), textures_.end());
  buffers_.erase(std::remove_if(buffers_.begin(), buffers_.end(), idle), buffers_.end());
}

gl::Texture* TexturePool::acquire(gl::Format format, int width, int height) {
  for (auto& e : textures_) {
    const gl::Texture& t = *e.texture;
    if (!e.in_use && t.format() == format && t.width() == width && t.height() == height) {
      e.in_use = true;
      e.generation = generation_;
      e.idle_frames = 0;
      return e.texture.get();
    }
  }
  textures_.push_back({std::make_unique<gl::Texture>(format, width, height), generation_, true, 0});
  return textures_.back().texture.get();
}

gl::Buffer* TexturePool::acquire_buffer(size_t bytes) {
  for (auto& e : buffers_) {
    if (!e.in_use && e.buffer->size() == bytes) {
      e.in_use = true;
      e.generation = generation_;
      e.idle_frames = 0;
      return e.buffer.get();
    }
  }
  buffers_.push_back({std::make_unique<gl::Buffer>(bytes, nullptr, true), generation_, true, 0});
  return buffers_.back().buffer.get();
}

gl::Texture* TexturePool::persistent(const std::string& name, gl::Format format, int width, int height,
                                     bool* created) {
  auto& slot = persistent_[name];
  bool fresh = !slot || slot->format() != format || slot->width() != width || slot->height() != height;
  if (fresh) {
    slot = std::make_unique<gl::Texture>(format, width, height);
    slot->clear(0.0f);
  }
  if (created) *created = fresh;
  return slot.get();
}

std::uint64_t TexturePool::bytes() const {
  std::uint64_t total = 0;
  for (const auto& e : textures_) total += e.texture->bytes();
  for (const auto& [name, t] : persistent_) total += t->bytes();
  for (const auto& e : buffers_) total += e.buffer->size();
  return total;
}

}  // namespace penumbra::exec
