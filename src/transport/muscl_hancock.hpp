// Second-order upwind face values of a cell field for one explicit transport step: limited
// linear reconstruction with a half-step predictor (MUSCL-Hancock; van Leer, SIAM J. Sci. Stat.
// Comput. 5, 1984; Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", 3rd ed.
// 2009, Sect. 14.4), unsplit in 2-D and 3-D. The flow's mass balance carries Phi with these face
// values (flow/faces/semi_implicit_faces.hpp), the bulk transport phi_hat (segregation/bulk_transport_fct.hpp).
//
//   solves      nothing over time: the face values q_f of a cell field q for a step of length dt
//   inputs      the grid (inside cells, periodic axes) and the limiter, once; per step q per cell,
//               the face velocities U per axis (walls: 0), dt and the form of the balance
//   outputs     per face of each active axis the value its lower cell gives it (what a flow
//               upwards carries) and the value its upper cell gives it (a flow downwards)
//   invariants  each value lies between the smallest and the largest q of the cell that gives it
//               and of that cell's face neighbours (so q >= 0 gives face values >= 0 and a phi_hat
//               in [0, 1] face values in [0, 1]); a uniform q gives q; q linear in space carried by
//               a uniform U gives the exact value at the face half-way through the step
//
// Per inside cell c and active axis a, the slope s_a = limited_slope(q_c - q_below, q_above - q_c)
// with the neighbours along a (s_a = 0 next to a wall: first order there). The value half-way
// through the step, from the cell's own reconstruction and the velocities U_b- and U_b+ on its lower
// and upper face along each active axis b:
//     conservative (d_t q + div(q u) = 0, the mass balance of eq. 8):
//         q_c' = q_c - dt/2 sum_b [U_b+ (q_c + s_b/2) - U_b- (q_c - s_b/2)]/h_b
//     advective (d_t q + u . grad q = 0, a composition carried by the bulk flow):
//         q_c' = q_c - dt/2 sum_b (U_b- + U_b+)/2 s_b/h_b
// and the cell gives its upper face along a the value q_c' + s_a/2, its lower face q_c' - s_a/2, each
// clipped to the range of q over c and its face neighbours. In one dimension with a uniform U > 0
// the upper face gets q_c + (1 - U dt/h) s/2, the Lax-Wendroff face value of a limited slope
// (Fromm's scheme where the limiter is inactive); the transverse terms (b != a) are what keeps the
// unsplit step second order in time when the flow crosses the faces obliquely (Colella, J. Comput.
// Phys. 87, 1990: corner transport). The clip makes the values bounded whatever the velocities; in
// smooth regions it is inactive.
#pragma once

#include "core/face_fields.hpp"
#include "core/grid.hpp"
#include "transport/limiter.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace granseg {

class MusclHancock {
public:
    /// Which balance q obeys (header comment).
    enum class Form { conservative, advective };

    /// Lists the inside cells with their neighbours and faces once (the grid's walls do not move).
    MusclHancock(const Grid& grid, Limiter limiter);

    /// The face values of q for a step dt with the face velocities U (one field per active axis,
    /// grid.faces(axis) values; 0 on walls): from_lower() and from_upper() afterwards.
    void face_values(const std::vector<double>& q, const FaceFieldRefs& U, double dt, Form form);

    /// Per axis and face: the value the cell below the face gives it (used where U > 0).
    const FaceFields& from_lower() const { return from_lower_; }
    /// Per axis and face: the value the cell above the face gives it (used where U < 0).
    const FaceFields& from_upper() const { return from_upper_; }
    Limiter limiter() const { return limiter_; }

private:
    /// An inside cell with, per axis, its neighbours (kNoCell across a wall) and its faces; on a
    /// periodic axis the boundary face also stands in the other layer (alias, kNoCell otherwise).
    struct Cell {
        std::size_t c;
        std::array<std::size_t, 3> below, above, lower_face, upper_face, lower_alias, upper_alias;
    };

    std::array<double, 3> h_{};
    std::array<bool, 3> active_{};
    Limiter limiter_;
    bool parallel_;
    std::vector<Cell> cells_;
    FaceFields from_lower_, from_upper_;
};

}  // namespace granseg
