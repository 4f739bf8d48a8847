"""A new user's malformed and extreme inputs across all nine commands, each refused cleanly.

The table rebuilds the trial behind "the trial's bad inputs re-run give >= 190 clean": bad values of every kind of
case key (out of range, wrong type, NaN/inf, negative, zero), unknown and mistyped keys and tables, malformed TOML,
duplicate keys, bad ``--set`` syntax, bad options of each command, bad calibration data, bad sweep files, runaway
sizes and bad output folders. Each row is refused by :func:`refusal.refused`: exit status 2, one stderr line naming
what the user gave (the option or key as typed, or the file, column and row) and its value, nothing written. The
commands' work functions are replaced by a tripwire, so that a row not refused before any work fails at once
instead of running. A few rows run ``impactwear`` in a subprocess, the end-to-end path.
"""

from __future__ import annotations

import json
import shlex
import subprocess
import sys
import time
from pathlib import Path

import pytest
from refusal import refused, snapshot

from wear.app.outputs.folder import MANIFEST

DATA = "angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n45,20,2e-5\n60,20,1.5e-5\n"
HEAD = "angle_deg,speed_m_s,erosion_kg_per_kg\n"
SWEEP = '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 30]\n'


class WorkStarted(BaseException):
    """Raised by the tripwire: the command started its work on an input it should have refused."""


#: Where each command's work starts, as the module calling it imported it: the command's runner, or, where the
#: runner checks its inputs first (the erosion's memory, the calibration's free constants and rows), its first work.
WORK = {
    "run": ("wear.app.commands.run.run", "wear.app.commands.run.write_run"),
    "repeat": ("wear.app.commands.repeat.repeat",),
    "erode": ("wear.erosion.run.build_response_table",),
    "indent": ("wear.app.commands.indent.indent_case",),
    "impact": ("wear.app.commands.impact.simulate_impact",),
    "calibrate": (
        "wear.chain.forward_model.ForwardModel._batched",
        "wear.chain.forward_model.ForwardModel._coupled",
        "wear.chain.forward_model.ForwardModel._closed_form",
    ),
    "sweep": ("wear.app.commands.sweep.run_sweep",),
    "reproduce": ("wear.app.commands.reproduce.reproduce",),
    "validate": ("wear.app.commands.validate.run_validation",),
}


@pytest.fixture
def tripwire(monkeypatch):
    def trip(*_args, **_kwargs):
        raise WorkStarted

    for names in WORK.values():
        for name in names:
            monkeypatch.setattr(name, trip)


# (argv, the substrings the line must hold, files). {case}, {data}, {sweep} are files holding the row's text (the
# data and sweep files default to good ones); {file} is a user's file, {userdir} a folder of user files, {calibrated}
# and {ran} the output folders of calibrate and run, {missing} a path that does not exist, {binary} a binary file.
ROWS: list = []  # pytest.param(argv, named, files)


def row(argv: str, *named: str | tuple[str, ...], xfail: str = "", **files: str | bytes) -> None:
    flat = tuple(n for name in named for n in ((name,) if isinstance(name, str) else name))
    marks = [pytest.mark.xfail(reason=xfail, raises=WorkStarted, strict=True)] if xfail else []
    ROWS.append(pytest.param(argv, flat, files, marks=marks, id=f"{argv} [{flat[0] if flat else ''}]"))


# ---- every kind of case key through --set: out of range, zero, negative, NaN/inf, wrong type
for text, *named in [
    ("ball.radius=0", "ball.radius=0"),
    ("ball.radius=-1e-3", "ball.radius=-0.001"),
    ("ball.radius=11", "ball.radius=11"),
    ("ball.radius=[1,2]", "ball.radius=[1, 2]"),
    ("ball.E=1e3", "ball.E=1000"),
    ("ball.nu=-0.1", "ball.nu=-0.1"),
    ("ball.density=0", "ball.density=0"),
    ("ball.density=nan", "ball.density=nan"),
    ("ball.yield_strength=10", "ball.yield_strength=10"),
    ("ball.name=3", "ball.name=3"),
    ("plate.rigid=yes", "plate.rigid='yes'"),
    ("plate.E=-inf", "plate.E=-inf"),
    ("plate.nu=0.6", "plate.nu=0.6"),
    ("plate.density=1e6", "plate.density=1e+06"),
    ("plate.yield_strength=-1", "plate.yield_strength=-1"),
    ("plate.hardness=1e3", "plate.hardness=1000"),
    ("plate.name=true", "plate.name=True"),
    ("impact.speed=0", "impact.speed=0"),
    ("impact.speed=-3", "impact.speed=-3"),
    ("impact.speed=inf", "impact.speed=inf"),
    ('impact.speed="3"', "impact.speed='3'"),
    ("impact.speed={a=1}", "impact.speed="),
    ("impact.angle=90", "impact.angle=90"),
    ("impact.angle=-1", "impact.angle=-1"),
    ("impact.angle=inf", "impact.angle=inf"),
    ("impact.friction=11", "impact.friction=11"),
    ("impact.friction=-0.1", "impact.friction=-0.1"),
    ("impact.friction=-inf", "impact.friction=-inf"),
    ("impact.restitution=0", "impact.restitution=0"),
    ("impact.restitution=1.5", "impact.restitution=1.5"),
    ("impact.normal_model=hertzian", "impact.normal_model='hertzian'"),
    ("impact.tangential_model=coulomb", "impact.tangential_model='coulomb'"),
    ("impact.limiting_pressure=0", "impact.limiting_pressure=0"),
    ("impact.scheme=euler", "impact.scheme='euler'"),
    ("impact.time_step=0", "impact.time_step=0"),
    ("impact.time_step=-1e-9", "impact.time_step=-1e-09"),
    ("wear.law=archard", "wear.law='archard'"),
    ("wear.K=2e-3", "wear.K=0.002"),
    ("wear.K=nan", "wear.K=nan"),
    ("wear.alpha=5", "wear.alpha=5"),
    ("wear.beta=-1", "wear.beta=-1"),
    ("wear.pressure=contact", "wear.pressure='contact'"),
    ("wear.speed=fast", "wear.speed='fast'"),
    ("wear.points_across=39", "wear.points_across=39"),
    ("wear.points_across=64.5", "wear.points_across=64.5"),
    ("wear.cutting=ideal", "wear.cutting='ideal'"),
    ("wear.cutting_fraction=0", "wear.cutting_fraction=0"),
    ("wear.force_ratio=0.05", "wear.force_ratio=0.05"),
    ("wear.depth_ratio=25", "wear.depth_ratio=25"),
    ("wear.deformation_factor=1", "wear.deformation_factor=1"),
    ("wear.oka_e90=2", "wear.oka_e90=2"),
    ("wear.oka_k2=0.1", "wear.oka_k2=0.1"),
    ("wear.dnv_K=0", "wear.dnv_K=0"),
    ("wear.dnv_n=6", "wear.dnv_n=6"),
    ("fem.coupling=full", "fem.coupling='full'"),
    ("fem.tolerance=0", "fem.tolerance=0"),
    ("fem.max_iterations=1", "fem.max_iterations=1"),
    ("fem.load_steps=1", "fem.load_steps=1"),
    ("fem.unload_steps=0", "fem.unload_steps=0"),
    ("fem.overshoot=3", "fem.overshoot=3"),
    ("fem.mesh_scale=9", "fem.mesh_scale=9"),
    ("fem.model=2d", "fem.model='2d'"),
    ("fem.solid_iterations=0", "fem.solid_iterations=0"),
    ("fem.solid_load_steps=201", "fem.solid_load_steps=201"),
    ("fem.solid_unload_steps=-1", "fem.solid_unload_steps=-1"),
    ("output.figures=1", "output.figures=1"),
    ("output.render=maybe", "output.render='maybe'"),
    ("output.block_thickness=0", "output.block_thickness=0"),
    ("output.plate_mesh=7", "output.plate_mesh=7"),
]:
    row(f"run --set {shlex.quote(text)}", *named)

# ---- --set syntax, unknown and mistyped keys and tables, tables a command does not read
for argv, *named in [
    ("run --set impact.angle", "--set"),
    ("run --set =3", "--set"),
    ("run --set impact=3", "impact=3"),
    ("run --set impact.angle=", "impact.angle"),
    ("run --set impact.angle.x=3", "impact.angle.x"),
    ("run --set impcat.angle=3", "impcat"),
    ("run --set impact.angel=3", "impact.angel"),
    ("run --set impact.speed=3..0", "impact.speed='3..0'"),
    ("""run --set 'impact.angle="30'""", "impact.angle"),
    ("run --set erosion.grid=64", "erosion.grid"),
    ("run --set repeat.impacts=5", "repeat.impacts"),
    ("run --set calibration.data=x.csv", "calibration.data"),
    ("impact --set fem.load_steps=10", "fem.load_steps"),
    ("impact --set wear.K=1e-10", "wear.K"),
    ("indent --set wear.law=dnv", "wear.law"),
    ("erode --set repeat.impacts=3", "repeat.impacts"),
    ("calibrate {data} --set erosion.grid=64", "erosion.grid"),
    ("repeat --set erosion.grid=64", "erosion.grid"),
    ("repeat --set calibration.free=K", "calibration.free"),
    ("repeat --set repeat.impact=5", "repeat.impact"),
]:
    row(argv, *named)

# ---- case files: malformed TOML, duplicates, wrong types, unknown tables and keys, unreadable files
for text, *named in [
    ("[ball]\nradius = \n", "case.toml"),
    ("[ball]\nradius = 1e-3 1e-3\n", "case.toml"),
    ("[ball\nradius = 1e-3\n", "case.toml"),
    ("ball.radius = 1e-3\nball.radius = 2e-3\n", "ball.radius"),
    ("[plate]\nE = 1e11\nE = 2e11\n", "plate.E"),
    ("[wear]\nK = 1e-11\n[wear]\nalpha = 1\n", "[wear]"),
    ("[ball]\nradius = '1e-3'\n", "ball.radius='1e-3'"),
    ("[ball]\nradius = true\n", "ball.radius=True"),
    ("[plate]\nrigid = 'true'\n", "plate.rigid='true'"),
    ("[impact]\nangle = [30, 45]\n", "impact.angle=[30, 45]"),
    ("[wear]\npoints_across = 64.5\n", "wear.points_across=64.5"),
    ("[fem]\nload_steps = 'many'\n", "fem.load_steps='many'"),
    ("[ball]\nradiuss = 1e-3\n", "ball.radiuss"),
    ("[Ball]\nradius = 1e-3\n", "[Ball]"),
    ("[output]\nfigures = 'no'\n", "output.figures='no'"),
    ("title = 'x'\n", "title"),
    ("[wear]\nK = inf\n", "wear.K=inf"),
    ("[impact]\nspeed = -inf\n", "impact.speed=-inf"),
    ("[wear]\nalpha = nan\n", "wear.alpha=nan"),
    ("[ball]\nradius = 1e-3\n[ball.extra]\nx = 1\n", "ball.extra"),
    ("[[ball]]\nradius = 1e-3\n", "ball"),
    ("[erosion]\ngrid = 8\n", "erosion.grid=8"),
    ("[repeat]\nimpacts = 'ten'\n", "repeat.impacts='ten'"),
    ("[calibration]\nfree = 3\n", "calibration.free=3"),
    ("[sweep]\nstage = 'run'\n", "sweep"),
]:
    row("run {case}", *named, case=text)
row("run {case}", "case.toml", case=b"\x00\x01\x02\xff\xfe" * 50)
row("run {case}", "case.toml", case="[ball]\nradius = 1e-3\n".encode("utf-16"))
row("run {missing}", "missing.toml")
row("run {userdir}", "userdir")
row("impact --config {missing}", "missing.toml")
row("impact --config {case}", "impact.angle=95", case="[impact]\nangle = 95\n")
row("indent --config {case}", "fem.mesh_scale=0.1", case="[fem]\nmesh_scale = 0.1\n")
row("repeat {case}", "repeat.impacts=0", case="[repeat]\nimpacts = 0\n")
row("erode {case}", "erosion.grid=8", case="[erosion]\ngrid = 8\n")
row("calibrate {data} {case}", "ball.radius=0", case="[ball]\nradius = 0\n")

# ---- impact's options
for argv, *named in [
    ("--radius 0", "ball.radius=0"),
    ("--radius abc", "--radius", "'abc'"),
    ("--speed nan", "impact.speed=nan"),
    ("--speed 1e9", "impact.speed=1e+09"),
    ("--angle 95", "impact.angle=95"),
    ("--friction -1", "impact.friction=-1"),
    ("--restitution 0", "impact.restitution=0"),
    ("--restitution 2", "impact.restitution=2"),
    ("--normal-model jkr", "impact.normal_model='jkr'"),
    ("--tangential-model coulomb", "impact.tangential_model='coulomb'"),
    ("--limiting-pressure -5", "impact.limiting_pressure=-5"),
    ("--scheme rk4", "impact.scheme='rk4'"),
    ("--time-step 0", "impact.time_step=0"),
    ("--time-step 1", "impact.time_step=1"),
    ("--bogus 3", "--bogus"),
    ("--speed", "--speed"),
    ("foo", "foo"),
]:
    row(f"impact {argv}", *named)

# ---- indent's options
for argv, *named in [
    ("--max-overlap 0", "--max-overlap=0"),
    ("--max-overlap 1", "--max-overlap=1"),
    ("--max-overlap nan", "--max-overlap=nan"),
    ("--max-force 0", "--max-force=0"),
    ("--max-force -5", "--max-force=-5"),
    ("--max-force inf", "--max-force=inf"),
    ("--max-overlap 1e-5 --max-force 1", "--max-force"),
    ("--radius -1", "ball.radius=-1"),
    ("--E 0", "plate.E=0"),
    ("--nu 0.7", "plate.nu=0.7"),
    ("--yield-strength -1", "plate.yield_strength=-1"),
    ("--load-steps 1", "fem.load_steps=1"),
    ("--load-steps 2.5", "--load-steps", "'2.5'"),
    ("--unload-steps 0", "fem.unload_steps=0"),
    ("--load-steps 5000", "fem.load_steps=5000"),
    ("--hardening -1", "--hardening=-1"),
    ("--hardening nan", "--hardening=nan"),
    ("--hardening abc", "--hardening", "'abc'"),
    ("--mesh {missing}", "--mesh", "missing.toml"),
    ("--mesh {binary}", "--mesh", "binary.bin"),
    ("--set fem.model=3d", "fem.model='3d'"),
    ("--set fem.mesh_scale=0.2", "fem.mesh_scale=0.2"),
]:
    row(f"indent {argv}", *named)

# ---- repeat's options and [repeat] keys
for argv, *named in [
    ("--impacts -5", "--impacts=-5"),
    ("--impacts nan", "--impacts=nan"),
    ("--impacts inf", "--impacts=inf"),
    ("--impacts 2e9", "--impacts=2e9"),
    ("--set repeat.impacts=0", "repeat.impacts=0"),
    ("--set repeat.shakedown_tolerance=0", "repeat.shakedown_tolerance=0"),
    ("--set repeat.surface_fraction=2", "repeat.surface_fraction=2"),
    ("--set repeat.max_plastic_impacts=0", "repeat.max_plastic_impacts=0"),
    ("--set repeat.save_every=-1", "repeat.save_every=-1"),
    ("--set repeat.wear_smoothing=1.5", "repeat.wear_smoothing=1.5"),
    ("--set repeat.geometry_update=1", "repeat.geometry_update=1"),
    ("--set repeat.elastic_after_shakedown=no", "repeat.elastic_after_shakedown='no'"),
]:
    row(f"repeat {argv}", *named)

# ---- erode's options and [erosion] keys
for argv, *named in [
    ("--angles 30,abc", "--angles='30,abc'"),
    ("--angles ''", "--angles=''"),
    ("--angles 90", "--angles", "angle=90"),
    ("--angles nan", "--angles", "angle=nan"),
    ("--angles '30;45'", "--angles='30;45'"),
    ("--seed -1", "erosion.seed=-1"),
    ("--seed abc", "--seed", "'abc'"),
    ("--seed 1.5", "--seed", "'1.5'"),
    ("--set erosion.concentration=0", "erosion.concentration=0"),
    ("--set erosion.mass_flux=-1", "erosion.mass_flux=-1"),
    ("--set erosion.exposure_time=0", "erosion.exposure_time=0"),
    ("--set erosion.exposure_time=1e11", "erosion.exposure_time=1e+11"),
    ("--set erosion.azimuth=400", "erosion.azimuth=400"),
    ("--set erosion.grid=15", "erosion.grid=15"),
    ("--set erosion.grid=100.5", "erosion.grid=100.5"),
    ("""--set 'erosion.grid="512"'""", "erosion.grid='512'"),
    ("--set erosion.patch_size=0", "erosion.patch_size=0"),
    ("--set erosion.seed=-1", "erosion.seed=-1"),
    ("--set erosion.frames=0", "erosion.frames=0"),
    ("--set erosion.samples=0", "erosion.samples=0"),
    ("--set erosion.samples=1e6", "erosion.samples=1e+06"),
    ("--set erosion.angle_margin=50", "erosion.angle_margin=50"),
    ("--set erosion.angle_step=0", "erosion.angle_step=0"),
    ("--set erosion.table_speeds=1", "erosion.table_speeds=1"),
    ("--set erosion.points_per_length=3", "erosion.points_per_length=3"),
    ("--set impact.angle=89", "impact.angle=89"),
    ("--set wear.law=deformation", "wear.deformation_factor"),
]:
    row(f"erode {argv}", *named)

# ---- calibrate: the data file (missing/duplicate columns, bad cells with their row and column, unreadable files)
for text, *named in [
    ("", ("data.csv",)),
    (HEAD, ("data.csv",)),
    ("angle_deg,erosion_kg_per_kg\n30,1e-5\n", ("speed_m_s",)),
    ("angle_deg,speed_m_s\n30,20\n", ("erosion_kg_per_kg",)),
    ("angle_deg,speed_m_s,volume_per_impact_m3,mass_per_impact_kg\n30,20,1e-12,1e-9\n", ("mass_per_impact_kg",)),
    ("Angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n", ("'angle_deg' is missing",)),
    ("angle_deg,speed_m_s,erosion_kg_per_kg,erosion_kg_per_kg\n30,20,1e-5,1e-5\n", ("erosion_kg_per_kg", "2 times")),
    (HEAD + "30,20,1e-5\nabc,20,1e-5\n", ("angle_deg='abc'", "row 2")),
    (HEAD + "30,20,inf\n", ("erosion_kg_per_kg='inf'", "row 1")),
    (HEAD + "30,0,1e-5\n", ("speed_m_s=0", "row 1")),
    (HEAD + "30,-20,1e-5\n", ("speed_m_s=-20", "row 1")),
    (HEAD + "30,20\n", ("row 1",)),
    (HEAD + "30,20,1e-5,7\n", ("row 1",)),
    ("angle_deg,speed_m_s,ball.radus,erosion_kg_per_kg\n30,20,1e-4,1e-5\n", ("ball.radus",)),
    (
        "angle_deg,speed_m_s,ball.radius,erosion_kg_per_kg\n30,20,1e-4,1e-5\n45,20,-1,1e-5\n",
        ("ball.radius=-1", "row 2"),
    ),
    ("\ufeffangle_deg,speed_m_s\n30,20\n", ("erosion_kg_per_kg",)),
    ("\ufeffangle_deg,speed_m_s,angle_deg,erosion_kg_per_kg\n30,20,30,1e-5\n", ("'angle_deg'", "2 times")),
    ("angle_deg;speed_m_s;erosion_kg_per_kg\n30;20;1e-5\n", ("angle_deg",)),
]:
    row("calibrate {data}", "data.csv", *named, data=text)
for argv, *named in [
    ("calibrate", ("DATA.csv",)),
    ("calibrate {missing}", ("missing.toml",)),
    ("calibrate {userdir}", ("userdir",)),
    ("calibrate {data} --law archard", ("--law", "'archard'")),
    ("calibrate {data} --free K,K", ("--free", "K,K")),
    ("calibrate {data} --free 'K alpha'", ("--free", "'K alpha'")),
    ("calibrate {data} --free bogus", ("--free", "bogus")),
    ("calibrate {data} --law oka --free K", ("--free", "'K'")),
    ("calibrate {data} --set calibration.free=zzz", ("zzz",)),
    ("calibrate {data} --law deformation --free alpha", ("wear.deformation_factor",)),
]:
    row(argv, *named)

# ---- sweep: its options and files
for argv, *named in [
    ("{sweep} --workers 0", ("--workers", "0")),
    ("{sweep} --workers abc", ("--workers", "'abc'")),
    ("{sweep} --dask-local 0", ("--dask-local", "0")),
    ("{sweep} --workers 2 --dask-local 2", ("--dask-local",)),
    ("{userdir}", ("userdir",)),
    ("{binary}", ("binary.bin",)),
]:
    row(f"sweep {argv}", *named)
row("sweep {sweep}", "impact.speed", sweep='[sweep]\nstage = "impact"\n[grid]\n"impact.speed" = [1, 1e9]\n')
row("sweep {sweep}", "impact.angle", sweep='[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = ["a"]\n')
row("sweep {sweep}", "impact.angle", sweep='[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [nan]\n')
row("sweep {sweep}", "sweep.stage", sweep='[sweep]\nstage = 3\n[grid]\n"impact.angle" = [10]\n')
row("sweep {sweep}", "impact.spede", sweep='[sweep]\nstage = "impact"\n[[cases]]\nimpact.spede = 3\n')
row("sweep {sweep}", "angle", sweep='[sweep]\nstage = "impact"\n[grid]\nangle = [10]\n')
row(
    "sweep {sweep}",
    "grid.impact.angle is given twice",
    sweep='[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [1]\n"impact.angle" = [2]\n',
)
row("sweep {sweep}", "impact.angle", sweep='[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [[10, 20]]\n')
row("sweep {sweep}", "plat", sweep='[sweep]\nstage = "impact"\n[base]\nplat.E = 1e9\n[grid]\n"impact.angle" = [10]\n')
row("sweep {sweep}", "fem", sweep='[sweep]\nstage = "impact"\n[[cases]]\nfem.load_steps = 10\n')

# ---- runaway sizes: refused up front with the largest value that fits
grid = ", ".join(str(10 + k * 1e-4) for k in range(2000))
row("sweep {sweep}", "grid", sweep=f'[sweep]\nstage = "run"\n[grid]\n"impact.angle" = [{grid}]\n"wear.K" = [{grid}]\n')
row("erode --set erosion.samples=100000 --set erosion.grid=2048 --set erosion.frames=50", "erosion.grid=2048", "<=")
row("repeat --impacts 1e9 --set fem.mesh_scale=0.25", "fem.mesh_scale=0.25", ">=")
row("run --set fem.unload_steps=2000", "fem.unload_steps=2000", "<=")
row(
    "run --set fem.model='3d' --set fem.solid_load_steps=200 --set fem.solid_iterations=20",
    "fem.solid_load_steps=200",
    "<=",
)
row("run --set fem.model='3d' --set fem.mesh_scale=0.5", "fem.mesh_scale=0.5", ">=")

# ---- reproduce and validate
for argv, *named in [
    ("reproduce --only ''", ("--only=''",)),
    ("reproduce --only fig09_wear_mass_vs_angle --only bogus", ("--only='bogus'",)),
    ("reproduce --quick extra", ("extra",)),
    ("reproduce --out {file}", ("--out", "notes.txt")),
    ("reproduce --out {file}/sub", ("--out", "notes.txt")),
    ("validate --only nonexistent", ("--only", "nonexistent")),
    ("validate --report {userdir}", ("--report", "userdir")),
    ("validate --report {file}/validation.md", ("--report", "notes.txt")),
    ("validate --out {file}", ("--out", "notes.txt")),
    ("validate --bogus", ("--bogus",)),
    ("reproduce --only fig9", ("--only='fig9'",)),
    ("reproduce --only fig04_peak_force_vs_angle,fig06_spin", ("--only='fig04_peak_force_vs_angle,fig06_spin'",)),
    ("reproduce --out ''", ("--out", "''")),
    ("validate --out ''", ("--out", "''")),
    ("validate --report ''", ("--report", "''")),
    ("validate --only ''", ("--only=''",)),
    ("validate --only wear --only zzz", ("--only='zzz'",)),
    ("run --out ''", ("--out", "''")),
    ("sweep {sweep} --out ''", ("--out", "''")),
]:
    row(argv, *named)

# ---- bad --out of each command that writes one: a file, under a file, a folder of user files, another command's
for command in ("run", "indent", "repeat", "erode", "calibrate {data}", "sweep {sweep}"):
    other = "{ran}" if command.startswith("calibrate") else "{calibrated}"
    for out, named in [("{file}", "notes.txt"), ("{file}/sub", "notes.txt"), ("{userdir}", "userdir"), (other, "")]:
        row(f"{command} --out {out}", "--out", named or other.strip("{}"))


def _layout(tmp_path: Path, files: dict[str, str | bytes]) -> dict[str, str]:
    """Write the row's files and the fixed ones; the placeholders' paths."""

    def write(path: Path, content: str | bytes) -> Path:
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")
        return path

    paths = {
        "case": write(tmp_path / "case.toml", files.get("case", "")),
        "data": write(tmp_path / "data.csv", files.get("data", DATA)),
        "sweep": write(tmp_path / "sweep.toml", files.get("sweep", SWEEP)),
        "file": write(tmp_path / "notes.txt", "the user's notes\n"),
        "userdir": write(tmp_path / "userdir" / "thesis.tex", "chapter 1\n").parent,
        "binary": write(tmp_path / "binary.bin", bytes(range(256)) * 8),
        "missing": tmp_path / "missing.toml",
    }
    for name, command, entry in [("calibrated", "calibrate", "calibration.json"), ("ran", "run", "summary.json")]:
        folder = tmp_path / name
        write(folder / entry, "{}\n")
        write(folder / MANIFEST, json.dumps({"command": command, "entries": [entry], "complete": True}))
        paths[name] = folder
    return {k: str(v) for k, v in paths.items()}


def _argv(text: str, paths: dict[str, str]) -> list[str]:
    argv = shlex.split(text)
    for name, path in paths.items():
        argv = [a.replace(f"{{{name}}}", path) for a in argv]
    return argv


@pytest.mark.parametrize(("argv", "named", "files"), ROWS)
def test_bad_input_is_refused_cleanly(argv, named, files, tmp_path, capsys, monkeypatch, tripwire):
    monkeypatch.chdir(tmp_path)  # a default output folder would land here: the snapshot catches it
    paths = _layout(tmp_path, files)
    command = argv.split()[0]
    line = refused(_argv(argv, paths), tmp_path, capsys, out=command not in ("impact",))
    assert line.startswith(f"impactwear {command}: error: "), line
    for text in named:
        assert text in line, f"{text!r} not in {line!r}"


def test_the_table_covers_every_command_and_enough_inputs():
    commands = {r.values[0].split()[0] for r in ROWS}
    assert commands == set(WORK) and len(ROWS) >= 200


# ---- the end-to-end path: the installed entry point in a fresh process


@pytest.mark.parametrize(
    "argv, named",
    [
        (["run", "--set", "impact.angle=90"], "impact.angle=90"),
        (["calibrate", "{data}", "--law", "archard"], "--law"),
        (["indent", "--out", "{file}"], "--out"),
    ],
)
def test_bad_input_is_refused_cleanly_in_a_fresh_process(argv, named, tmp_path):
    paths = _layout(tmp_path, {})
    argv = _argv(shlex.join(argv), paths)
    if "--out" not in argv:
        argv += ["--out", str(tmp_path / "out")]
    before = snapshot(tmp_path)
    start = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, "-m", "wear.app.cli", *argv], capture_output=True, text=True, cwd=tmp_path, timeout=120
    )
    assert time.perf_counter() - start < 60.0
    lines = proc.stderr.strip().splitlines()
    assert proc.returncode == 2 and len(lines) == 1, proc.stderr
    assert named in lines[0] and "Traceback" not in proc.stderr
    assert proc.stdout == "" and snapshot(tmp_path) == before
