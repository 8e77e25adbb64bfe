#include "segregation/frozen_fields.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granseg {

void check_frozen_fields(const Grid& grid, const FrozenFields& fields) {
    const std::size_t cells = grid.cells();
    if (fields.Phi.size() != cells) throw std::invalid_argument("segregation: Phi must have one value per cell");
    for (double v : fields.Phi)
        if (!(v >= 0.0 && v < 1.0)) throw std::invalid_argument("segregation: Phi outside [0, 1)");
    for (int axis = 0; axis < 3; ++axis) {
        const auto& a = fields.a[axis];
        if (!a.empty() && a.size() != cells)
            throw std::invalid_argument("segregation: a along axis " + std::to_string(axis) + " needs one value per cell");
        for (double v : a)
            if (!std::isfinite(v)) throw std::invalid_argument("segregation: non-finite coefficient a");
        for (const FaceFields* f : {&fields.Phi_face, &fields.a_face}) {
            const auto& face = (*f)[axis];
            if (!face.empty() && face.size() != grid.faces(axis))
                throw std::invalid_argument("segregation: interface values need one value per face");
            for (double v : face)
                if (!std::isfinite(v)) throw std::invalid_argument("segregation: non-finite interface value");
        }
    }
    if (!(fields.D >= 0.0) || !std::isfinite(fields.D)) throw std::invalid_argument("segregation: need D >= 0");
}

}  // namespace granseg
