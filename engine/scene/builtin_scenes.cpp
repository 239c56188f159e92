#include "scene/builtin_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builder.h"
#include "scene/palm_tree.h"

namespace penumbra::scene {
namespace {

constexpr float kPi = 3.14159265358979f;

// Resolved parameters: defaults merged with overrides.
struct Params {
  std::map<std::string, float> values;
  float operator()(const std::string& key) const { return values.at(key); }
};

// Collects meshes and materials; every mesh gets one instance with `place`.
struct SceneBuilder {
  Scene scene;
  uint32_t material(const std::string& name, const glm::vec3& color) {
    scene.materials.push_back(Material{.name = name, .base_color_factor = glm::vec4(color, 1.0f)});
    return static_cast<uint32_t>(scene.materials.size() - 1);
  }
  void add(Mesh mesh, uint32_t material, const glm::mat4& place) {
    mesh.material = material;
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size() - 1), place});
  }
};

// Light from the sky at `elevation` degrees above the horizon, coming from `azimuth` degrees
// (0 = from +Z, 90 = from +X), emitter plane `distance` metres from `target`.
Light sky_light(const Params& p, const glm::vec3& target) {
  const float el = glm::radians(p("light_elevation")), az = glm::radians(p("light_azimuth"));
  Light l;
  l.type = LightType::directional;
  l.direction = glm::normalize(glm::vec3(-std::cos(el) * std::sin(az), -std::sin(el), -std::cos(el) * std::cos(az)));
  l.position = target - l.direction * p("light_distance");
  l.size = p("light_size");
  return l;
}

Mesh ground_mesh(float sx, float sz, const glm::vec3& center) {
  Mesh m;
  m.name = "ground";
  build::add_ground(m, center, sx, sz);
  return m;
}

void add_fence(SceneBuilder& b, const Params& p, const glm::mat4& place) {
  Mesh fence;
  fence.name = "fence";
  const int count = std::max(1, static_cast<int>(p("picket_count")));
  const float w = p("picket_width"), h = p("picket_height"), gap = p("picket_gap");
  const float pitch = w + gap, x0 = -0.5f * pitch * static_cast<float>(count - 1);
  for (int i = 0; i < count; ++i)
    build::add_box(fence, {x0 + pitch * static_cast<float>(i), 0.5f * h, 0.0f}, {0.5f * w, 0.5f * h, 0.02f});
  const float rail_len = pitch * static_cast<float>(count);
  for (float y : {0.25f * h, 0.75f * h})  // rails behind the pickets
    build::add_box(fence, {0.0f, y, -0.045f}, {0.5f * rail_len, 0.03f, 0.025f});
  b.add(std::move(fence), b.material("fence", {0.85f, 0.82f, 0.75f}), place);
}

void add_ball(SceneBuilder& b, const Params& p, const glm::mat4& place) {
  Mesh ball;
  ball.name = "ball";
  const float r = p("ball_radius");
  build::add_sphere(ball, {0.0f, p("ball_height") + r, 0.0f}, r, 48, 24);
  b.add(std::move(ball), b.material("ball", {0.8f, 0.25f, 0.2f}), place);
}

void add_poles(SceneBuilder& b, const Params& p, const glm::mat4& place) {
  Mesh poles;
  poles.name = "poles";
  const float r = p("pole_radius");
  for (int i = 0; i < 7; ++i) {  // standing poles: heights 0.6..2.4 m, tilts 0..36 degrees
    const float x = -2.4f + 0.8f * static_cast<float>(i), height = 0.6f + 0.3f * static_cast<float>(i);
    const float tilt = glm::radians(6.0f * static_cast<float>(i)) * (i % 2 ? 1.0f : -1.0f);
    const glm::vec3 base(x, 0.0f, 0.0f);
    build::add_cylinder(poles, base, base + height * glm::vec3(std::sin(tilt), std::cos(tilt), 0.0f), r, 12);
  }
  for (int i = 0; i < 3; ++i) {  // floating horizontal poles at 0.25, 0.75, 1.5 m
    const float y = std::array<float, 3>{0.25f, 0.75f, 1.5f}[static_cast<size_t>(i)];
    const float z = 1.0f + 0.5f * static_cast<float>(i);
    build::add_cylinder(poles, {-2.0f, y, z}, {2.0f, y, z - 0.6f}, r, 12);
  }
  b.add(std::move(poles), b.material("poles", {0.3f, 0.45f, 0.75f}), place);
}

void add_colonnade(SceneBuilder& b, const Params& p, const glm::mat4& place) {
  Mesh stone, hanging;
  stone.name = "colonnade";
  hanging.name = "hanging_poles";
  const int columns = std::max(2, static_cast<int>(p("column_count")));
  const float h = p("column_height"), cr = 0.3f, spacing = 2.0f, half_width = 2.5f;
  const float x0 = -0.5f * spacing * static_cast<float>(columns - 1), length = spacing * static_cast<float>(columns);
  for (float z : {-half_width, half_width}) {
    for (int i = 0; i < columns; ++i) build::add_cylinder(stone, {x0 + spacing * i, 0, z}, {x0 + spacing * i, h, z}, cr, 20);
    build::add_box(stone, {0.0f, h + 0.2f, z}, {0.5f * length, 0.2f, 0.35f});  // architrave
    const float ar = 0.5f * spacing - cr;                                      // arch radius
    for (int i = 0; i + 1 < columns; ++i) {
      const glm::vec3 c(x0 + spacing * (static_cast<float>(i) + 0.5f), h - ar, z);
      for (int k = 0; k < 10; ++k) {  // semicircle of 10 voussoir boxes
        const float a = kPi * (static_cast<float>(k) + 0.5f) / 10.0f;
        const glm::mat3 rot = glm::mat3(glm::rotate(glm::mat4(1.0f), a, glm::vec3(0, 0, 1)));
        build::add_box(stone, c + ar * glm::vec3(std::cos(a), std::sin(a), 0.0f), {0.08f, ar * kPi / 20.0f, 0.2f}, rot);
      }
    }
  }
  const float beam_y = h + 0.55f, hang = p("hanging_length");
  for (float x : {-0.5f * length + 1.0f, 0.0f, 0.5f * length - 1.0f}) {  // cross beams and what hangs from them
    build::add_box(stone, {x, beam_y, 0.0f}, {0.1f, 0.1f, half_width + 0.3f});
    for (float z : {-1.2f, -0.4f, 0.4f, 1.2f})
      build::add_cylinder(hanging, {x, beam_y, z}, {x + 0.1f * z, beam_y - hang, z}, 0.03f, 10);
  }
  b.add(std::move(stone), b.material("stone", {0.78f, 0.74f, 0.66f}), place);
  b.add(std::move(hanging), b.material("hanging", {0.55f, 0.35f, 0.25f}), place);
}

// Three palms of different heights around a low wall, on a sand-coloured ground. The fronds are
// alpha-masked (Cherry & Kooima's Pool scene): the shadow map, the G-buffer and the ray-traced
// reference all see the gaps between the leaflets.
void add_palms(SceneBuilder& b, const Params& p) {
  Mesh trunks, fronds, wall;
  trunks.name = "palm_trunks";
  fronds.name = "palm_fronds";
  wall.name = "wall";
  const float h = p("palm_height"), length = p("frond_length");
  const int count = std::max(3, static_cast<int>(p("frond_count")));
  build::add_palm(trunks, fronds, {.base = {-1.6f, 0, -1.2f}, .height = h, .lean_degrees = 10, .lean_azimuth = 200,
                                   .fronds = count, .frond_length = length, .crown_phase = 10});
  build::add_palm(trunks, fronds, {.base = {1.2f, 0, -2.2f}, .height = 0.8f * h, .lean_degrees = 6, .lean_azimuth = 20,
                                   .fronds = count, .frond_length = 0.9f * length, .crown_phase = 35});
  build::add_palm(trunks, fronds, {.base = {0.6f, 0, 1.2f}, .height = 0.6f * h, .lean_degrees = 14, .lean_azimuth = 300,
                                   .fronds = count, .frond_length = 0.8f * length, .crown_phase = 60});
  build::add_box(wall, {0.0f, 0.25f, 2.6f}, {2.2f, 0.25f, 0.15f});  // a low wall to catch shadows off the ground
  b.scene.images.push_back(palm_frond_image());
  b.scene.materials.push_back(Material{.name = "palm_frond",
                                       .base_color_factor = glm::vec4(1.0f),
                                       .base_color_texture = static_cast<int>(b.scene.images.size() - 1),
                                       .alpha_mode = AlphaMode::mask,
                                       .alpha_cutoff = 0.5f,
                                       .double_sided = true});
  const uint32_t frond_material = static_cast<uint32_t>(b.scene.materials.size() - 1);
  b.add(std::move(trunks), b.material("palm_trunk", {0.5f, 0.38f, 0.26f}), glm::mat4(1.0f));
  b.add(std::move(fronds), frond_material, glm::mat4(1.0f));
  b.add(std::move(wall), b.material("wall", {0.85f, 0.85f, 0.8f}), glm::mat4(1.0f));
}

const std::vector<ProceduralParam> kRoomParams = {
    {"room_width", 6.0f, "inside width (x), metres"},
    {"room_depth", 5.0f, "inside depth (z), metres"},
    {"room_height", 3.0f, "inside height (y), metres"},
    {"lamp_height", 2.5f, "height of the lamp (the light's centre) above the floor, metres"},
    {"light_size", 0.25f, "the lamp's diameter, metres"},
    {"lamp_cone", 0.0f, "0: the lamp lights every direction (a point light); 1-89: a spot light "
                        "pointing down with this half-angle, degrees (one shadow map, to compare with)"}};

// The furniture needs a room of at least 3 x 3 m and 2.2 m high (the cabinet is 1.8 m tall, the
// shelf at 2 m); the lamp hangs inside it, below the ceiling and above the floor by its radius.
Status check_room(const Params& p) {
  char text[200];
  for (const char* key : {"room_width", "room_depth"}) {
    if (p(key) >= 3.0f) continue;
    std::snprintf(text, sizeof text, "%s %.3g m is below the smallest room that holds the furniture (3 m)", key, p(key));
    return make_error(text);
  }
  if (p("room_height") < 2.2f) {
    std::snprintf(text, sizeof text, "room_height %.3g m is below the smallest room that holds the furniture (2.2 m)",
                  p("room_height"));
    return make_error(text);
  }
  const float radius = 0.5f * p("light_size");
  if (p("light_size") < 0.0f || p("light_size") > 1.0f) {
    std::snprintf(text, sizeof text, "light_size %.3g m is outside [0, 1] m", p("light_size"));
    return make_error(text);
  }
  if (p("lamp_cone") != 0.0f) {
    if (Status s = check_spot_angle_degrees(p("lamp_cone")); !s) return make_error("lamp_cone: " + s.error().message);
  }
  if (p("lamp_height") - radius <= 0.0f || p("lamp_height") + radius >= p("room_height")) {
    std::snprintf(text, sizeof text,
                  "lamp_height %.3g m puts the lamp (radius %.3g m) outside the room (floor 0, ceiling %.3g m)",
                  p("lamp_height"), radius, p("room_height"));
    return make_error(text);
  }
  return {};
}

// A closed room lit by a lamp hanging from the ceiling: a table with a ball on it, a chair, a
// tall cabinet against the back wall and a shelf on the side wall, so that casters stand at
// several heights below the lamp and around it (issue: point lights inside the scene).
void add_room(SceneBuilder& b, const Params& p) {
  const float w = p("room_width"), d = p("room_depth"), h = p("room_height");
  Mesh walls;
  walls.name = "walls";
  build::add_inside_box(walls, {0.0f, 0.5f * h, 0.0f}, {0.5f * w, 0.5f * h, 0.5f * d});
  b.add(std::move(walls), b.material("walls", {0.78f, 0.76f, 0.72f}), glm::mat4(1.0f));
  Mesh furniture;
  furniture.name = "furniture";
  const glm::vec3 table(0.5f, 0.0f, -0.5f);
  build::add_box(furniture, table + glm::vec3(0.0f, 0.74f, 0.0f), {0.7f, 0.025f, 0.4f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      build::add_box(furniture, table + glm::vec3(0.64f * sx, 0.36f, 0.34f * sz), {0.025f, 0.36f, 0.025f});
  const glm::vec3 chair(-0.6f, 0.0f, 0.1f);
  build::add_box(furniture, chair + glm::vec3(0.0f, 0.45f, 0.0f), {0.22f, 0.02f, 0.22f});
  build::add_box(furniture, chair + glm::vec3(-0.2f, 0.72f, 0.0f), {0.02f, 0.26f, 0.22f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      build::add_box(furniture, chair + glm::vec3(0.19f * sx, 0.215f, 0.19f * sz), {0.018f, 0.215f, 0.018f});
  build::add_box(furniture, {-0.3f * w, 0.9f, -0.5f * d + 0.2f}, {0.6f, 0.9f, 0.18f});      // cabinet
  build::add_box(furniture, {0.5f * w - 0.16f, 2.0f, 0.4f}, {0.15f, 0.02f, 0.55f});         // shelf
  b.add(std::move(furniture), b.material("wood", {0.55f, 0.4f, 0.28f}), glm::mat4(1.0f));
  Mesh ball;
  ball.name = "ball";
  build::add_sphere(ball, table + glm::vec3(-0.3f, 0.88f, 0.1f), 0.12f, 32, 16);
  b.add(std::move(ball), b.material("ball", {0.8f, 0.25f, 0.2f}), glm::mat4(1.0f));
  const glm::vec3 lamp(0.0f, p("lamp_height"), 0.0f);
  const float cord_bottom = lamp.y + 0.5f * p("light_size") + 0.02f;
  if (cord_bottom < h - 0.02f) {  // the lamp hangs from the ceiling by a cord above the light
    Mesh cord;
    cord.name = "cord";
    build::add_cylinder(cord, {0.0f, cord_bottom, 0.0f}, {0.0f, h, 0.0f}, 0.008f, 8);
    b.add(std::move(cord), b.material("cord", glm::vec3(0.1f)), glm::mat4(1.0f));
  }
  Light l;
  l.type = p("lamp_cone") > 0.0f ? LightType::spot : LightType::point;
  l.position = lamp;
  l.direction = {0.0f, -1.0f, 0.0f};
  l.spot_angle = glm::radians(p("lamp_cone"));
  l.size = p("light_size");
  b.scene.light = l;
  b.scene.camera = Camera::look_at({-0.42f * w, 1.7f, 0.42f * d}, {0.4f, 0.5f, -0.6f}, glm::radians(70.0f));
}

// A street under the sun, long enough that one shadow map over it has texels of decimetres near
// the camera: lamp posts with arms every `post_spacing` metres on both sides out to `length`, a
// pergola of thin beams and benches near the camera, the camera at eye height looking along it.
// Casters stand from about 1 m to `length` from the camera (cascades: scene/cascades.h).
const std::vector<ProceduralParam> kAvenueParams = {
    {"length", 200.0f, "length of the avenue in front of the camera, metres"},
    {"post_spacing", 8.0f, "distance between lamp posts along each side, metres"},
    {"post_height", 4.5f, "lamp post height, metres"}};

Status check_avenue(const Params& p) {
  if (!(p("length") >= 10.0f && p("length") <= 2000.0f))
    return make_error("length must be in [10, 2000] metres", ErrorKind::bad_input);
  if (!(p("post_spacing") >= 1.0f) || p("length") / p("post_spacing") > 2000.0f)
    return make_error("post_spacing must be at least 1 metre and length / post_spacing at most 2000",
                      ErrorKind::bad_input);
  if (!(p("post_height") >= 0.5f && p("post_height") <= 50.0f))
    return make_error("post_height must be in [0.5, 50] metres", ErrorKind::bad_input);
  return {};
}

void add_avenue(SceneBuilder& b, const Params& p) {
  const float length = p("length"), spacing = p("post_spacing"), h = p("post_height");
  const float road = 3.5f;  // half width: posts stand at x = +-road
  // The camera stands at z = 0 looking down -z; the ground runs from behind it to past the end.
  b.add(ground_mesh(4.0f * road + 8.0f, length + 12.0f, {0.0f, 0.0f, -0.5f * length + 4.0f}),
        b.material("pavement", glm::vec3(0.68f, 0.66f, 0.62f)), glm::mat4(1.0f));
  Mesh posts, pergola, benches;
  posts.name = "lamp_posts";
  pergola.name = "pergola";
  benches.name = "benches";
  for (float z = -2.0f; z > -length; z -= spacing)
    for (float side : {-1.0f, 1.0f}) {
      const float x = side * road;
      build::add_cylinder(posts, {x, 0.0f, z}, {x, h, z}, 0.09f, 12);
      build::add_box(posts, {x - side * 0.6f, h - 0.05f, z}, {0.6f, 0.05f, 0.05f});  // arm over the road
      build::add_box(posts, {x - side * 1.15f, h - 0.25f, z}, {0.15f, 0.12f, 0.1f});  // lamp head
    }
  // A pergola of slats 2.6 m up over the first 6 m: thin casters with wide penumbrae.
  for (float x : {-2.0f, 2.0f})
    for (float z : {-1.0f, -7.0f}) build::add_box(pergola, {x, 1.3f, z}, {0.08f, 1.3f, 0.08f});
  for (float x : {-2.0f, 2.0f}) build::add_box(pergola, {x, 2.65f, -4.0f}, {0.1f, 0.06f, 3.2f});
  for (int i = 0; i < 13; ++i)
    build::add_box(pergola, {0.0f, 2.75f, -1.0f - 0.5f * static_cast<float>(i)}, {2.4f, 0.04f, 0.05f});
  // Benches a metre or two from the camera and further along: contact shadows near and far.
  for (float z : {-1.5f, -12.0f, -40.0f})
    for (float side : {-1.0f, 1.0f}) {
      const float x = side * (road - 1.0f);
      build::add_box(benches, {x, 0.45f, z}, {0.25f, 0.04f, 0.9f});  // seat
      for (float dz : {-0.75f, 0.75f}) build::add_box(benches, {x, 0.21f, z + dz}, {0.2f, 0.21f, 0.04f});
    }
  b.add(std::move(posts), b.material("iron", glm::vec3(0.35f, 0.36f, 0.38f)), glm::mat4(1.0f));
  b.add(std::move(pergola), b.material("timber", glm::vec3(0.55f, 0.42f, 0.3f)), glm::mat4(1.0f));
  b.add(std::move(benches), b.material("bench", glm::vec3(0.6f, 0.5f, 0.4f)), glm::mat4(1.0f));
  b.scene.camera = Camera::look_at({0.6f, 1.7f, 1.0f}, {0.0f, 0.9f, -12.0f}, glm::radians(60.0f), 0.1f,
                                   length + 20.0f);
  b.scene.light = sky_light(p, {0.0f, 0.0f, -0.5f * length});
}

const std::vector<ProceduralParam> kLightParams(float size, float elevation, float azimuth, float distance) {
  return {{"light_size", size, "emitter disk diameter, metres"},
          {"light_elevation", elevation, "light elevation above the horizon, degrees"},
          {"light_azimuth", azimuth, "direction the light comes from, degrees (0 = +Z, 90 = +X)"},
          {"light_distance", distance, "distance of the emitter plane from the scene centre, metres"}};
}

struct BuiltinScene {
  std::string name;
  std::vector<ProceduralParam> params;
  std::function<void(SceneBuilder&, const Params&)> build;
  // Parameters the geometry cannot be built from (none checked when empty).
  std::function<Status(const Params&)> check;
};

std::vector<ProceduralParam> join(std::vector<ProceduralParam> a, const std::vector<ProceduralParam>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const std::vector<ProceduralParam> kFenceParams = {
    {"picket_count", 14, "number of pickets"},
    {"picket_height", 1.2f, "picket height, metres"},
    {"picket_width", 0.08f, "picket width, metres"},
    {"picket_gap", 0.14f, "gap between pickets, metres"}};
const std::vector<ProceduralParam> kBallParams = {
    {"ball_height", 0.5f, "gap between the ground and the bottom of the ball, metres"},
    {"ball_radius", 0.5f, "ball radius, metres"}};
const std::vector<ProceduralParam> kPoleParams = {{"pole_radius", 0.04f, "pole radius, metres"}};
const std::vector<ProceduralParam> kPalmParams = {
    {"palm_height", 3.5f, "trunk height of the tallest palm (the others are 0.8x and 0.6x), metres"},
    {"frond_count", 9, "fronds per crown"},
    {"frond_length", 1.8f, "frond length of the tallest palm, metres"}};
const std::vector<ProceduralParam> kColonnadeParams = {
    {"column_count", 6, "columns per row"},
    {"column_height", 3.5f, "column height, metres"},
    {"hanging_length", 1.4f, "length of the poles hanging from the cross beams, metres"}};

const std::vector<BuiltinScene>& registry() {
  static const std::vector<BuiltinScene> scenes = {
      {"fence", join(kFenceParams, kLightParams(0.5f, 40.0f, 0.0f, 8.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(8, 8, {0, 0, -1.5f}), b.material("ground", glm::vec3(0.7f)), glm::mat4(1.0f));
         add_fence(b, p, glm::mat4(1.0f));
         b.scene.camera = Camera::look_at({2.0f, 3.2f, -5.2f}, {0.0f, 0.3f, -0.9f});
         b.scene.light = sky_light(p, {0, 0, -0.5f});
       }},
      {"ball", join(kBallParams, kLightParams(0.6f, 20.0f, 0.0f, 10.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(12, 12, {0, 0, -2.5f}), b.material("ground", glm::vec3(0.7f)), glm::mat4(1.0f));
         add_ball(b, p, glm::mat4(1.0f));
         b.scene.camera = Camera::look_at({4.5f, 4.0f, 3.0f}, {0.0f, 0.3f, -2.0f});
         b.scene.light = sky_light(p, {0, 0, -1.5f});
       }},
      {"poles", join(kPoleParams, kLightParams(0.5f, 45.0f, 30.0f, 8.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(9, 8, {0, 0, -0.5f}), b.material("ground", glm::vec3(0.7f)), glm::mat4(1.0f));
         add_poles(b, p, glm::mat4(1.0f));
         b.scene.camera = Camera::look_at({1.5f, 4.0f, 5.5f}, {0.0f, 0.4f, -0.5f});
         b.scene.light = sky_light(p, {0, 0, 0});
       }},
      {"colonnade", join(kColonnadeParams, kLightParams(0.6f, 55.0f, 35.0f, 14.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(16, 10, {0, 0, 0}), b.material("floor", glm::vec3(0.72f, 0.7f, 0.66f)), glm::mat4(1.0f));
         add_colonnade(b, p, glm::mat4(1.0f));
         b.scene.camera = Camera::look_at({-9.0f, 4.0f, 7.0f}, {0.5f, 0.8f, -0.5f}, glm::radians(55.0f));
         b.scene.light = sky_light(p, {0, 0, 0});
       }},
      {"palms", join(kPalmParams, kLightParams(0.6f, 50.0f, 200.0f, 12.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(12, 12, {0, 0, -0.5f}), b.material("sand", {0.82f, 0.76f, 0.62f}), glm::mat4(1.0f));
         add_palms(b, p);
         b.scene.camera = Camera::look_at({3.5f, 5.5f, 7.5f}, {-0.2f, 0.6f, -0.6f});
         b.scene.light = sky_light(p, {0, 0, -0.5f});
       }},
      {"room", kRoomParams, [](SceneBuilder& b, const Params& p) { add_room(b, p); }, check_room},
      {"avenue", join(kAvenueParams, kLightParams(2.0f, 35.0f, 60.0f, 150.0f)),
       [](SceneBuilder& b, const Params& p) { add_avenue(b, p); }, check_avenue},
      {"showcase",
       join(join(join(join(kFenceParams, kBallParams), kPoleParams), kColonnadeParams),
            kLightParams(0.7f, 40.0f, 25.0f, 16.0f)),
       [](SceneBuilder& b, const Params& p) {
         b.add(ground_mesh(26, 22, {0, 0, -2.0f}), b.material("ground", glm::vec3(0.7f)), glm::mat4(1.0f));
         add_colonnade(b, p, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -8.0f}));
         add_fence(b, p, glm::translate(glm::mat4(1.0f), {-6.0f, 0.0f, 2.0f}));
         add_ball(b, p, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, 2.5f}));
         add_poles(b, p, glm::translate(glm::mat4(1.0f), {6.0f, 0.0f, 1.5f}));
         b.scene.camera = Camera::look_at({0.0f, 5.5f, 7.5f}, {0.0f, 0.0f, -2.5f}, glm::radians(55.0f));
         b.scene.light = sky_light(p, {0, 0, -2.0f});
       }},
  };
  return scenes;
}

std::string joined_names() {
  std::string s;
  for (const BuiltinScene& b : registry()) s += (s.empty() ? "" : ", ") + b.name;
  return s;
}

}  // namespace

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const BuiltinScene& b : registry()) names.push_back(b.name);
  return names;
}

std::vector<ProceduralParam> builtin_scene_params(const std::string& name) {
  for (const BuiltinScene& b : registry())
    if (b.name == name) return b.params;
  return {};
}

Result<Scene> make_builtin_scene(const std::string& name, const ProceduralParams& overrides) {
  for (const BuiltinScene& entry : registry()) {
    if (entry.name != name) continue;
    Params p;
    for (const ProceduralParam& d : entry.params) p.values[d.key] = d.default_value;
    for (const auto& [key, value] : overrides) {
      if (!p.values.count(key)) {
        std::string keys;
        for (const ProceduralParam& d : entry.params) keys += (keys.empty() ? "" : ", ") + d.key;
        Error e = make_error("unknown parameter '" + key + "' for built-in scene '" + name + "'; valid: " + keys);
        e.where = "scene " + name;
        return e;
      }
      if (!std::isfinite(value)) return make_error("parameter '" + key + "' of scene '" + name + "' is not finite");
      p.values[key] = value;
    }
    SceneBuilder b;
    b.scene.name = name;
    if (entry.check) {
      if (Status s = entry.check(p); !s) {
        Error e = s.error();
        e.where = "scene " + name;
        return e;
      }
    }
    entry.build(b, p);
    b.scene.bounds = compute_bounds(b.scene);
    const float extent = glm::length(b.scene.bounds.extent());
    b.scene.camera.near_plane = 0.05f;
    b.scene.camera.far_plane = 4.0f * extent + 10.0f;
    return std::move(b.scene);
  }
  return make_error("unknown built-in scene '" + name + "'; valid names: " + joined_names());
}

}  // namespace penumbra::scene
