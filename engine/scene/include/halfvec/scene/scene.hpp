// Scene: the CPU description of one frame (camera, objects, materials, lights, environment,
// render settings). Knows nothing of OpenGL. Loaded from JSON by scene_loader.hpp; the format is
// documented in docs/scene-format.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "halfvec/scene/render_settings.hpp"

namespace hv {

struct Camera {
  glm::vec3 position{0.0f, 1.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;  // vertical field of view
  float near_plane = 0.05f;
  float far_plane = 200.0f;
};

// Shading-model IDs as stored in the G-buffer (see docs/gbuffer.md). 0 marks background pixels.
// ClearCoat is DefaultLit under a clear coat (Material::clearcoat): the light and ambient passes
// branch on it, and only scenes with such a material compile that branch (docs/brdf.md,
// "Clear coat").
enum class ShadingModel : uint8_t { Background = 0, Unlit = 1, DefaultLit = 2, ClearCoat = 3 };
// The models the light and ambient passes light (everything but background and unlit).
constexpr bool isLit(ShadingModel m) {
  return m == ShadingModel::DefaultLit || m == ShadingModel::ClearCoat;
}

// A decoded image owned by the scene (glTF textures). 8-bit RGBA, row 0 = top.
struct ImageData {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;
};

enum class Wrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };
enum class Filter : uint8_t { Nearest, Linear };

struct Sampler {
  Wrap wrap_s = Wrap::Repeat;
  Wrap wrap_t = Wrap::Repeat;
  Filter mag = Filter::Linear;
  Filter min = Filter::Linear;
  bool mipmaps = true;
};

struct TextureRef {
  int image = -1;    // index into Scene::images; -1 = none
  int texcoord = 0;  // 0 or 1
  Sampler sampler;
  float scale = 1.0f;  // normalTexture.scale / occlusionTexture.strength
  // KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv, rotation in radians
  // counter-clockwise in UV space (the extension's matrix order).
  glm::vec2 uv_offset{0.0f};
  float uv_rotation = 0.0f;
  glm::vec2 uv_scale{1.0f};
  bool valid() const { return image >= 0; }
  bool transformed() const {
    return uv_offset != glm::vec2(0.0f) || uv_rotation != 0.0f || uv_scale != glm::vec2(1.0f);
  }
};

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

struct Material {
  std::string name;
  // Where the material is defined in its scene file, as the loader's JSON pointer
  // (/materials/gold, /objects/3/material); empty for glTF and default materials. Scene save
  // (scene_writer.hpp) writes edits there.
  std::string source;
  glm::vec3 base_color{0.8f};  // linear
  float metallic = 0.0f;
  float roughness = 0.5f;    // perceptual; alpha = roughness^2 (Karis 2013)
  float cavity = 1.0f;       // small-scale occlusion, 1 = none
  glm::vec3 emissive{0.0f};  // linear radiance added as-is
  ShadingModel model = ShadingModel::DefaultLit;
  // KHR_materials_clearcoat: the coat's layer weight and perceptual roughness. A material with
  // clearcoat > 0 has model ClearCoat (the loaders set it), 0 is DefaultLit.
  float clearcoat = 0.0f;
  float clearcoat_roughness = 0.0f;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  float base_alpha = 1.0f;
  bool double_sided = false;
  // Multiply base colour and alpha by the mesh's vertex colour (glTF COLOR_0) where it has one;
  // a scene file can switch it off per material ("vertex_color": false).
  bool vertex_color = true;
  TextureRef base_color_tex;          // sRGB
  TextureRef metallic_roughness_tex;  // B = metallic, G = roughness
  TextureRef normal_tex;
  TextureRef occlusion_tex;  // R -> Cavity
  TextureRef emissive_tex;   // sRGB
  // KHR_materials_clearcoat's textures (clear_coat materials only): R multiplies the coat's
  // weight, G its roughness; the coat's normal map (scale: its normalTexture.scale), in place
  // of the vertex normal. The G-buffer pass applies them; the forward pass of blended surfaces
  // has no texture units left for them and takes the factors alone (the loader warns).
  TextureRef clearcoat_tex;
  TextureRef clearcoat_roughness_tex;
  TextureRef clearcoat_normal_tex;
};

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // w = handedness
  glm::vec2 uv0{0.0f};
  glm::vec2 uv1{0.0f};
  glm::vec4 color{1.0f};  // linear RGBA (glTF COLOR_0); white where the mesh has none
};

// Triangle list in object space.
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  int material = 0;         // index into Scene::materials
  bool has_colors = false;  // vertices carry a COLOR_0 (else every Vertex::color is white)
};

struct Object {
  std::string name;
  glm::mat4 transform{1.0f};  // object -> world
  std::vector<int> meshes;    // indices into Scene::meshes
};

// Spot: a point (radius 0) or sphere light whose light is restricted to a cone about
// `direction` (docs/lights.md, "Spot lights"). Directional: light from a distant disk (the sun)
// travelling along `direction` (docs/lights.md, "Directional lights").
enum class LightType : uint8_t { Point = 0, Sphere = 1, Tube = 2, Spot = 3, Directional = 4 };

// A directional light's angular diameter: the sun's mean as seen from the Earth (0.533 degrees),
// the default; and the largest accepted, a cone of half-angle pi/4, beyond which a "distant disk"
// is half a sky and the representative-point and LTC methods were not measured.
constexpr float kSunAngularDiameter = 0.0093f;
constexpr float kMaxAngularDiameter = 1.5707963f;  // pi / 2
// Directional lights are not culled per tile: every lit pixel loops over them all, from a list
// of this many in the frame block (frame_block.glsl, directional_lights).
constexpr size_t kMaxDirectionalLights = 4;

// Physical meaning of each field: docs/lights.md.
struct Light {
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};
  glm::vec3 color{1.0f};  // linear RGB, multiplied by intensity
  // radiant intensity I (W/sr per unit color); a directional light's illuminance E at normal
  // incidence (W/m^2 per unit color); see docs/lights.md
  float intensity = 10.0f;
  float radius = 0.0f;               // sphere radius / tube capsule radius
  float length = 0.0f;               // tube segment length
  glm::vec3 axis{1.0f, 0.0f, 0.0f};  // tube segment direction (normalized on load)
  float range = 10.0f;  // falloff window radius R of Karis eq. 9; also the culling bound
  // Spot: the cone's axis (unit, from the light) and its angles from it in radians, with
  // KHR_lights_punctual's names and defaults; 0 <= inner < outer <= pi/2 (checked on load).
  // Directional: the direction the light travels (unit).
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  float inner_cone_angle = 0.0f;
  float outer_cone_angle = 0.78539816f;  // pi / 4
  // Directional: the full angle the disk subtends, radians, in [0, kMaxAngularDiameter]; 0 is a
  // single direction. The default is the sun's mean (about 0.53 degrees).
  float angular_diameter = kSunAngularDiameter;
  // Casts shadows: an omnidirectional shadow map (docs/lights.md, "Shadows").
  bool shadows = false;
};

// The emitter a light is shaded as: a spot of radius 0 is a point light, of radius > 0 a sphere
// (times its cone); the other types are their own shape.
inline LightType lightShape(const Light& l) {
  if (l.type != LightType::Spot) return l.type;
  return l.radius > 0.0f ? LightType::Sphere : LightType::Point;
}

enum class EnvironmentKind : uint8_t { None, Uniform, Sky, HdrFile };

struct Environment {
  EnvironmentKind kind = EnvironmentKind::Sky;
  std::string path;       // HdrFile: absolute path after loading
  glm::vec3 color{1.0f};  // Uniform: radiance
  float intensity = 1.0f;
  float rotation_deg = 0.0f;  // about +Y
  int cube_size = 256;
  int prefilter_samples = 256;
};

struct Scene {
  std::string source_path;  // the file it was loaded from (for error messages, relative paths)
  Camera camera;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Object> objects;
  std::vector<ImageData> images;
  std::vector<Light> lights;
  Environment environment;
  RenderSettings settings;
};

}  // namespace hv
