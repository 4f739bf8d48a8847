"""The case schema (wear/case): every key checked with one-line errors naming it, TOML round trips, each job's
default case the same whichever way it arrives."""

import math
from dataclasses import dataclass
from typing import ClassVar

import pytest

from wear.app.outputs.writer import write_text
from wear.case import (
    JOBS,
    Case,
    Table,
    apply_override,
    default_case,
    dump_case,
    key,
    key_reference,
    load_case,
    parse_case,
)


def test_default_case_is_complete_and_valid():
    c = default_case("impact")
    assert Case.from_dict(c.to_dict()) == c
    assert c.impact.angle == 30.0 and c.ball.radius == 2.5e-3
    assert c.impact.time_step is None


def test_round_trip(tmp_path):
    c = default_case("impact").with_(impact={"speed": 7.5}, plate={"yield_strength": 250e6, "E": math.inf})
    path = tmp_path / "case.toml"
    write_text(path, dump_case(c))
    assert load_case(path, "impact") == c
    assert [p.name for p in tmp_path.iterdir()] == ["case.toml"]  # no temporary file left behind


def test_partial_file_fills_defaults():
    c = parse_case("[impact]\nangle = 45\nnormal_model = 'thornton'\n", "impact")
    assert c.impact.angle == 45.0 and c.impact.speed == 3.9
    assert c.impact.normal_model == "thornton"


@pytest.mark.parametrize(
    "text, message",
    [
        (
            "[impact]\nangle = 120\n",
            "impact.angle=120 is out of range: impact angle from the plate normal must be in [0, 90) deg",
        ),
        ("[impact]\nspeeed = 3\n", "impact.speeed is not a known key"),
        ("[wearr]\nx = 1\n", "[wearr] is not a known case table"),
        ("[ball]\nE = 210\n", "ball.E=210 is out of range"),
        ("[ball]\nnu = 0.5\n", "ball.nu=0.5 is out of range"),
        ("[impact]\nspeed = 'fast'\n", "impact.speed='fast' is not a number"),
        ("[impact]\nnormal_model = 'jkr'\n", "impact.normal_model='jkr' is not a valid choice"),
        ("[plate]\nrigid = 1\n", "plate.rigid=1 is not a boolean"),
        ("[impact]\nfriction = nan\n", "impact.friction=nan is not finite"),
        ("impact = 3\n", "impact=3 is not a table"),
        ("[impact\n", "is not valid TOML"),
    ],
)
def test_errors_name_the_key(text, message):
    with pytest.raises(ValueError) as info:
        parse_case(text, "impact")
    assert message in str(info.value)
    assert "\n" not in str(info.value)


@dataclass(frozen=True)
class _Extra(Table):
    table: ClassVar[str] = "testtable"
    k_w: float = key(float, 1e-12, "wear coefficient", "m/(s Pa)", low=0.0, low_open=True)


def test_a_table_checks_its_keys_and_the_reference_lists_them():
    """A table is a frozen dataclass whose fields carry their keys: construction checks them with one-line errors;
    the docs' key reference is generated from the same keys (default, valid range, units)."""
    assert _Extra().k_w == 1e-12 and _Extra(k_w=2e-12).k_w == 2e-12
    assert _Extra(k_w=2).k_w == 2.0 and isinstance(_Extra(k_w=2).k_w, float)  # a TOML integer becomes a float
    with pytest.raises(ValueError, match=r"testtable.k_w=-1 is out of range: wear coefficient must be > 0 m/\(s Pa\)"):
        _Extra(k_w=-1.0)
    assert "| `impact.angle` | `30.0` | in [0, 90) deg | impact angle from the plate normal |" in key_reference()


def test_impact_arguments_builds_materials():
    c = default_case("impact").with_(plate={"rigid": True})
    kw = c.impact_arguments()
    assert kw["plate"].is_rigid and kw["ball"].E == 380e9 and kw["speed"] == 3.9


@pytest.mark.parametrize("job", sorted(JOBS))
def test_empty_tables_and_printed_default_are_the_default(job):
    """Empty tables = no file = --print-default fed back = the Python default, for every job."""
    default = default_case(job)
    assert parse_case("".join(f"[{t}]\n" for t in JOBS[job].tables), job) == default
    assert load_case(None, job) == default
    assert parse_case(dump_case(default, JOBS[job].tables), job) == default
    assert default_case() == Case() == Case.default()


def test_an_override_is_checked_and_names_the_key():
    c = apply_override(Case(), "impact.normal_model=hertz")  # a bare word is a string
    assert c.impact.normal_model == "hertz" and c.impact.speed == Case().impact.speed
    with pytest.raises(ValueError, match="wear.K=-1 is out of range"):
        apply_override(Case(), "wear.K=-1.0")
    with pytest.raises(ValueError, match=r"impact.spede is not a known key"):
        apply_override(Case(), "impact.spede=3")


def test_an_integer_key_takes_a_whole_number_written_as_a_float():
    """TOML reads ``1e3`` and ``5.0`` as floats: a whole number is the integer the user meant, a fraction is refused."""
    c = parse_case("[erosion]\nsamples = 1e3\n", "erode")
    assert c.erosion.samples == 1000 and isinstance(c.erosion.samples, int)
    assert apply_override(Case(), "repeat.impacts=5.0").repeat.impacts == 5
    with pytest.raises(ValueError, match=r"erosion.samples=2.5 is not an integer"):
        apply_override(Case(), "erosion.samples=2.5")
    with pytest.raises(ValueError, match=r"erosion.samples=1e\+06 is out of range"):
        apply_override(Case(), "erosion.samples=1e6")


def test_inf_yield_strength_means_never_yields():
    """A job whose default plate yields can still be given an elastic plate in TOML: yield_strength = inf."""
    c = parse_case("[plate]\nyield_strength = inf\n", "indent")
    assert c.plate.yield_strength is None and not c.plate.material().yield_strength
