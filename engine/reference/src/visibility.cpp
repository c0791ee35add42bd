#include "halfvec/reference/visibility.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace hv::reference_detail {

namespace {

// What the alpha filter of one masked mesh needs: the UVs of its vertices (the material's
// texcoord set), its triangles, and the material's alpha inputs.
struct AlphaMask {
  std::vector<glm::vec2> uv;
  std::vector<uint32_t> indices;  // 3 per Embree primitive, in the geometry's primitive order
  const ImageData* image = nullptr;
  Sampler sampler;
  float base_alpha = 1.0f;
  float cutoff = 0.5f;
};

float wrapCoord(float t, Wrap w) {
  switch (w) {
    case Wrap::ClampToEdge:
      return std::clamp(t, 0.0f, 1.0f);
    case Wrap::MirroredRepeat: {
      const float m = t - 2.0f * std::floor(0.5f * t);  // in [0, 2)
      return m <= 1.0f ? m : 2.0f - m;
    }
    case Wrap::Repeat:
      break;
  }
  return t - std::floor(t);
}

// One texel's alpha with GL's wrap rule for integer coordinates (ClampToEdge clamps the index,
// Repeat and MirroredRepeat fold it into the image).
float texelAlpha(const ImageData& img, int x, int y, const Sampler& s) {
  auto fold = [](int i, int n, Wrap w) {
    if (w == Wrap::ClampToEdge) return std::clamp(i, 0, n - 1);
    if (w == Wrap::MirroredRepeat) {
      const int p = ((i % (2 * n)) + 2 * n) % (2 * n);
      return p < n ? p : 2 * n - 1 - p;
    }
    return ((i % n) + n) % n;
  };
  x = fold(x, img.width, s.wrap_s);
  y = fold(y, img.height, s.wrap_t);
  return float(img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4u + 3u]) * (1.0f / 255.0f);
}

// The base-color texture's alpha at uv, from its full-resolution level: bilinear unless the
// sampler's magnification filter is Nearest. The G-buffer pass samples a mip chosen by the
// pixel's footprint; a shadow ray has no footprint, so the surface's own alpha is the finest
// level's (the alpha channel is linear even in an sRGB texture).
float textureAlpha(const ImageData& img, const Sampler& s, glm::vec2 uv) {
  if (img.width <= 0 || img.height <= 0 || img.rgba.size() < size_t(img.width) * img.height * 4u)
    return 1.0f;
  const float u = wrapCoord(uv.x, s.wrap_s) * float(img.width);
  const float v = wrapCoord(uv.y, s.wrap_t) * float(img.height);  // row 0 = top = v 0 (glTF)
  if (s.mag == Filter::Nearest) {
    return texelAlpha(img, int(std::floor(u)), int(std::floor(v)), s);
  }
  const float fu = u - 0.5f, fv = v - 0.5f;
  const int x0 = int(std::floor(fu)), y0 = int(std::floor(fv));
  const float ax = fu - float(x0), ay = fv - float(y0);
  const float a00 = texelAlpha(img, x0, y0, s), a10 = texelAlpha(img, x0 + 1, y0, s);
  const float a01 = texelAlpha(img, x0, y0 + 1, s), a11 = texelAlpha(img, x0 + 1, y0 + 1, s);
  return (a00 * (1.0f - ax) + a10 * ax) * (1.0f - ay) + (a01 * (1.0f - ax) + a11 * ax) * ay;
}

// Embree's occlusion filter for masked geometry: a hit where the material is cut out is not a
// hit (valid = 0), and the ray goes on to the next triangle.
void alphaFilter(const RTCFilterFunctionNArguments* args) {
  const auto* m = static_cast<const AlphaMask*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const uint32_t* t = &m->indices[size_t(prim) * 3u];
    // Embree's barycentrics: hit = (1 - u - v) p0 + u p1 + v p2.
    const glm::vec2 uv = (1.0f - u - v) * m->uv[t[0]] + u * m->uv[t[1]] + v * m->uv[t[2]];
    float alpha = m->base_alpha;
    if (m->image) alpha *= textureAlpha(*m->image, m->sampler, uv);
    if (alpha < m->cutoff) args->valid[i] = 0;
  }
}

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("reference visibility: Embree ") + what +
                             " failed (RTCError " + std::to_string(int(e)) + ")");
  }
}

}  // namespace

struct SceneVisibility::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaMask>> masks;  // geometry user data; outlive the scene
  size_t triangles = 0, masked = 0;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

SceneVisibility::SceneVisibility(const Scene& s) : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.device = rtcNewDevice(nullptr);
  if (!im.device) {
    throw std::runtime_error("reference visibility: Embree rtcNewDevice failed (RTCError " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  }
  im.scene = rtcNewScene(im.device);
  // Robust traversal: a ray through a shared edge or vertex of two triangles hits one of them
  // (no leak through the seams of a closed occluder).
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(im.scene, RTC_BUILD_QUALITY_HIGH);
  for (const Object& o : s.objects) {
    for (int mi : o.meshes) {
      if (mi < 0 || size_t(mi) >= s.meshes.size()) continue;
      const Mesh& mesh = s.meshes[size_t(mi)];
      // Triangles whose indices are in range, as the G-buffer pass can draw them.
      std::vector<uint32_t> tri;
      tri.reserve(mesh.indices.size());
      for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        if (std::max({a, b, c}) >= mesh.vertices.size()) continue;
        tri.insert(tri.end(), {a, b, c});
      }
      if (tri.empty()) continue;
      RTCGeometry g = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                             RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                             mesh.vertices.size()));
      auto* ib = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
          g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), tri.size() / 3));
      check(im.device, "rtcSetNewGeometryBuffer");
      for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const glm::vec3 p = glm::vec3(o.transform * glm::vec4(mesh.vertices[v].position, 1.0f));
        vb[3 * v] = p.x, vb[3 * v + 1] = p.y, vb[3 * v + 2] = p.z;
      }
      std::copy(tri.begin(), tri.end(), ib);
      const Material* mat = mesh.material >= 0 && size_t(mesh.material) < s.materials.size()
                                ? &s.materials[size_t(mesh.material)]
                                : nullptr;
      if (mat && mat->alpha_mode == AlphaMode::Mask) {
        auto m = std::make_unique<AlphaMask>();
        const TextureRef& t = mat->base_color_tex;
        if (t.valid() && size_t(t.image) < s.images.size()) {
          m->image = &s.images[size_t(t.image)];
          m->sampler = t.sampler;
        }
        m->uv.reserve(mesh.vertices.size());
        for (const Vertex& v : mesh.vertices) m->uv.push_back(t.texcoord == 1 ? v.uv1 : v.uv0);
        m->indices = std::move(tri);
        m->base_alpha = mat->base_alpha;
        m->cutoff = mat->alpha_cutoff;
        rtcSetGeometryUserData(g, m.get());
        rtcSetGeometryOccludedFilterFunction(g, alphaFilter);
        rtcSetGeometryIntersectFilterFunction(g, alphaFilter);
        im.masked += m->indices.size() / 3;
        im.triangles += m->indices.size() / 3;
        im.masks.push_back(std::move(m));
      } else {
        im.triangles += tri.size() / 3;
      }
      rtcCommitGeometry(g);
      rtcAttachGeometry(im.scene, g);
      rtcReleaseGeometry(g);
      check(im.device, "geometry creation");
    }
  }
  rtcCommitScene(im.scene);
  check(im.device, "rtcCommitScene");
}

SceneVisibility::~SceneVisibility() = default;

bool SceneVisibility::occluded(const glm::vec3& origin, const glm::vec3& dir, float tfar) const {
  if (impl_->triangles == 0 || !(tfar > 0.0f)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
  ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

size_t SceneVisibility::triangles() const {
  return impl_->triangles;
}
size_t SceneVisibility::maskedTriangles() const {
  return impl_->masked;
}

glm::vec3 rayOrigin(const glm::vec3& P, const glm::vec3& N, const glm::vec3& eye) {
  const float scale = std::max(glm::length(P), glm::length(P - eye));
  return P + N * (kRayOffset * scale);
}

}  // namespace hv::reference_detail
