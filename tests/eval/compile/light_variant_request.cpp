// Compiled by two CTest tests (tests/CMakeLists.txt), not linked anywhere: as is, a request of a
// compiled light variant, which must compile; with HV_REQUEST_MISSING, a request of a combination
// that kEngineLightVariants does not hold (Implicit V is compiled for no light mode), which must
// fail to compile with the name of the function that says so.
#include "halfvec/eval/light_variants.hpp"

using namespace hv;
using namespace hv::eval;

#ifdef HV_REQUEST_MISSING
constexpr EngineLightOptions kRequest{.sphere_specular = SphereSpecular::Ltc,
                                      .v = VisibilityTerm::Implicit};
#else
constexpr EngineLightOptions kRequest{.sphere_specular = SphereSpecular::Ltc,
                                      .tube_specular = TubeSpecular::Ltc,
                                      .v = VisibilityTerm::SmithGGXCorrelated};
#endif
constexpr CompiledLightVariant kVariant = compiledLightVariant(LightTerm::Specular, kRequest);
static_assert(kVariant.variant().term == LightTerm::Specular);
