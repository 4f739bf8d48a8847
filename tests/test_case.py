"""Case files (wear/app/case.py): schema checks with one-line errors naming the key, TOML round trip."""

import math

import pytest

from wear.app import case as cases


def test_default_case_is_complete_and_valid():
    c = cases.default_case()
    assert cases.check_case(c) == c
    assert c["impact"]["angle"] == 30.0 and c["ball"]["radius"] == 2.5e-3
    assert c["impact"]["time_step"] is None


def test_round_trip(tmp_path):
    c = cases.default_case()
    c["impact"]["speed"] = 7.5
    c["plate"]["yield_strength"] = 250e6
    c["plate"]["E"] = math.inf
    path = tmp_path / "case.toml"
    cases.write_case(path, c)
    assert cases.load_case(path) == c
    assert [p.name for p in tmp_path.iterdir()] == ["case.toml"]  # no temporary file left behind


def test_partial_file_fills_defaults():
    c = cases.parse_case("[impact]\nangle = 45\nnormal_model = 'thornton'\n")
    assert c["impact"]["angle"] == 45.0 and c["impact"]["speed"] == 3.9
    assert c["impact"]["normal_model"] == "thornton"


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
        cases.parse_case(text)
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_register_table_and_render():
    keys = {"k_w": cases.Key(float, 1e-12, "wear coefficient", "m/(s Pa)", low=0.0, low_open=True)}
    cases.register_table("testtable", keys)
    try:
        cases.register_table("testtable", keys)  # idempotent
        c = cases.parse_case("[testtable]\nk_w = 2e-12\n")
        assert c["testtable"]["k_w"] == 2e-12
        with pytest.raises(ValueError, match="testtable.k_w=-1 is out of range"):
            cases.parse_case("[testtable]\nk_w = -1\n")
        assert "| `testtable.k_w` | 1e-12 |" in cases.render_defaults()
    finally:
        del cases.SCHEMA["testtable"]
    text = cases.render_defaults(["impact"])
    assert "| `impact.angle` | 30.0 | [0, 90) | deg |" in text


def test_impact_arguments_builds_materials():
    c = cases.default_case()
    c["plate"]["rigid"] = True
    kw = cases.impact_arguments(c)
    assert kw["plate"].is_rigid and kw["ball"].E == 380e9 and kw["speed"] == 3.9
