#include "support/generic_pass_types.h"

// Designated initializers deliberately leave the remaining members at their defaults.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace penumbra::graph {

void register_generic_pass_types(PassTypeRegistry& registry) {
  using F = Format;
  const std::vector<Format> mask_formats = {F::R8, F::R16F, F::RGBA16F};

  registry.add({.name = "shadow_map",
                .slots = {{"scene", Access::read, SlotKind::imported, {}, Usage::imported},
                          {"light", Access::read, SlotKind::imported, {}, Usage::imported},
                          {"depth", Access::write, SlotKind::texture, {F::DEPTH32F}, Usage::depth_attachment}},
                .params = {{.name = "depth_bias", .type = ParamType::real, .default_value = 0.002,
                            .min = 0.0, .max = 0.1, .unit = "shadow-map depth",
                            .description = "Constant depth bias against shadow acne"}},
                .description = "Renders the scene's depth from the light"});
  registry.add({.name = "depth_prepass",
                .slots = {{"scene", Access::read, SlotKind::imported, {}, Usage::imported},
                          {"camera", Access::read, SlotKind::imported, {}, Usage::imported},
                          {"depth", Access::write, SlotKind::texture, {F::DEPTH32F}, Usage::depth_attachment}},
                .description = "Camera depth for screen-space passes"});
  registry.add({.name = "blocker_search",
                .slots = {{"shadow_map", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"depth", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"blocker", Access::write, SlotKind::texture, {F::R16F, F::R32F, F::RG16F}, Usage::image_store}},
                .params = {{.name = "search_radius", .type = ParamType::real, .default_value = 0.01,
                            .min = 0.0, .max = 0.1, .unit = "shadow-map UV",
                            .description = "Blocker search region half-width"},
                           {.name = "samples", .type = ParamType::integer, .default_value = 16,
                            .min = 1, .max = 64, .description = "Blocker search taps"}},
                .description = "Average blocker depth (PCSS step 1)"});
  registry.add({.name = "penumbra_filter",
                .slots = {{"shadow_map", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"depth", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"blocker", Access::read, SlotKind::texture, {F::R16F, F::R32F, F::RG16F}, Usage::sampled, false},
                          {"tiles", Access::read, SlotKind::buffer, {}, Usage::storage_buffer, false},
                          {"mask", Access::write, SlotKind::texture, mask_formats, Usage::image_store}},
                .params = {{.name = "kernel", .type = ParamType::enumeration, .default_value = std::string("vogel"),
                            .description = "Filter tap pattern", .options = {"box", "vogel", "poisson"}},
                           {.name = "samples", .type = ParamType::integer, .default_value = 16,
                            .min = 1, .max = 64, .description = "Filter taps"},
                           {.name = "light_size", .type = ParamType::real, .default_value = 0.5,
                            .min = 0.0, .max = 10.0, .unit = "world units",
                            .description = "Light radius"}},
                .same_size_groups = {{"depth", "mask"}},
                .description = "Percentage-closer filtering into the shadow mask"});
  registry.add({.name = "tile_classify",
                .slots = {{"depth", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"tiles", Access::write, SlotKind::buffer, {}, Usage::storage_buffer}},
                .params = {{.name = "tile_size", .type = ParamType::integer, .default_value = 16,
                            .min = 4, .max = 64, .unit = "pixels", .description = "Tile edge"}},
                .description = "Lists tiles that need the penumbra filter"});
  registry.add({.name = "tile_list_fill",
                .slots = {{"depth", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"tiles", Access::write, SlotKind::buffer, {}, Usage::storage_buffer, true, true}},
                .description = "Appends the tiles that need work to a tile list"});
  registry.add({.name = "tiled_filter",
                .slots = {{"depth", Access::read, SlotKind::texture, {F::DEPTH32F}, Usage::sampled},
                          {"tiles", Access::read, SlotKind::buffer, {}, Usage::indirect_dispatch, true, true},
                          {"mask", Access::write, SlotKind::texture, mask_formats, Usage::image_store}},
                .description = "Runs one work group per listed tile"});
  registry.add({.name = "blur",
                .slots = {{"input", Access::read, SlotKind::texture, mask_formats, Usage::sampled},
                          {"output", Access::write, SlotKind::texture, mask_formats, Usage::image_store}},
                .params = {{.name = "radius", .type = ParamType::integer, .default_value = 4,
                            .min = 1, .max = 16, .unit = "texels", .description = "Kernel radius"},
                           {.name = "sigma", .type = ParamType::real, .default_value = 2.0,
                            .min = 0.1, .max = 16.0, .unit = "texels", .description = "Gaussian sigma"}},
                .same_size_groups = {{"input", "output"}},
                .description = "Separable Gaussian blur (ping-pong)"});
  registry.add({.name = "tiled_blur",
                .slots = {{"input", Access::read, SlotKind::texture, mask_formats, Usage::sampled},
                          {"output", Access::write, SlotKind::texture, mask_formats, Usage::image_store, true, false,
                           true}},
                .same_size_groups = {{"input", "output"}},
                .description = "Blur that rewrites part of its output and keeps the rest (ping-pong)"});
  registry.add({.name = "directional_blur",
                .slots = {{"input", Access::read, SlotKind::texture, mask_formats, Usage::sampled},
                          {"output", Access::write, SlotKind::texture, mask_formats, Usage::image_store}},
                .params = {{.name = "axis", .type = ParamType::enumeration, .default_value = std::string("x"),
                            .description = "Blur direction", .options = {"x", "y"}, .required = true}},
                .same_size_groups = {{"input", "output"}},
                .description = "One axis of a separable blur: each pass must say which"});
  registry.add({.name = "blur_in_place",
                .slots = {{"image", Access::read_write, SlotKind::texture, mask_formats, Usage::image_load}},
                .params = {{.name = "radius", .type = ParamType::integer, .default_value = 2,
                            .min = 1, .max = 16, .unit = "texels", .description = "Kernel radius"}},
                .description = "Small in-place blur through image load/store"});
  registry.add({.name = "accumulate",
                .slots = {{"sample", Access::read, SlotKind::texture, mask_formats, Usage::sampled},
                          {"history", Access::read_write, SlotKind::texture, {F::RGBA16F, F::RGBA32F}, Usage::image_load}},
                .params = {{.name = "max_samples", .type = ParamType::integer, .default_value = 256,
                            .min = 1, .max = 65536, .description = "Frames to average"}},
                .description = "Progressive running average into a history texture"});
  registry.add({.name = "composite",
                .slots = {{"mask", Access::read, SlotKind::texture, {}, Usage::sampled},
                          {"target", Access::write, SlotKind::imported, {}, Usage::imported}},
                .side_effect = true,
                .description = "Lights the scene with the mask into the output target"});
}

}  // namespace penumbra::graph
