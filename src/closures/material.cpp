#include "closures/material.hpp"

#include <cmath>

namespace granseg {

Material Material::glass_substitute() { return Material{PackingFit(builtin_packing_table(), kDefaultPackingDegree)}; }

double Material::shear_friction() const { return std::sqrt(2.0 * eta0 * eps0 / 3.0); }

}  // namespace granseg
