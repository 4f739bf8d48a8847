"""Inputs that would run for hours or fill the memory are refused up front, in one line naming the key.

The time step against the Hertz contact time of the case (contact.timestep.check_time_step: at most 2e7 steps per
contact, 2e6 with time histories), the erosion patch's memory ((runs + 1) x frames + 6 grid² float64 arrays, at
most 2 GB; grid at most 2048 in a case) and the response table's size (at most 2000 impacts). Each refusal must
come before any heavy work: the tests time it.
"""

import time
import tracemalloc

import pytest

from contact import Material, effective_modulus, simulate_impact, simulate_impacts, theory
from contact.timestep import MAX_HISTORY_STEPS, MAX_STEPS, check_time_step
from fem.solid.mesh import generate_block
from wear import WearLaw, run
from wear.app.cli import main
from wear.case import Case, check_job_case, default_case
from wear.case.budget import MAX_MEMORY, MAX_SECONDS, fitting_value, memory_budget
from wear.case.work import (
    REPEAT_BLOCK_PASS,
    fe_elements,
    fe_memory,
    fe_seconds,
    repeat_block_impacts,
    solid_elements,
    solid_seconds,
    wear_grid_memory,
)
from wear.chain.forward_model import BYTES_PER_ROW
from wear.chain.indent import indent_case
from wear.chain.plate import case_mesh
from wear.erosion import ImpactResponse, Stream, build_response_table, erode, erode_angles, erode_case, table_axes
from wear.erosion.memory import check_patch_memory, patch_memory
from wear.erosion.table import MAX_TABLE_ENTRIES

ALUMINA = Material(E=380e9, nu=0.23, density=4000.0)
GLASS = Material(E=70e9, nu=0.25, density=2500.0)
QUICK = 1.0  # s: a refusal must come before any impact, FE solve or patch array


def _contact_time(speed: float = 3.9) -> float:
    """Hertz contact time (s) of the impact command's default, alumina R 2.5 mm on glass, at a normal ``speed``."""
    mass = theory.sphere_mass(2.5e-3, 4000.0)
    return theory.hertz_impact(mass, 2.5e-3, effective_modulus(ALUMINA, GLASS), speed).contact_time


def _refused(call, match: str) -> str:
    start = time.perf_counter()
    with pytest.raises(ValueError, match=match) as info:
        call()
    assert time.perf_counter() - start < QUICK
    message = str(info.value)
    assert "\n" not in message
    return message


# ---------------------------------------------------------------- the time step


def test_library_refuses_a_time_step_of_too_many_steps_before_running():
    msg = _refused(
        lambda: simulate_impact(2.5e-3, ALUMINA, GLASS, 3.9, 30.0, 0.1, time_step=1e-15, history=False),
        r"^time_step=1e-15 s gives ~1\.\de10 steps over the Hertz contact time",
    )
    assert "at most 2e7" in msg and "give time_step >= " in msg


def test_history_bound_is_tighter_and_scales_with_history_every():
    tc = _contact_time(3.9)
    dt = tc / (3 * MAX_HISTORY_STEPS)  # 6e6 steps: fine without histories, too many kept steps with them
    _refused(
        lambda: simulate_impact(2.5e-3, ALUMINA, GLASS, 3.9, 0.0, 0.1, time_step=dt),
        r"^time_step=.* at most 2e6 with time histories",
    )
    assert check_time_step(dt, tc) == dt
    assert check_time_step(dt, tc, histories=True, history_every=4) == dt
    with pytest.raises(ValueError, match=r"^time_step=.*at most 2e7"):
        check_time_step(tc / (2 * MAX_STEPS), tc, histories=True, history_every=1000)


def test_bound_uses_the_longest_contact_of_a_batch():
    # the slowest impact of the batch has the longest contact: the bound is checked on it
    tc_slow = _contact_time(0.01)
    dt = 0.5 * tc_slow / MAX_STEPS * 1.5  # fine for 3.9 m/s, 1.33x too many steps at 0.01 m/s
    _refused(
        lambda: simulate_impacts(2.5e-3, ALUMINA, GLASS, [3.9, 0.01], 0.0, 0.1, time_step=dt),
        r"^time_step=.*steps over the Hertz contact time",
    )


def test_time_steps_the_toolkit_uses_pass():
    tc = _contact_time(3.9)
    r = simulate_impact(2.5e-3, ALUMINA, GLASS, 3.9, 0.0, 0.1, time_step=tc / 51200)  # the validation's finest
    assert r.steps == pytest.approx(51200, rel=1e-3)
    assert check_time_step(tc / MAX_STEPS * 1.001, tc) > 0.0  # just inside


def test_case_names_impact_time_step():
    msg = _refused(lambda: Case().with_(impact={"time_step": 1e-20}), r"^impact\.time_step=1e-20 s gives ~")
    assert "at most 2e7" in msg and "give impact.time_step >= " in msg
    _refused(lambda: Case().with_(impact={"time_step": 1e-3}), r"^impact\.time_step=0\.001 is out of range")
    # the default (None: t_c/2000) and a fine time step pass; the histories' bound is asked for by the chains
    case = Case().with_(impact={"time_step": 1e-12})
    assert case.impact_arguments(history=False)["time_step"] == 1e-12
    _refused(lambda: case.impact_arguments(history=True), r"^impact\.time_step=1e-12 s .* with time histories")


@pytest.mark.parametrize(
    "argv, key",
    [
        (["impact", "--time-step", "1e-15"], "impact.time_step=1e-15"),
        (["impact", "--set", "impact.time_step=1e-20"], "impact.time_step=1e-20"),
        (["run", "--set", "impact.time_step=1e-20"], "impact.time_step=1e-20"),
        (["run", "--set", "impact.time_step=1e-12"], "impact.time_step=1e-12"),  # passes 2e7, not 2e6 with histories
        (["erode", "--set", "erosion.grid=8192"], "erosion.grid=8192"),
        (["erode", "--set", "erosion.grid=2048", "--set", "erosion.frames=100"], "erosion.grid=2048"),
        (["erode", "--set", "erosion.angle_step=0.1", "--set", "erosion.angle_margin=45"], "erosion.angle_step=0.1"),
    ],
)
def test_cli_one_line_exit_2_quickly(argv, key, tmp_path, capsys):
    if argv[0] in ("run", "erode"):
        argv = [*argv, "--out", str(tmp_path / "out")]
    start = time.perf_counter()
    assert main(argv) == 2
    assert time.perf_counter() - start < 5.0  # the runs would take minutes to hours
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and key in err, err
    assert err.startswith(f"impactwear {argv[0]}: error: ")


# ---------------------------------------------------------------- the erosion patch and table


def test_schema_grid_range_and_print_default():
    keys = Case().erosion.keys()
    assert keys["grid"].high == 2048
    assert default_case("erode").with_(erosion={"grid": 2048}).erosion.grid == 2048
    _refused(
        lambda: default_case("erode").with_(erosion={"grid": 8192}),
        r"^erosion\.grid=8192 is out of range: .* in \[16, 2048\]",
    )


def test_patch_memory_refused_naming_grid_and_frames():
    case = default_case("erode").with_(erosion={"grid": 2048, "frames": 100})
    msg = _refused(lambda: erode_case(case), r"^erosion\.grid=2048 with erosion\.frames=100 needs ~6\.91 GB")
    limit = memory_budget()  # 2 GB, or half this machine's memory if less
    frames = int((limit / (8.0 * 2048**2) - 6.0) // 2)  # ((1 + 1) frames + 6) 2048² 8 B <= limit
    assert f"at most {limit / 1e9:.3g} GB on this machine" in msg and f"erosion.frames <= {frames}" in msg
    # several stream angles keep every run's frames: 4 angles x 10 frames on 2048² is 1.9 GB, 8 angles too much
    _refused(
        lambda: erode_angles(default_case("erode").with_(erosion={"grid": 2048}), [10.0 * k for k in range(8)]),
        r"^erosion\.grid=2048 with erosion\.frames=10 and 8 stream angles",
    )
    assert patch_memory(2048, 10, 4) < 2e9 < patch_memory(2048, 10, 8)
    check_patch_memory(512, 10)  # the default: 55 MB


def test_response_table_size_refused_before_any_impact():
    case = default_case("erode").with_(erosion={"angle_step": 0.1, "angle_margin": 45.0, "table_speeds": 50})
    msg = _refused(lambda: erode_case(case), r"^erosion\.angle_step=0\.1 over erosion\.angle_margin=45 deg")
    assert f"at most {MAX_TABLE_ENTRIES}" in msg

    def never(*_):
        raise AssertionError("no impact may run")

    vn, angles = table_axes(20.0, 45.0, angle_margin=45.0, angle_step=0.5, speeds=30)
    _refused(
        lambda: build_response_table(never, vn, angles, particle_radius=1e-4, particle_mass=1e-8, plate_density=7850.0),
        r"^normal_speeds, angles: 30 x 171",
    )


def test_patch_memory_estimate_bounds_the_measured_peak():
    """The estimate is conservative: tracemalloc's peak of a small erosion (256², 10 frames) is below it."""
    sand = Material(E=94e9, nu=0.17, density=2650.0)
    steel = Material(E=200e9, nu=0.3, density=7850.0, yield_strength=350e6)
    response = ImpactResponse(
        100e-6, sand, steel, 0.3, WearLaw(K=1e-11, alpha=1.0, beta=0.3), pressure="hertz", points_across=40
    )
    vn, angles = table_axes(20.0, 45.0, angle_margin=5.0, angle_step=5.0, speeds=2)
    table = build_response_table(response, vn, angles, points_per_length=6)
    stream = Stream(20.0, 45.0, 0.5, concentration=0.464)
    erode(table, stream, grid=64, seed=1, frames=1, samples=2)  # compile or load the kernel first
    tracemalloc.start()
    result = erode(table, stream, grid=256, seed=1, frames=10, samples=5)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert result.n_impacts > 0
    assert 0.5 * patch_memory(256, 10) < peak < patch_memory(256, 10)
    _refused(lambda: erode(table, stream, grid=4096, frames=10), r"^grid=4096 with frames=10 needs ~3\.49 GB")


# ---------------------------------------------------------------- the FE plate, the wear grid and the calibration


def test_fitting_value_is_the_brute_force_bound_either_way():
    def need(n):
        return 3.0 * n * n

    assert fitting_value(need, 300.0, 1, 1000) == max(n for n in range(1, 1001) if need(n) <= 300.0) == 10
    # a need that falls with the value (a mesh size): the smallest value that fits, to 1e-3
    assert fitting_value(lambda s: 1.0 / s**2, 16.0, 8.0, 0.1, integer=False) == pytest.approx(0.25, rel=1e-3)
    assert fitting_value(need, 1.0, 1, 1000) is None
    assert memory_budget() <= MAX_MEMORY


def _fe_run_seconds(passes: int, steps: int = 24) -> float:
    return fe_seconds(default_case("run").fem.mesh_scale, steps, passes)


def _largest(need, limit: float, start: int) -> int:
    """The largest n >= start with need(n) <= limit, counted up one by one (the reference for the bisection)."""
    n = start
    while need(n + 1) <= limit:
        n += 1
    return n


def test_runaway_keys_refused_before_any_work_naming_the_value_that_fits(tmp_path, capsys):
    """The issue's runaways: each one line naming the key, its value and the value that fits (from the same
    estimate, counted up here), within a second, nothing written."""
    run_case = default_case("run")
    grid = _largest(lambda n: wear_grid_memory(run_case, n), memory_budget(), 64)
    # the impacts computed one by one, then those between the cycle-jump blocks of the rest of the 10^5
    repeat_case = default_case("repeat").with_(repeat={"impacts": 100000})
    plastic = _largest(
        lambda n: fe_seconds(
            run_case.fem.mesh_scale,
            24,
            n + REPEAT_BLOCK_PASS * repeat_block_impacts(repeat_case.with_(repeat={"max_plastic_impacts": n}), 100000),
        ),
        MAX_SECONDS,
        20,
    )
    steps = _largest(lambda n: _fe_run_seconds(8, n + 8), MAX_SECONDS, 16)
    cases = [
        (
            ["repeat", "--impacts", "1e5", "--set", "repeat.max_plastic_impacts=100000"],
            "repeat.max_plastic_impacts=100000 needs ~",
            f"give repeat.max_plastic_impacts <= {plastic}",
        ),
        (["run", "--set", "fem.load_steps=2000"], "fem.load_steps=2000 needs ~", f"give fem.load_steps <= {steps}"),
        (
            ["run", "--set", "wear.points_across=2000"],
            "wear.points_across=2000 needs ~",
            f"give wear.points_across <= {grid}",
        ),
        (["indent", "--set", "fem.mesh_scale=0.25"], "fem.mesh_scale=0.25 needs ~", "give fem.mesh_scale >= 0.2"),
    ]
    for argv, named, fix in cases:
        out = tmp_path / "out"
        start = time.perf_counter()
        assert main([*argv, "--out", str(out)]) == 2
        assert time.perf_counter() - start < 2 * QUICK
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and named in err and fix in err, err
        assert not out.exists()
    # the mesh scale that fits is the one whose estimated memory is the budget
    (line,) = _refused_cli(["indent", "--set", "fem.mesh_scale=0.25"], tmp_path, capsys)
    smallest = float(line.rsplit(">= ", 1)[1])
    assert fe_memory(smallest) <= memory_budget() < fe_memory(smallest * 0.999)


def _refused_cli(argv, tmp_path, capsys):
    assert main([*argv, "--out", str(tmp_path / "out")]) == 2
    return capsys.readouterr().err.strip().splitlines()


def test_calibration_of_too_many_rows_refused_naming_the_file(tmp_path, capsys, monkeypatch):
    """Refused before any impact is run (the impacts of 200,000 rows took minutes): the batch engine is replaced by
    one that fails the test if called. A law that runs the impacts (a closed form such as dnv runs none, and fits
    200,000 rows)."""
    data = tmp_path / "data.csv"
    data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n" + "30,40,1e-4\n" * 200_000, encoding="utf-8")
    base, per_row = BYTES_PER_ROW
    rows = _largest(lambda n: base + per_row * n, memory_budget(), 1)

    def no_impacts(*args, **kwargs):
        raise AssertionError("the impacts were run before the refusal")

    monkeypatch.setattr("wear.chain.forward_model.simulate_impacts", no_impacts)
    (line,) = _refused_cli(["calibrate", str(data), "--law", "local"], tmp_path, capsys)
    assert f"data={str(data)!r}: rows=200000 needs ~" in line and f"give rows <= {rows}" in line
    assert not (tmp_path / "out").exists()


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_default_cases_fit_and_the_element_estimate_bounds_the_meshes():
    """The default cases pass; the element estimate is at or above the meshes the plate is built on (generated
    here at the default case's overlap), within 40%."""
    for job in ("run", "repeat", "indent"):
        check_job_case(default_case(job), job)
    # a repeat computes at most its impacts one by one: few impacts fit whatever max_plastic_impacts says
    check_job_case(default_case("repeat").with_(repeat={"impacts": 5, "max_plastic_impacts": 100000}), "repeat")
    case = default_case("run")
    for scale in (2.0, 1.0, 0.5):
        elements = case_mesh(case.with_(fem={"mesh_scale": scale}), 2e-5).t.shape[1]
        assert elements <= fe_elements(scale) <= 1.4 * elements


def test_three_d_plate_runaways_refused_and_the_measured_runs_fit(tmp_path, capsys):
    """The 3-D plate's estimate (wear.case.work): its default run and the 5-impact repeat that was measured (33 min,
    docs/repeat-record.md) pass; 200 load increments or a mesh twice as fine are refused naming the key and the
    value that fits (counted up here from the same estimate); its element count is within its stated band of the
    blocks the plate is built on (generated here, oblique track ±0.3 a_max)."""
    solid = default_case("run").with_(fem={"model": "3d"})
    check_job_case(solid, "run")
    check_job_case(default_case("repeat").with_(fem={"model": "3d"}, repeat={"impacts": 5}), "repeat")
    steps = _largest(lambda n: solid_seconds(2.0, n + 6, 20, 1), MAX_SECONDS, 2)
    argv = ["run", "--set", "fem.model='3d'", "--set", "fem.solid_load_steps=200", "--set", "fem.solid_iterations=20"]
    (line,) = _refused_cli(argv, tmp_path, capsys)
    assert "fem.solid_load_steps=200 needs ~" in line and f"give fem.solid_load_steps <= {steps}" in line, line
    (line,) = _refused_cli(["run", "--set", "fem.model='3d'", "--set", "fem.mesh_scale=0.5"], tmp_path, capsys)
    assert "fem.mesh_scale=0.5 needs ~" in line and "give fem.mesh_scale >= " in line, line
    assert not (tmp_path / "out").exists()
    for across in (3, 4, 6):
        elements = generate_block(across, track=(-0.3, 0.3)).t.shape[1]
        assert 0.75 * elements <= solid_elements(8.0 / across) <= 1.3 * elements


def test_library_entry_points_refuse_the_runaways_too():
    _refused(lambda: run(default_case("run").with_(fem={"load_steps": 2000})), r"^fem\.load_steps=2000 needs ~")
    indent = default_case("indent").with_(fem={"mesh_scale": 0.25})
    _refused(lambda: indent_case(indent), r"^fem\.mesh_scale=0\.25 needs ~")
