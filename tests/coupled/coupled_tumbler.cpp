// The coupled drum's pieces on small grids: the bulk step written like the mass balance (a uniform
// phi_hat of 1/2 carried exactly, its Courant number), the drum's fill fraction and angle of
// repose, a few coupled steps with S = 0, a segregating drum with either bulk transport, the
// segregation sub-step in every flow step, the flow without packing feedback as the flow alone, a
// passive tracer riding in a segregating drum, a drum of one phase only, the diagnostic that
// switches the segregation off below a shear rate, and the default step's acoustic bound.
#include "coupled/coupled_tumbler.hpp"
#include "closures/closures.hpp"
#include "coupled/coupled_run.hpp"
#include "direction/segregation_direction.hpp"
#include "drum/bed.hpp"
#include "drum/drum.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/invariants.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(coupled_tumbler_tests)

BOOST_AUTO_TEST_CASE(bulk_step_carries_half_exactly_and_reports_its_courant_number) {
    const Grid g = drum_grid(12, 1.0);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> Phi(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c)) Phi[c] = 0.1 + 0.5 * unit(random);
    FaceFields M;
    for (int axis : {0, 2}) {
        M[axis].assign(g.faces(axis), 0.0);
        for_each_face(g, axis, [&](const FaceCells& f) {
            if (is_open_face(g, f)) M[axis][f.face] = 0.2 * (unit(random) - 0.5);
        });
    }
    const double dt = bulk_time_step(g, Phi, M, 0.9);
    // The mass balance as the flow solver writes it: the sum over the axes first, one subtraction.
    std::vector<double> Phi_new(g.cells(), 0.0), phi(g.cells(), 0.0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            if (!g.is_inside(c)) continue;
            double net = 0.0;
            for (int axis : {0, 2}) {
                const std::size_t lower = g.face_index(axis, i, 0, k);
                net += (M[axis][lower + g.face_stride(axis)] - M[axis][lower]) * (1.0 / g.h[axis]);
            }
            Phi_new[c] = Phi[c] - dt * net;
            phi[c] = 0.5 * Phi[c];
        }
    BulkTransport bulk(g);
    const double courant = bulk.step(Phi, refs(M), FaceFields{}, dt, phi);
    long not_half = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) not_half += g.is_inside(c) && phi[c] != 0.5 * Phi_new[c];
    BOOST_TEST(not_half == 0);
    BOOST_TEST(courant == 0.9, tt::tolerance(1e-14));  // dt was 0.9 of the step that empties a cell
}

BOOST_AUTO_TEST_CASE(fill_fraction_and_angle_of_repose) {
    DrumSpec drum;
    drum.cells_per_diameter = 200;
    const Grid g = drum.grid();
    double filled = 0.0;
    for (double f : drum_fill_fraction(drum, g)) filled += f;
    // The part of the disc below the surface at height d has area R^2 (acos(-d/R) + (d/R) sqrt(1 - d^2/R^2));
    // the staircase wall changes it by O(h R): well within 1 % at 200 cells.
    const double R = drum.radius(), d = drum.surface_height() / R;
    const double exact = R * R * (std::acos(-d) + d * std::sqrt(1 - d * d));
    BOOST_TEST(filled * g.h[0] * g.h[2] == exact, tt::tolerance(0.01));
    TimeAverage angle(1.0);
    angle.add(0.5, 90.0);  // before `from`: left out
    angle.add(1.0, 20.0);
    angle.add(2.0, NAN);  // no surface crossing: left out
    angle.add(3.0, 30.0);
    BOOST_TEST(angle.samples() == 2);
    BOOST_TEST(angle.mean() == 25.0);
    BOOST_TEST(angle.std_dev() == 5.0, tt::tolerance(1e-12));
    TimeAverage none(1.0);  // a diagnostic never defined (e.g. the layer of a drum at rest)
    none.add(2.0, NAN);
    BOOST_TEST(std::isnan(none.mean()));
    BOOST_TEST(std::isnan(none.std_dev()));
}

BOOST_AUTO_TEST_CASE(no_segregation_keeps_phi_hat_half_and_both_phases) {
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    setup.S = 0.0;
    CoupledTumbler tumbler(setup);
    BOOST_TEST(tumbler.initial_mixture() == 0.5);
    const Grid& g = tumbler.grid();
    const double small0 = total_amount(g, tumbler.phi()), all0 = tumbler.flow().mass();
    for (int n = 0; n < 200; ++n) tumbler.step();
    long not_half = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) not_half += g.is_inside(c) && tumbler.phi()[c] != 0.5 * tumbler.flow().Phi()[c];
    BOOST_TEST(not_half == 0);
    BOOST_TEST(total_amount(g, tumbler.phi()) == small0, tt::tolerance(1e-14));
    BOOST_TEST(tumbler.flow().mass() == all0, tt::tolerance(1e-14));
    BOOST_TEST(tumbler.split_segregation_steps() >= 1);
}

BOOST_AUTO_TEST_CASE(either_transport_keeps_both_phases_and_the_bounds_while_segregating) {
    // The paper's first-order transport stays selectable: the same segregating drum (S = 1) with
    // `donor-cell` and with `muscl` keeps both phases to round-off and 0 <= phi <= Phi in every
    // cell (to the segregation step's round-off clip), and the two runs differ (the key is read).
    std::vector<double> phi_of[2];
    int k = 0;
    for (const Transport transport : {Transport::donor_cell, Transport::muscl}) {
        CoupledTumblerSetup setup;
        setup.drum.cells_per_diameter = 26;
        setup.flow.transport = transport;
        CoupledTumbler tumbler(setup);
        const Grid& g = tumbler.grid();
        const double small0 = total_amount(g, tumbler.phi()), all0 = tumbler.flow().mass();
        double below = 0.0, above = 0.0;
        for (int n = 0; n < 200; ++n) {
            tumbler.step();
            for (std::size_t c = 0; c < g.cells(); ++c) {
                if (!g.is_inside(c)) continue;
                below = std::max(below, -tumbler.phi()[c]);
                above = std::max(above, tumbler.phi()[c] - tumbler.flow().Phi()[c]);
            }
        }
        BOOST_TEST(below <= 0.0);
        BOOST_TEST(above <= 0.0);
        BOOST_TEST(total_amount(g, tumbler.phi()) == small0, tt::tolerance(1e-13));
        BOOST_TEST(tumbler.flow().mass() == all0, tt::tolerance(1e-13));
        phi_of[k++] = tumbler.phi();
    }
    double differ = 0.0;
    for (std::size_t c = 0; c < phi_of[0].size(); ++c) differ = std::max(differ, std::fabs(phi_of[0][c] - phi_of[1][c]));
    BOOST_TEST(differ > 1e-6);
}

BOOST_AUTO_TEST_CASE(the_segregation_sub_step_covers_every_flow_step) {
    // With packing feedback Phi_rcp and Phi_co follow phi_hat: a segregation sub-step that covered a
    // stretch of time of its own (several flow steps at once) changed them in jumps that one flow
    // step absorbed, an error that did not vanish with dt (assumption C1). Every flow step takes one
    // sub-step over its own dt, so the amount phi_hat moves per step shrinks with dt.
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    CoupledTumbler tumbler(setup);
    for (int n = 0; n < 100; ++n) tumbler.step();
    BOOST_TEST(tumbler.split_segregation_steps() == tumbler.flow().steps());
    BOOST_TEST(tumbler.segregation_solver_steps() >= tumbler.flow().steps());
}

BOOST_AUTO_TEST_CASE(without_packing_feedback_the_flow_is_the_flow_alone) {
    // The flow does not see phi when Phi_rcp and Phi_co keep the initial mixture's values (C3): the
    // coupled drum's Phi and u are bitwise those of the flow solver alone on the same drum (the
    // tumbler-flow scene's set-up), so the time-step study reads the flow alone's angle from it.
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    setup.packing_feedback = false;
    CoupledTumbler tumbler(setup);
    FlowSettings settings = setup.flow;
    settings.phi_hat = tumbler.initial_mixture();
    const Grid grid = setup.drum.grid();
    FlowSolver alone(grid, setup.material, settings, setup.drum.frame());
    const std::vector<double> zero(grid.cells(), 0.0), T(grid.cells(), settings.T_floor);
    alone.set_state(drum_bed_at_rest(setup.drum, grid, setup.material, settings.phi_hat, settings.T_floor), {zero, zero, zero},
                    T);
    for (int n = 0; n < 100; ++n) tumbler.step(), alone.step();
    BOOST_TEST(alone.time() == tumbler.time());
    long differ = 0;
    for (std::size_t c = 0; c < grid.cells(); ++c)
        differ += alone.Phi()[c] != tumbler.flow().Phi()[c] || alone.u(0)[c] != tumbler.flow().u(0)[c] ||
                  alone.u(2)[c] != tumbler.flow().u(2)[c] || alone.T()[c] != tumbler.flow().T()[c];
    BOOST_TEST(differ == 0);
}

// A passive tracer in the full model (S = 1, packing feedback): it does not act on the flow or on
// phi (both bitwise those of the same drum without it), keeps its amount to round-off and
// 0 <= tau <= Phi, and a tracer filling the whole drum (tau = Phi) stays tau = Phi: the bulk step
// carries a uniform share exactly.
BOOST_AUTO_TEST_CASE(a_passive_tracer_rides_without_acting) {
    CoupledTumblerSetup plain;
    plain.drum.cells_per_diameter = 26;
    CoupledTumblerSetup marked = plain, full = plain;
    marked.tracer0 = [](double x, double z) { return std::hypot(x, z) < 0.015 ? 1.0 : 0.0; };
    full.tracer0 = [](double, double) { return 1.0; };
    CoupledTumbler a(plain), b(marked), c(full);
    const Grid& g = b.grid();
    const double tracer0 = total_amount(g, b.tracer());
    BOOST_TEST(tracer0 > 0.0);
    BOOST_TEST(a.tracer().empty());
    double below = 0.0, above = 0.0;
    long not_full = 0;
    for (int n = 0; n < 200; ++n) {
        a.step(), b.step(), c.step();
        for (std::size_t i = 0; i < g.cells(); ++i) {
            if (!g.is_inside(i)) continue;
            below = std::max(below, -b.tracer()[i]);
            above = std::max(above, b.tracer()[i] - b.flow().Phi()[i]);
        }
    }
    for (std::size_t i = 0; i < g.cells(); ++i) not_full += g.is_inside(i) && c.tracer()[i] != c.flow().Phi()[i];
    BOOST_TEST(below <= 0.0);
    BOOST_TEST(above <= 0.0);
    BOOST_TEST(total_amount(g, b.tracer()) == tracer0, tt::tolerance(1e-13));
    BOOST_TEST(not_full == 0);
    BOOST_TEST((a.phi() == b.phi()));
    BOOST_TEST((a.flow().Phi() == b.flow().Phi()));
}

BOOST_AUTO_TEST_CASE(a_drum_of_small_particles_only_runs_with_an_empty_phase) {
    // The run's invariants measure both phases against all material: a phase that starts empty
    // (phi_hat = 1 everywhere) has no amount of its own to divide by (it once stopped the run
    // with a change of NaN at t = 0).
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    setup.phi_hat0 = [](double, double) { return 1.0; };
    CoupledTumbler tumbler(setup);
    CoupledRunOptions options;
    options.run.t_end = 0.1, options.run.angle_from = 0.0, options.run.vtk = false, options.frames = 0;
    options.regions = coupled_regions(setup.drum, surface_level(setup.material, 1.0));
    OutputSet files;
    BOOST_CHECK_NO_THROW(files = run_coupled_tumbler(tumbler, options));
    long not_all = 0;
    const Grid& g = tumbler.grid();
    for (std::size_t c = 0; c < g.cells(); ++c) not_all += g.is_inside(c) && tumbler.phi()[c] != tumbler.flow().Phi()[c];
    BOOST_TEST(not_all == 0);
}

// [segregation] diagnostic_min_shear_rate: off (0, the default) the sub-step's d_s is bitwise the
// direction of Sect. 2.3 with D1's own threshold, recomputed here from the flow's fields; above
// every cell's shear rate nothing segregates (phi_hat stays 1/2 bitwise, as with S = 0).
BOOST_AUTO_TEST_CASE(the_shear_rate_diagnostic_is_off_by_default_and_stops_all_segregation_above_every_shear_rate) {
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    BOOST_TEST(setup.diagnostic_min_shear_rate == 0.0);
    CoupledTumblerSetup blocked = setup;
    blocked.diagnostic_min_shear_rate = 1e6;  // 1/s, far above any shear rate of this drum
    CoupledTumbler a(setup), b(blocked);
    for (int n = 0; n < 200; ++n) a.step(), b.step();
    const Grid& g = a.grid();
    const FlowSolver& f = a.flow();
    DirectionOptions before;  // the sub-step's options without the diagnostic
    before.planar_xz = true;
    long differ = 0, not_half = 0, segregating = 0;
    double largest_shear = 0.0;
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c)) continue;
        not_half += b.phi()[c] != 0.5 * b.flow().Phi()[c];
        largest_shear = std::max(largest_shear, b.direction(c).principal_shear);
        if (!(f.Phi()[c] >= setup.Phi_min)) continue;
        Eigen::Matrix3d G;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) G(i, j) = f.velocity_gradient(i, j)[c];
        const Eigen::Vector3d d = segregation_direction(G, {f.u(0)[c], f.u(1)[c], f.u(2)[c]}, before).d_s;
        differ += d(0) != a.d_s(0)[c] || d(2) != a.d_s(2)[c];
        segregating += d.squaredNorm() > 0.0;
    }
    BOOST_TEST(differ == 0);
    BOOST_TEST(segregating > 0);
    BOOST_TEST(largest_shear > 0.0);
    BOOST_TEST(largest_shear < blocked.diagnostic_min_shear_rate);
    BOOST_TEST(not_half == 0);
}

// A moderate threshold (the median shear rate of the bed): the creeping cells at or below it get no
// segregation velocity, the faster-sheared ones keep theirs, and the drum still segregates.
BOOST_AUTO_TEST_CASE(a_moderate_shear_rate_threshold_switches_only_the_creeping_cells_off) {
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    CoupledTumbler probe(setup);
    for (int n = 0; n < 200; ++n) probe.step();
    const Grid& g = probe.grid();
    std::vector<double> shear;
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c) && probe.flow().Phi()[c] >= setup.Phi_min) shear.push_back(probe.direction(c).principal_shear);
    std::nth_element(shear.begin(), shear.begin() + shear.size() / 2, shear.end());
    setup.diagnostic_min_shear_rate = shear[shear.size() / 2];
    BOOST_TEST(setup.diagnostic_min_shear_rate > 1e-6);  // above D1's own threshold

    CoupledTumbler tumbler(setup);
    for (int n = 0; n < 200; ++n) tumbler.step();
    long creeping = 0, creeping_moving = 0, sheared = 0, sheared_moving = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c) || !(tumbler.flow().Phi()[c] >= setup.Phi_min)) continue;
        const bool moves = tumbler.frozen().a[0][c] != 0.0 || tumbler.frozen().a[2][c] != 0.0;
        const SegregationDirection d = tumbler.direction(c);
        if (d.principal_shear <= setup.diagnostic_min_shear_rate)
            ++creeping, creeping_moving += moves;
        else if (d.segregates())
            ++sheared, sheared_moving += moves;
    }
    BOOST_TEST(creeping > 0);
    BOOST_TEST(creeping_moving == 0);
    BOOST_TEST(sheared > 0);
    BOOST_TEST(sheared_moving == sheared);
    long not_half = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) not_half += g.is_inside(c) && tumbler.phi()[c] != 0.5 * tumbler.flow().Phi()[c];
    BOOST_TEST(not_half > 0);
}

BOOST_AUTO_TEST_CASE(the_default_step_is_at_most_two_acoustic_times_of_a_cell) {
    // At 60 cells per diameter two acoustic times h/c of the packed bed are shorter than dt_max
    // (1 ms), so the coupled drum's own Courant number (kCoupledAcousticCourantMax, C9) sets the
    // step; at the flow solver's five acoustic times the same drum takes dt_max. S = 0 keeps
    // phi_hat = 1/2, and with it Phi_rcp and Phi_co, in every cell.
    struct LastStep {
        double dt, dt_acoustic;  // the step taken, and two h/c at its start
        StepBound bound;
    };
    auto run = [](const FlowSettings& flow) {
        CoupledTumblerSetup setup;
        setup.drum.cells_per_diameter = 60;
        setup.S = 0.0;
        setup.flow = flow;
        CoupledTumbler tumbler(setup);
        for (int n = 0; n < 40; ++n) tumbler.step();
        const FlowSolver& f = tumbler.flow();
        const Material& m = setup.material;
        const double rcp = m.packing.Phi_rcp(0.5), co = m.packing.Phi_co(0.5);
        double c_max = 0.0;  // the largest sound speed at the start of the last step, from which its dt is set
        for (std::size_t c = 0; c < tumbler.grid().cells(); ++c)
            if (tumbler.grid().is_inside(c))
                c_max = std::max(c_max, std::sqrt(evaluate_closures_at(m, f.Phi()[c], f.T()[c], rcp, co).c2));
        tumbler.step();
        return LastStep{f.last_dt(), kCoupledAcousticCourantMax * tumbler.grid().h[0] / c_max, f.last_bound()};
    };
    FlowSettings five = coupled_flow_settings();
    five.acoustic_courant_max = FlowSettings{}.acoustic_courant_max;
    const LastStep coupled = run(coupled_flow_settings()), flow_solver = run(five);
    BOOST_TEST(coupled_flow_settings().acoustic_courant_max == kCoupledAcousticCourantMax);
    BOOST_TEST(std::string(step_bound_name(coupled.bound)) == "acoustic");
    BOOST_TEST(coupled.dt <= coupled.dt_acoustic * (1.0 + 1e-9));  // the same sound speeds, up to round-off
    BOOST_TEST(coupled.dt < 0.9 * kCoupledDtMax);
    BOOST_TEST(std::string(step_bound_name(flow_solver.bound)) == "dt_max");
    BOOST_TEST(flow_solver.dt == kCoupledDtMax);
}

BOOST_AUTO_TEST_SUITE_END()
