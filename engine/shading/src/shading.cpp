#include "halfvec/shading/shading.hpp"
