"""The wall's Python API as a notebook user calls it: a wrong argument is a one-line ``ValueError`` naming the
argument and what to give, before any work (before: ZeroDivisionError, AttributeError, "min() arg is an empty
sequence", "Indices for islice() must be None or an integer", ...)."""

from __future__ import annotations

import pytest
from wall_cases import OUTPUTS, RECORDS

import wear.wall as W
from wear.case import default_case
from wear.wall.options import WallOptions


@pytest.fixture(scope="module")
def bend():
    return W.read_wall(OUTPUTS)


CASE = default_case("wall")

CALLS = {
    "workers=0": (
        lambda wall: W.erode_component(CASE, RECORDS, wall, WallOptions(workers=0)),
        "workers=0 is out of range",
    ),
    "workers=1.5": (
        lambda wall: W.erode_component(CASE, RECORDS, wall, WallOptions(workers=1.5)),
        "workers=1.5 is out of range",
    ),
    "a path for the wall": (
        lambda wall: W.erode_component(CASE, RECORDS, str(OUTPUTS)),
        "is a path: give the Wall it holds, wear.wall.read_wall(",
    ),
    "no case": (lambda wall: W.erode_component(None, RECORDS, wall), "case=None is not a wear.Case"),
    "a dict for the case": (lambda wall: W.erode_component({}, RECORDS, wall), "case=<dict> is not a wear.Case"),
    "an empty record list": (lambda wall: W.erode_component(CASE, [], wall), "records=[] is not a record file"),
    "no records": (lambda wall: W.erode_component(CASE, None, wall), "records=None is not a record file"),
    "a number for the records": (lambda wall: W.erode_component(CASE, 5, wall), "records=5 is not a record file"),
    "a number for the scheduler": (
        lambda wall: W.erode_component(CASE, RECORDS, wall, WallOptions(scheduler=5)),
        "scheduler=5 is not a Dask scheduler",
    ),
    "read_wall(5)": (lambda wall: W.read_wall(5), "path=5 is not a path"),
    "read_wall(None)": (lambda wall: W.read_wall(None), "path=None is not a path"),
    "read_surface(5)": (lambda wall: W.read_surface(5), "path=5 is not a path"),
    "read_fluent_dpm(5)": (lambda wall: W.read_fluent_dpm(5), "path=5 is not a path"),
    "read_table(start_row=-5)": (
        lambda wall: W.read_table(RECORDS / "0.02" / "bend.post.gz", start_row=-5),
        "start_row=-5 is out of range: give an integer >= 0",
    ),
    "read_patch_post_processing(max_rows=0)": (
        lambda wall: W.read_patch_post_processing(RECORDS / "0.02" / "bend.post.gz", wall, max_rows=0),
        "max_rows=0 is out of range: give an integer >= 1",
    ),
    "hits_on_wall(None, wall)": (lambda wall: W.hits_on_wall(None, wall), "records=None is not a wear.wall.Impact"),
    "wall_law(None)": (lambda wall: W.wall_law(None), "case=None is not a wear.Case"),
    "remaining_life(1.0, 1.0)": (lambda wall: W.remaining_life(1.0, 1.0), "wear=1 is not a wear.wall.WallWear"),
}


@pytest.mark.parametrize("name", list(CALLS))
def test_a_wrong_argument_is_one_line_naming_it(name, bend):
    call, says = CALLS[name]
    with pytest.raises(ValueError) as err:
        call(bend)
    message = str(err.value)
    assert "\n" not in message and says in message, message
