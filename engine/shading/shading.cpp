#include "shading/shading.hpp"
