// The binding points every pass of the renderer shares, for its gl::PassBindings scope (private to
// engine/render; the slots themselves: shaders/common/bindings.glsl).
#pragma once

#include "halfvec/gl/bindings.hpp"
#include "halfvec/shaders/common/bindings.glsl"

namespace hv::render {

// The 8 storage slots, the uniform slots up to HV_UBO_CULL_BATCH, texture units up to
// HV_UNIT_COAT, image units up to HV_IMAGE_AO, each rounded up to a GL 4.5 minimum;
// the frame block (HV_UBO_FRAME) stays bound for the whole frame (Renderer::frameUniforms).
constexpr gl::BindingSlots kPassSlots{8, 8, 16, 8, 1u << HV_UBO_FRAME};
static_assert(HV_UBO_SUN_SHADOWS < 8 && HV_UNIT_SUN_SHADOW_COMPARE < 16 && HV_UNIT_COAT < 16 &&
              HV_IMAGE_AO < 8);

}  // namespace hv::render
