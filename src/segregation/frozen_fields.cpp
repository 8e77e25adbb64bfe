#include "segregation/frozen_fields.hpp"

#include "core/error.hpp"

#include <cmath>
#include <string>

namespace granseg {

void check_frozen_fields(const Grid& grid, const FrozenFields& fields) {
    const std::size_t cells = grid.cells();
    if (fields.Phi.size() != cells) throw InputError("segregation: Phi must have one value per cell");
    for (double v : fields.Phi)
        if (!(v >= 0.0 && v < 1.0)) throw InputError("segregation: Phi outside [0, 1)");
    for (int axis = 0; axis < 3; ++axis) {
        const auto& a = fields.a[axis];
        if (!a.empty() && a.size() != cells)
            throw InputError("segregation: a along axis " + std::to_string(axis) + " needs one value per cell");
        for (double v : a)
            if (!std::isfinite(v)) throw InvariantError("segregation: non-finite coefficient a");
        for (const FaceFields* f : {&fields.Phi_face, &fields.a_face}) {
            const auto& face = (*f)[axis];
            if (!face.empty() && face.size() != grid.faces(axis))
                throw InputError("segregation: interface values need one value per face");
            for (double v : face)
                if (!std::isfinite(v)) throw InvariantError("segregation: non-finite interface value");
        }
    }
    if (!(fields.D >= 0.0) || !std::isfinite(fields.D)) throw InputError("segregation: need D >= 0");
}

}  // namespace granseg
