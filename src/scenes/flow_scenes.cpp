// Scene kinds bed-at-rest, simple-shear and inclined-plane (keys: docs/scenes.md); the shared
// [flow] reader and the job that runs a prepared flow problem and writes its profiles.
#include "scenes/flow_scenes.hpp"

#include "closures/closures.hpp"
#include "core/format.hpp"
#include "drum/drum_state.hpp"
#include "flow/flow_loop.hpp"
#include "flow/flow_tables.hpp"
#include "scenes/material_section.hpp"

#include <cmath>

namespace granseg {

FlowSettings read_flow_settings(const SceneFile& scene, bool mixture, const FlowSettings& defaults) {
    const std::string s = "flow";
    FlowSettings f = defaults;
    f.time_stepping =
        parse_choice(kTimeSteppings,
                     scene.choice(s, "time_stepping", choice_names(kTimeSteppings), choice_name(kTimeSteppings, f.time_stepping)),
                     "time_stepping");
    f.viscosity = parse_choice(
        kViscositySolves,
        scene.choice(s, "viscosity", choice_names(kViscositySolves), choice_name(kViscositySolves, viscosity_solve(f))),
        "viscosity");
    f.factorisation = parse_choice(
        kFactorisations,
        scene.choice(s, "factorisation", choice_names(kFactorisations), choice_name(kFactorisations, f.factorisation)),
        "factorisation");
    f.cfl = scene.number(s, "cfl", Range::left_open(0, 1), f.cfl);
    f.T_floor = scene.number(s, "T_floor", Range::open(0, 1e-2), f.T_floor);
    f.Phi_vacuum = scene.number(s, "Phi_vacuum", Range::open(0, 1e-3), f.Phi_vacuum);
    f.dt_min = scene.number(s, "dt_min", Range::open(0, 1), f.dt_min);
    f.dt_max = scene.number(s, "dt_max", Range::open(0, 10), f.dt_max);
    f.pressure_tolerance = scene.number(s, "pressure_tolerance", Range::open(0, 1), f.pressure_tolerance);
    f.face_smoothing = parse_choice(
        kFaceSmoothings,
        scene.choice(s, "face_smoothing", choice_names(kFaceSmoothings), choice_name(kFaceSmoothings, f.face_smoothing)),
        "face_smoothing");
    f.smoothing_time_max = scene.number(s, "smoothing_time_max", Range::open(0, 10), f.smoothing_time_max);
    f.acoustic_courant_max = scene.number(s, "acoustic_courant_max", Range::open(0, 1e6), f.acoustic_courant_max);
    if (mixture) f.phi_hat = scene.number(s, "phi_hat", Range::closed(0, 1), f.phi_hat);
    f.transport = parse_choice(
        kTransports, scene.choice(s, "transport", choice_names(kTransports), choice_name(kTransports, transport_scheme(f))),
        "transport");
    f.limiter = parse_limiter(scene.choice(s, "limiter", limiter_names(), limiter_name(f.limiter)));
    if (transport_scheme(f) == Transport::muscl && f.time_stepping != TimeStepping::semi_implicit)
        scene.fail(s, "transport", "\"muscl\" with time_stepping = \"explicit\"",
                   "\"donor-cell\" with the explicit step; \"muscl\" needs \"semi-implicit\"");
    if (!(f.dt_min < f.dt_max)) scene.fail(s, "dt_min", format_number(f.dt_min) + " >= dt_max", "dt_min < dt_max");
    return f;
}

namespace {

/// A prepared flow problem: solver set-up, initial state, run length; writes the final profiles
/// (columns) or fields (2-D) and a history of global quantities.
struct FlowJob : SceneJob {
    std::string label;
    Grid grid;
    Material material;
    FlowSettings settings;
    Frame frame;
    std::vector<double> Phi, T;
    std::array<std::vector<double>, 3> u;
    std::array<std::array<Vec3, 2>, 3> walls{};
    double t_end = 0.0;
    int history_samples = 200;

    explicit FlowJob(Material m) : material(std::move(m)) {}

    OutputSet run() override {
        FlowSolver solver(grid, material, settings, frame);
        for (int a = 0; a < 3; ++a)
            for (int side = 0; side < 2; ++side) solver.set_wall_velocity(a, side, walls[a][side]);
        solver.set_state(Phi, u, T);
        DataTable history;
        history.comment(
            label +
            ": mass = sum Phi dV (m^3 per m^(3-d)), mass_change relative to t = 0, kinetic energy sum Phi |u|^2/2 dV (rho* = 1)");
        double mass0 = solver.mass(),
               next = 0.0;  // rows every t_end/history_samples (from the checkpoint's next on, after a resume)
        auto sample = [&] {
            if (solver.time() < next && solver.time() < t_end) return;
            next += t_end / history_samples;
            const DrumState d = drum_state(solver, 0.0, 0.0, 0.0);
            double PhiT = 0.0, sum = 0.0;
            for (std::size_t c = 0; c < grid.cells(); ++c)
                if (grid.is_inside(c)) PhiT += solver.Phi()[c] * solver.T()[c], sum += solver.Phi()[c];
            history.row({{"t", solver.time()},
                         {"steps", static_cast<double>(solver.steps())},
                         {"mass", solver.mass()},
                         {"mass_change", solver.mass() / mass0 - 1.0},
                         {"kinetic_energy", d.kinetic_energy},
                         {"max_speed", d.max_speed},
                         {"T_mean", sum > 0 ? PhiT / sum : 0.0},
                         {"dt", solver.last_dt()}});
        };
        const RunState state = [&](StateIO& io) { io("flow", solver)("history", history)("mass0", mass0)("next", next); };
        run_flow(solver, t_end, label, sample, checkpoints, state);
        OutputSet out;
        out.add("history.dat", history);
        if (grid.n[0] == 1 && grid.n[1] == 1)
            out.add("profile.dat", flow_column_table(solver));
        else
            out.add("fields.dat", flow_field_table(solver, false));
        return out;
    }
};

/// Reads [grid] nz and height (and nx, width when `plane`), building a column or an x-z box.
Grid read_box(const SceneFile& scene, bool plane, bool periodic_x) {
    const std::string s = "grid";
    const long nz = scene.integer(s, "nz", 2, 100000);
    const double height = scene.number(s, "height", Range::above(0));
    const long nx = plane ? scene.integer(s, "nx", 1, 100000, 1) : 1;
    const double width = plane ? scene.number(s, "width", Range::above(0), height / nz * nx) : height / nz;
    Grid g = Grid::plane_xz(static_cast<int>(nx), static_cast<int>(nz), 0.0, 0.0, width, height);
    g.periodic[0] = periodic_x;
    return g;
}

/// Fills `field` from an expression in x, z at every cell centre; every value must lie in `range`.
void fill(const SceneFile& scene, const std::string& section, const std::string& key, const Expression& e, const Grid& g,
          std::vector<double>& field, const Range& range) {
    field.assign(g.cells(), 0.0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const double v = e({g.center(0, i), g.center(2, k)});
            if (!range.contains(v))
                scene.fail(
                    section, key,
                    format_number(v) + " at x = " + format_number(g.center(0, i)) + ", z = " + format_number(g.center(2, k)),
                    range.describe(key));
            field[g.index(i, 0, k)] = v;
        }
}

std::unique_ptr<FlowJob> common(const SceneFile& scene, const std::string& label, Grid grid) {
    auto job = std::make_unique<FlowJob>(read_material(scene));
    job->label = label;
    job->grid = std::move(grid);
    job->settings = read_flow_settings(scene);
    job->t_end = scene.number("run", "t_end", Range::above(0));
    for (auto& v : job->u) v.assign(job->grid.cells(), 0.0);
    return job;
}

/// Phi must stay below Phi_rcp(phi_hat) of the [flow] mixture.
Range packing_range(const FlowJob& job) { return Range::right_open(0, job.material.packing.Phi_rcp(job.settings.phi_hat)); }

}  // namespace

std::unique_ptr<SceneJob> prepare_bed_at_rest(const SceneFile& scene) {
    auto job = common(scene, "bed-at-rest", read_box(scene, true, false));
    job->frame.gravity = scene.number("run", "gravity", Range::at_least(0), 9.81);
    if (job->frame.gravity > 0.0) require_yield_pressure(scene, job->material);
    const std::vector<std::string> xz = {"x", "z"};
    fill(scene, "bed", "Phi", scene.expression("bed", "Phi", xz), job->grid, job->Phi, packing_range(*job));
    fill(scene, "bed", "T", scene.expression("bed", "T", xz, "1e-12"), job->grid, job->T, Range::at_least(0));
    return job;
}

std::unique_ptr<SceneJob> prepare_simple_shear(const SceneFile& scene) {
    auto job = common(scene, "simple-shear", read_box(scene, false, true));
    job->frame.gravity = 0.0;
    const std::string s = "shear";
    const double U = scene.number(s, "U", Range::any());
    job->walls[2][0] = {-0.5 * U, 0.0, 0.0};  // the walls move along x at -U/2 (bottom) and +U/2 (top)
    job->walls[2][1] = {0.5 * U, 0.0, 0.0};
    const double Phi = scene.number(s, "Phi", packing_range(*job));
    job->Phi.assign(job->grid.cells(), Phi);
    const double T =
        scene.number(s, "T", Range::at_least(0), steady_shear_temperature(job->material, U / job->grid.n[2] / job->grid.h[2]));
    job->T.assign(job->grid.cells(), T);
    return job;
}

std::unique_ptr<SceneJob> prepare_inclined_plane(const SceneFile& scene) {
    auto job = common(scene, "inclined-plane", read_box(scene, false, true));
    const std::string s = "plane";
    job->frame.gravity = scene.number("run", "gravity", Range::above(0), 9.81);
    require_yield_pressure(scene, job->material);
    job->frame.tilt = scene.number(s, "angle_deg", Range::open(-90, 90)) * M_PI / 180.0;
    const std::vector<std::string> z = {"z"};
    const Expression Phi = scene.expression(s, "Phi", z), T = scene.expression(s, "T", z, "1e-12"),
                     u = scene.expression(s, "u", z, "0");
    const Range rcp = packing_range(*job);
    for (int k = 0; k < job->grid.n[2]; ++k) {
        const double zc = job->grid.center(2, k);
        job->Phi.push_back(Phi({zc}));
        job->T.push_back(T({zc}));
        job->u[0][k] = u({zc});
        if (!rcp.contains(job->Phi.back()))
            scene.fail(s, "Phi", format_number(job->Phi.back()) + " at z = " + format_number(zc), rcp.describe("Phi"));
        if (!(job->T.back() >= 0) || !std::isfinite(job->u[0][k]))
            scene.fail(s, job->T.back() >= 0 ? "u" : "T", "not finite or negative at z = " + format_number(zc), "finite, T >= 0");
    }
    return job;
}

}  // namespace granseg
