// Images (decoded by gltf_loader.cpp's callback, moved here), textures with their samplers and
// KHR_texture_transform.
#include "gltf_import.hpp"

namespace hv::gltf {

void Importer::importImage(int i) {
  tinygltf::Image& im = m_.images[size_t(i)];
  const std::string el = idx("images", size_t(i));
  ImageData out;
  out.name = im.name.empty() ? (im.uri.empty() || im.uri.size() > 256 ? el : im.uri) : im.name;
  // decodeImage produced every decoded image as 8-bit RGBA within the budgets.
  if (im.image.empty() || im.width <= 0 || im.height <= 0 || im.component != 4 || im.bits != 8 ||
      im.image.size() != size_t(im.width) * size_t(im.height) * 4) {
    fail(el, "image could not be loaded or decoded" +
                 (im.uri.empty() || im.uri.size() > 256 ? "" : " (" + im.uri + ")"));
  }
  out.width = im.width;
  out.height = im.height;
  out.rgba = std::move(im.image);
  images.push_back(std::move(out));
}

// KHR_texture_transform on a textureInfo (`exts` its extensions): offset, rotation, scale and
// the texCoord that replaces the textureInfo's own.
void Importer::textureTransform(const tinygltf::ExtensionMap& exts, TextureRef& r, int& texcoord,
                                const std::string& el) {
  noteExtensions(exts, el);
  const auto it = exts.find("KHR_texture_transform");
  if (it == exts.end()) return;
  const tinygltf::Value& v = it->second;
  const std::string xel = el + ".extensions.KHR_texture_transform";
  if (!v.IsObject()) fail(xel, "expected an object");
  if (v.Has("offset")) r.uv_offset = extVec2(v, "offset", xel);
  if (v.Has("rotation")) r.uv_rotation = extNumber(v, "rotation", xel);
  if (v.Has("scale")) r.uv_scale = extVec2(v, "scale", xel);
  if (v.Has("texCoord")) {
    const tinygltf::Value& tc = v.Get("texCoord");
    if (!tc.IsInt()) fail(xel + ".texCoord", "expected an integer");
    texcoord = tc.GetNumberAsInt();
  }
}

TextureRef Importer::texture(int tex_index, int texcoord, const tinygltf::ExtensionMap& exts,
                             const std::string& el) {
  TextureRef r;
  if (tex_index < 0) return r;
  if (tex_index >= int(m_.textures.size())) fail(el, "texture index out of range");
  const tinygltf::Texture& t = m_.textures[size_t(tex_index)];
  textureTransform(exts, r, texcoord, el);
  if (texcoord < 0 || texcoord > 1)
    fail(el, "texCoord " + std::to_string(texcoord) + " not supported (0 or 1)");
  r.texcoord = texcoord;
  if (t.source < 0) {
    warn(el + ": texture has no source image (extension-only source?); ignored");
    return r;
  }
  if (t.source >= int(m_.images.size())) fail(el, "texture source out of range");
  r.image = image_base_ + t.source;
  if (t.sampler >= 0) {
    if (t.sampler >= int(m_.samplers.size())) fail(el, "sampler index out of range");
    r.sampler = samplerOf(m_.samplers[size_t(t.sampler)], el);
  }
  return r;
}

// A textureInfo inside an extension's object (tinygltf parses only the core's): index (required),
// texCoord, its extensions (KHR_texture_transform) and, for a normal map, scale.
TextureRef Importer::textureInfo(const tinygltf::Value& t, const std::string& el) {
  if (!t.IsObject()) fail(el, "expected a textureInfo object");
  if (!t.Has("index") || !t.Get("index").IsInt() || t.Get("index").GetNumberAsInt() < 0) {
    fail(el + ".index", "expected a texture index");
  }
  if (t.Has("texCoord") && !t.Get("texCoord").IsInt())
    fail(el + ".texCoord", "expected an integer");
  const int tc = t.Has("texCoord") ? t.Get("texCoord").GetNumberAsInt() : 0;
  tinygltf::ExtensionMap exts;
  if (t.Has("extensions") && t.Get("extensions").IsObject()) {
    const tinygltf::Value& e = t.Get("extensions");
    for (const std::string& k : e.Keys()) exts[k] = e.Get(k);
  }
  TextureRef r = texture(t.Get("index").GetNumberAsInt(), tc, exts, el);
  if (t.Has("scale")) r.scale = extNumber(t, "scale", el);
  return r;
}

// A glTF sampler's wrap modes and filters; `el` is the textureInfo that uses it, for messages.
Sampler Importer::samplerOf(const tinygltf::Sampler& s, const std::string& el) const {
  Sampler out;
  auto wrap = [&](int w) {
    switch (w) {
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return Wrap::ClampToEdge;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return Wrap::MirroredRepeat;
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return Wrap::Repeat;
      default:
        fail(el, "bad sampler wrap mode " + std::to_string(w));
    }
  };
  out.wrap_s = wrap(s.wrapS);
  out.wrap_t = wrap(s.wrapT);
  out.mag = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
  switch (s.minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      out.min = Filter::Nearest, out.mipmaps = false;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      out.min = Filter::Linear, out.mipmaps = false;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      out.min = Filter::Nearest;
      break;
    default:
      out.min = Filter::Linear;
      break;  // LINEAR_MIPMAP_* or unset
  }
  return out;
}

}  // namespace hv::gltf
